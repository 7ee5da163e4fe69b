#include "graspsim/model/sagittal_mirror.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim::model;

namespace {

// A one-joint limb: an oblique revolute joint, a body with a full inertia and an end-effector.
ModelDescription limb() {
    ModelDescription m;
    Body root;
    root.name = "root";
    Body link;
    link.name = "link";
    link.mass = 1;
    link.p_BCm = {0.1, -0.2, 0.05};
    link.inertia = {0.3, 0.2, 0.25, 0.01, 0.02, 0.03};
    m.bodies = {root, link};
    Joint j;
    j.name = "hinge";
    j.parent = "root";
    j.child = "link";
    const double n = std::sqrt(1.0 + 4.0 + 9.0);
    j.axis = {1 / n, 2 / n, 3 / n};
    j.X_PJ = Transform::axisAngle({0.3, 0.5, 0.8}, 0.7, {0.1, 0.2, 0.3});
    m.joints = {j};
    m.endEffectors = {{"tip", "link", {0.02, -0.3, 0.04}}};
    return m;
}

// Location in the parent of an end-effector after turning the joint by q.
Vec3 locate(const ModelDescription& m, double q) {
    const Joint& j = m.joints[0];
    return (j.X_PJ * Transform::axisAngle(j.axis, q)).shiftFrameStationToBase(m.endEffectors[0].p_BE);
}

}  // namespace

// Oracle: a reflection. The mirrored limb at angle q must sit exactly where the reflection
// (z -> -z) of the original limb at the same q sits.
TEST(SagittalMirror, EqualAnglesGiveMirrorImagePoses) {
    const ModelDescription right = limb();
    ModelDescription left = limb();
    mirrorSagittally(left, 0, 0, 0);
    for (double q : {-1.0, 0.0, 0.4, 2.0}) {
        const Vec3 r = locate(right, q);
        const Vec3 l = locate(left, q);
        EXPECT_NEAR(l[0], r[0], 1e-14);
        EXPECT_NEAR(l[1], r[1], 1e-14);
        EXPECT_NEAR(l[2], -r[2], 1e-14);
    }
}

TEST(SagittalMirror, MirroringTwiceIsTheIdentity) {
    const ModelDescription original = limb();
    ModelDescription twice = limb();
    mirrorSagittally(twice, 0, 0, 0);
    mirrorSagittally(twice, 0, 0, 0);
    for (int k = 0; k < 9; ++k) EXPECT_DOUBLE_EQ(twice.joints[0].X_PJ.R[k], original.joints[0].X_PJ.R[k]);
    EXPECT_DOUBLE_EQ(twice.bodies[1].inertia.yz, original.bodies[1].inertia.yz);
}
