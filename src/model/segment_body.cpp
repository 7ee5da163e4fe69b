#include "graspsim/model/segment_body.h"

#include <cmath>

namespace graspsim::model {

double calcSegmentLength(const anthropometry::SegmentParameters& segment, const anthropometry::Subject& subject) {
    const anthropometry::Subject reference = anthropometry::getReferenceSubject(subject.sex);
    return segment.length * subject.stature / reference.stature;
}

Body makeSegmentBody(const anthropometry::SegmentParameters& segment, const anthropometry::Subject& subject,
                     const std::string& name, SegmentOrigin origin) {
    const double L = calcSegmentLength(segment, subject);
    Body body;
    body.name = name;
    body.segment = segment.name;
    body.mass = segment.massFraction * subject.mass;
    // comFraction is measured from the first endpoint, which is the top of the segment.
    const double yCm = origin == SegmentOrigin::Proximal ? -segment.comFraction * L : (1 - segment.comFraction) * L;
    body.p_BCm = {0, yCm, 0};
    const auto moment = [&](double r) { return body.mass * (r * L) * (r * L); };
    body.inertia.xx = moment(segment.gyrationSagittal);
    body.inertia.yy = moment(segment.gyrationLongitudinal);
    body.inertia.zz = moment(segment.gyrationTransverse);

    // The collision capsule spans the segment's length exactly (caps included), along its long axis.
    Geometry capsule;
    capsule.type = Geometry::Type::Capsule;
    capsule.name = name + "_capsule";
    capsule.radius = std::min(std::sqrt(2.0) * segment.gyrationLongitudinal * L, 0.45 * L);
    capsule.length = L - 2 * capsule.radius;
    const double yMid = origin == SegmentOrigin::Proximal ? -L / 2 : L / 2;
    // Rotating -90 deg about x takes the capsule's z axis onto the segment's y axis.
    capsule.X_BG = Transform::axisAngle({1, 0, 0}, -M_PI / 2, {0, yMid, 0});
    body.geometry.push_back(capsule);
    return body;
}

}  // namespace graspsim::model
