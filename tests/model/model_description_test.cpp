#include "graspsim/model/model_description.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim::model;

namespace {

ModelDescription twoLinks() {
    ModelDescription m;
    m.name = "two";
    Body base;
    base.name = "base";
    base.mass = 1;
    base.inertia = {0.1, 0.1, 0.1};
    Body arm = base;
    arm.name = "arm";
    m.bodies = {base, arm};
    Joint j;
    j.name = "hinge";
    j.parent = "base";
    j.child = "arm";
    j.lower = -1;
    j.upper = 1;
    m.joints = {j};
    return m;
}

std::string messageOf(const ModelDescription& m) {
    try {
        m.validate("test.urdf");
    } catch (const graspsim::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(Transform, ComposedRotationsAddAngles) {
    const Transform a = Transform::axisAngle({0, 0, 1}, 0.3, {1, 0, 0});
    const Transform b = Transform::axisAngle({0, 0, 1}, 0.4, {0, 2, 0});
    const Transform ab = a * b;
    const Transform expected = Transform::axisAngle({0, 0, 1}, 0.7);
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(ab.R[k], expected.R[k], 1e-15);
    // b's origin (0, 2, 0) seen from a: rotated by 0.3 rad and shifted by (1, 0, 0).
    EXPECT_NEAR(ab.p[0], 1 - 2 * std::sin(0.3), 1e-15);
    EXPECT_NEAR(ab.p[1], 2 * std::cos(0.3), 1e-15);
}

TEST(ModelDescription, ValidTreePasses) {
    const ModelDescription m = twoLinks();
    EXPECT_NO_THROW(m.validate("test.urdf"));
    EXPECT_EQ(m.getDofCount(), 1);
    EXPECT_DOUBLE_EQ(m.calcTotalMass(), 2.0);
}

TEST(ModelDescription, MissingLinkIsNamed) {
    ModelDescription m = twoLinks();
    m.joints[0].child = "ghost";
    const std::string msg = messageOf(m);
    EXPECT_NE(msg.find("test.urdf"), std::string::npos);
    EXPECT_NE(msg.find("ghost"), std::string::npos);
}

TEST(ModelDescription, TwoParentsAreRejected) {
    ModelDescription m = twoLinks();
    Joint second = m.joints[0];
    second.name = "hinge2";
    m.joints.push_back(second);
    EXPECT_NE(messageOf(m).find("at most one parent"), std::string::npos);
}

TEST(ModelDescription, CycleIsRejected) {
    ModelDescription m = twoLinks();
    Body third = m.bodies[1];
    third.name = "third";
    m.bodies.push_back(third);
    Joint back = m.joints[0];
    back.name = "back";
    back.parent = "third";
    back.child = "arm";
    m.joints[0].child = "third";
    m.joints[0].parent = "arm";
    m.joints.push_back(back);
    EXPECT_NE(messageOf(m).find("cycle"), std::string::npos);
}

TEST(ModelDescription, NonPositiveDefiniteInertiaIsRejected) {
    ModelDescription m = twoLinks();
    m.bodies[1].inertia = {-0.1, 0.1, 0.1};
    EXPECT_NE(messageOf(m).find("positive definite"), std::string::npos);
    m.bodies[1].inertia = {1, 1, 3};
    EXPECT_NE(messageOf(m).find("triangle"), std::string::npos);
    // Diagonal (1, 2, 2) looks fine, but with I_yz = 1 the principal moments are (1, 1, 3).
    m.bodies[1].inertia = {1, 2, 2, 0, 0, 1};
    EXPECT_NE(messageOf(m).find("triangle"), std::string::npos);
}

TEST(ModelDescription, NegativeMassAndReversedLimitsAreRejected) {
    ModelDescription m = twoLinks();
    m.bodies[1].mass = -1;
    EXPECT_NE(messageOf(m).find("mass"), std::string::npos);
    m = twoLinks();
    m.joints[0].lower = 2;
    EXPECT_NE(messageOf(m).find("limits"), std::string::npos);
}

// A movable joint with no mass beyond it would leave Simbody's accelerations NaN: refused naming
// the source (the URDF file) and the joint. Mass further out, or a weld, is fine.
TEST(ModelDescription, AMovableJointThatMovesOnlyMasslessLinksIsRejected) {
    ModelDescription m = twoLinks();
    m.bodies[1].mass = 0;
    m.bodies[1].inertia = {0, 0, 0};
    EXPECT_EQ(messageOf(m), "test.urdf: joint 'hinge' outboard mass = 0 kg (it moves only massless links) is not accepted; "
                            "a movable joint needs a link with mass > 0 at or beyond its child");
    ModelDescription welded = m;
    welded.joints[0].type = Joint::Type::Fixed;
    EXPECT_EQ(messageOf(welded), "");
    Body hand = twoLinks().bodies[1];
    hand.name = "hand";
    Joint wrist = m.joints[0];
    wrist.name = "wrist";
    wrist.parent = "arm";
    wrist.child = "hand";
    m.bodies.push_back(hand);
    m.joints.push_back(wrist);
    EXPECT_EQ(messageOf(m), "") << "the massless arm carries the hand";
}

// Mass properties that pass the rigid-body checks (the triangle inequality within 1e-6 of the trace,
// which a plate written to six digits needs) but not Simbody's tighter ones are refused here, naming
// the source (the URDF file) rather than leaving it to MultibodyModel, which knows only the model's name.
TEST(ModelDescription, MassPropertiesSimbodyCannotHoldAreRejectedNamingTheSource) {
    ModelDescription plate = twoLinks();
    plate.bodies[1].mass = 100;
    plate.bodies[1].inertia = {50, 50, 100.00001};
    EXPECT_EQ(messageOf(plate),
              "test.urdf: link 'arm' inertia = [50 50 100.00001 0 0 0] kg m^2 is not accepted; Simbody accepts a central "
              "inertia whose moments are >= 0, each at most the sum of the other two and at least 2 |the product of the "
              "other two axes| (ixx >= 2 |iyz|), all within 1.49e-06 kg m^2; here izz exceeds ixx + iyy by 1e-05 kg m^2");
    ModelDescription far = twoLinks();
    far.bodies[1].mass = 2e11;
    far.bodies[1].p_BCm = {0, 0, 5};
    far.bodies[1].inertia = {1.62e-4, 1.62e-4, 1.62e-4};
    EXPECT_EQ(messageOf(far),
              "test.urdf: link 'arm' centre of mass = (0, 0, 5) m is not accepted; with mass 2e+11 kg, m |p|^2 = 5e+12 kg m^2 "
              "swamps the central inertia (trace 0.000486 kg m^2) when Simbody shifts it to the link origin; accepted: "
              "m |p|^2 below 4.19e+06 kg m^2 (put the link origin nearer the mass centre)");
    plate.bodies[1].inertia.zz = 100;  // a plate exactly flat
    EXPECT_EQ(messageOf(plate), "");
}

TEST(ModelDescription, DuplicateNamesAreRejected) {
    ModelDescription m = twoLinks();
    m.bodies[1].name = "base";
    EXPECT_NE(messageOf(m).find("unique"), std::string::npos);
}

TEST(ModelDescription, FindPalmTakesTheMassiveBodyWithThePalmRoleNotAName) {
    ModelDescription m = twoLinks();
    EXPECT_THROW(m.findPalm(), graspsim::InputError);
    m.bodies[1].role = BodyRole::Palm;  // "arm": found by its role
    Body wristChain;
    wristChain.name = "palm";  // the name alone does not make it the palm: massless, virtual
    wristChain.role = BodyRole::Palm;
    m.bodies.push_back(wristChain);
    ASSERT_TRUE(wristChain.isVirtual());
    EXPECT_EQ(m.findPalm().name, "arm");
    m.bodies[0].role = BodyRole::Palm;
    try {
        m.findPalm();
        FAIL() << "two palms must be refused";
    } catch (const graspsim::InputError& e) {
        EXPECT_NE(std::string(e.what()).find("two palms ('base', 'arm')"), std::string::npos) << e.what();
    }
}
