#include "graspsim/scenario/scenario.h"

#include "graspsim/anthropometry/subject.h"
#include "graspsim/model/object_model.h"

#include <algorithm>
#include <cmath>

namespace graspsim::scenario {

std::string toString(ObjectShape shape) { return shape == ObjectShape::Sphere ? "sphere" : "box"; }

model::Transform ObjectSpec::findPose() const {
    // Body-fixed X-Y-Z: rotate about x, then about the new y, then about the newest z, so the
    // rotations compose left to right.
    model::Transform X_GO = model::Transform::axisAngle({1, 0, 0}, orientation[0]) *
                            model::Transform::axisAngle({0, 1, 0}, orientation[1]) *
                            model::Transform::axisAngle({0, 0, 1}, orientation[2]);
    X_GO.p = position;
    return X_GO;
}

double ObjectSpec::calcSurfaceDistance(const Vec3& p_OP) const {
    if (shape == ObjectShape::Sphere) return std::hypot(p_OP[0], p_OP[1], p_OP[2]) - radius;
    // Box: outside, the Euclidean distance to the nearest surface point; inside, minus the
    // distance to the nearest face.
    double outside = 0, inside = -INFINITY;
    for (int i = 0; i < 3; ++i) {
        const double d = std::abs(p_OP[i]) - size[i] / 2;
        outside += d > 0 ? d * d : 0;
        inside = std::max(inside, d);
    }
    return inside > 0 ? std::sqrt(outside) : inside;
}

Vec3 ObjectSpec::findOutwardNormal(const Vec3& p_OP) const {
    if (shape == ObjectShape::Sphere) {
        const double r = std::hypot(p_OP[0], p_OP[1], p_OP[2]);
        return {p_OP[0] / r, p_OP[1] / r, p_OP[2] / r};
    }
    // The face whose plane is nearest, the same choice calcSurfaceDistance makes inside the box.
    int face = 0;
    for (int i = 1; i < 3; ++i) {
        if (std::abs(p_OP[i]) - size[i] / 2 > std::abs(p_OP[face]) - size[face] / 2) face = i;
    }
    Vec3 n{0, 0, 0};
    n[face] = p_OP[face] >= 0 ? 1 : -1;
    return n;
}

model::ModelDescription buildObjectModel(const ObjectSpec& object) {
    if (object.shape == ObjectShape::Sphere) return model::buildBallModel(object.mass, object.radius);
    return model::buildPhoneModel(object.mass, object.size);
}

const Perturbation* Scenario::findPerturbation(const std::string& perturbationName) const {
    for (const Perturbation& perturbation : perturbations) {
        if (perturbation.name == perturbationName) return &perturbation;
    }
    return nullptr;
}

model::BuildOptions Scenario::makeDefaultBodyOptions() {
    model::BuildOptions options;
    options.body = model::BodyKind::Arm;
    options.preset = model::Preset::Thesis;
    options.subject = anthropometry::getReferenceSubject(anthropometry::Sex::Male);
    return options;
}

}  // namespace graspsim::scenario
