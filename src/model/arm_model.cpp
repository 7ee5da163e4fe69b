#include "graspsim/model/arm_model.h"

#include "graspsim/anthropometry/joint_ranges.h"
#include "graspsim/anthropometry/segment_table.h"
#include "graspsim/model/hand_model.h"
#include "graspsim/model/joint_chain.h"
#include "graspsim/model/segment_body.h"

#include <cmath>

namespace graspsim::model {

namespace {

RevoluteSpec armDof(const ArmSpec& spec, const anthropometry::JointRanges& ranges, const std::string& name,
                    const Vec3& axis) {
    const anthropometry::JointRange& r = ranges.get(name);
    return {spec.prefix + name, axis, r.lower, r.upper, spec.armStiffness, spec.armDamping};
}

}  // namespace

void addArm(ModelDescription& model, const std::string& parent, const Transform& X_PS, const ArmSpec& spec) {
    const anthropometry::SegmentTable table = anthropometry::SegmentTable::loadDeLeva(spec.subject.sex);
    const anthropometry::JointRanges ranges = anthropometry::JointRanges::loadDefault();
    const auto& upperArm = table.getSegment("upper_arm");
    const auto& forearm = table.getSegment("forearm");
    const double upperArmLength = calcSegmentLength(upperArm, spec.subject);
    const double forearmLength = calcSegmentLength(forearm, spec.subject);

    addRevoluteChain(model, parent, X_PS,
                     {armDof(spec, ranges, "shoulder_flexion", {0, 0, 1}),
                      armDof(spec, ranges, "shoulder_abduction", {-1, 0, 0}),
                      armDof(spec, ranges, "shoulder_rotation", {0, 1, 0})},
                     makeSegmentBody(upperArm, spec.subject, spec.prefix + "upper_arm", SegmentOrigin::Proximal));

    // Elbow flexion is about the upper arm's z. The forearm's own frame is anatomical (palm
    // forward) at -90 deg of pronation; the pronation joint frame turns it by +90 deg about the
    // long axis so that q = 0 is the neutral forearm with the thumb forward.
    Body elbow;
    elbow.name = spec.prefix + "forearm__elbow_flexion";
    elbow.segment = "forearm";
    addRevoluteChain(model, spec.prefix + "upper_arm", Transform::translation({0, -upperArmLength, 0}),
                     {armDof(spec, ranges, "elbow_flexion", {0, 0, 1})}, elbow);
    addRevoluteChain(model, elbow.name, Transform::axisAngle({0, 1, 0}, M_PI / 2),
                     {armDof(spec, ranges, "forearm_pronation", {0, 1, 0})},
                     makeSegmentBody(forearm, spec.subject, spec.prefix + "forearm", SegmentOrigin::Proximal));

    HandSpec hand{spec.subject, spec.prefix, spec.fingerStiffness, spec.fingerDamping, spec.armStiffness,
                  spec.armDamping};
    addHand(model, spec.prefix + "forearm", Transform::translation({0, -forearmLength, 0}), hand);
}

ModelDescription buildArmModel(const BuildOptions& options) {
    ModelDescription model;
    model.name = "graspsim_right_arm";
    Body anchor;
    anchor.name = "shoulder_anchor";
    model.bodies.push_back(anchor);
    ArmSpec spec{options.subject, "", options.fingerStiffness, options.fingerDamping, options.armStiffness,
                 options.armDamping};
    addArm(model, anchor.name, Transform::identity(), spec);
    return model;
}

}  // namespace graspsim::model
