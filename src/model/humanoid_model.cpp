#include "graspsim/model/humanoid_model.h"

#include "graspsim/anthropometry/proportion_table.h"
#include "graspsim/anthropometry/joint_ranges.h"
#include "graspsim/anthropometry/segment_table.h"
#include "graspsim/model/arm_model.h"
#include "graspsim/model/joint_chain.h"
#include "graspsim/model/sagittal_mirror.h"
#include "graspsim/model/segment_body.h"

#include <cmath>
#include <functional>

namespace graspsim::model {

namespace {

struct HumanoidBuilder {
    HumanoidBuilder(ModelDescription& m, const BuildOptions& o) : model(m), options(o) {}

    ModelDescription& model;
    const BuildOptions& options;
    const anthropometry::SegmentTable table = anthropometry::SegmentTable::loadDeLeva(options.subject.sex);
    const anthropometry::JointRanges ranges = anthropometry::JointRanges::loadDefault();
    const anthropometry::ProportionTable proportions = anthropometry::ProportionTable::loadBody();

    double lengthOf(const std::string& segment) const {
        return calcSegmentLength(table.getSegment(segment), options.subject);
    }
    RevoluteSpec dof(const std::string& prefix, const std::string& name, const Vec3& axis) const {
        const anthropometry::JointRange& r = ranges.get(name);
        return {prefix + name, axis, r.lower, r.upper, 0.0, options.trunkDamping};
    }
    // Flexion bends the top forward (-z), lateral bending to the right (+x), rotation about +y.
    std::vector<RevoluteSpec> spineDofs(const std::string& joint) const {
        return {dof("", joint + "_flexion", {0, 0, -1}), dof("", joint + "_lateral", {1, 0, 0}),
                dof("", joint + "_rotation", {0, 1, 0})};
    }
    Body segmentBody(const std::string& segment, const std::string& name, SegmentOrigin origin) const {
        return makeSegmentBody(table.getSegment(segment), options.subject, name, origin);
    }

    void addSpineAndHead();
    void addRightLeg(const std::string& prefix, double hipHalfWidth);
    void addBothSides(const std::function<void(const std::string&)>& addRightSide);
};

void HumanoidBuilder::addSpineAndHead() {
    model.bodies.push_back(segmentBody("lower_trunk", "pelvis", SegmentOrigin::Distal));
    addRevoluteChain(model, "pelvis", Transform::translation({0, lengthOf("lower_trunk"), 0}), spineDofs("lumbar"),
                     segmentBody("middle_trunk", "middle_trunk", SegmentOrigin::Distal));
    addRevoluteChain(model, "middle_trunk", Transform::translation({0, lengthOf("middle_trunk"), 0}),
                     spineDofs("thoracic"), segmentBody("upper_trunk", "upper_trunk", SegmentOrigin::Distal));
    addRevoluteChain(model, "upper_trunk", Transform::translation({0, lengthOf("upper_trunk"), 0}), spineDofs("neck"),
                     segmentBody("head", "head", SegmentOrigin::Distal));
}

void HumanoidBuilder::addRightLeg(const std::string& prefix, double hipHalfWidth) {
    // Hip: flexion swings the thigh forward (+z), abduction laterally (-x), internal rotation +y.
    addRevoluteChain(model, "pelvis", Transform::translation({0, 0, hipHalfWidth}),
                     {dof(prefix, "hip_flexion", {0, 0, 1}), dof(prefix, "hip_abduction", {-1, 0, 0}),
                      dof(prefix, "hip_rotation", {0, 1, 0})},
                     segmentBody("thigh", prefix + "thigh", SegmentOrigin::Proximal));
    addRevoluteChain(model, prefix + "thigh", Transform::translation({0, -lengthOf("thigh"), 0}),
                     {dof(prefix, "knee_flexion", {0, 0, -1})},
                     segmentBody("shank", prefix + "shank", SegmentOrigin::Proximal));
    // The foot's long axis (its body -y) points forward: the ankle joint frame turns it 90 deg
    // about z. The foot frame sits at the ankle, a documented fraction of the foot behind the toe.
    Body foot = segmentBody("foot", prefix + "foot", SegmentOrigin::Proximal);
    const double heelToAnkle = proportions.get("ankle_from_heel_per_foot_length") * lengthOf("foot");
    foot.p_BCm[1] += heelToAnkle;
    for (Geometry& g : foot.geometry) g.X_BG.p[1] += heelToAnkle;
    addRevoluteChain(model, prefix + "shank", Transform::axisAngle({0, 0, 1}, M_PI / 2, {0, -lengthOf("shank"), 0}),
                     {dof(prefix, "ankle_flexion", {0, 0, 1}), dof(prefix, "ankle_inversion", {0, -1, 0})},
                     std::move(foot));
}

// Builds the right side with prefix "r_", then the same again with "l_", mirrored.
void HumanoidBuilder::addBothSides(const std::function<void(const std::string&)>& addRightSide) {
    addRightSide("r_");
    const std::size_t bodies = model.bodies.size(), joints = model.joints.size(), effectors = model.endEffectors.size();
    addRightSide("l_");
    mirrorSagittally(model, bodies, joints, effectors);
}

}  // namespace

ModelDescription buildHumanoidModel(const BuildOptions& options) {
    ModelDescription model;
    model.name = "graspsim_humanoid";
    HumanoidBuilder b(model, options);
    b.addSpineAndHead();
    const double H = options.subject.stature;
    const Transform X_TS = Transform::translation(
        {0, b.lengthOf("upper_trunk") - b.proportions.get("shoulder_below_suprasternale_per_stature") * H,
         b.proportions.get("shoulder_half_width_per_stature") * H});
    b.addBothSides([&](const std::string& prefix) {
        ArmSpec arm{options.subject, prefix, options.fingerStiffness, options.fingerDamping, options.armStiffness,
                    options.armDamping};
        addArm(model, "upper_trunk", X_TS, arm);
    });
    b.addBothSides([&](const std::string& prefix) {
        b.addRightLeg(prefix, b.proportions.get("hip_half_width_per_stature") * H);
    });
    return model;
}

}  // namespace graspsim::model
