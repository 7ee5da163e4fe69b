#include "graspsim/model/hand_model.h"

#include "graspsim/anthropometry/finger_table.h"
#include "graspsim/model/body_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim;
using namespace graspsim::model;

namespace {

// Pose of a body in ground at q = 0, where every joint frame coincides with its child frame.
Transform findRestPose(const ModelDescription& m, const std::string& body) {
    const Joint* joint = m.findParentJoint(body);
    if (!joint) return m.X_GR;
    return findRestPose(m, joint->parent) * joint->X_PJ;
}

Vec3 findRestLocation(const ModelDescription& m, const std::string& endEffector) {
    const EndEffector& e = *m.findEndEffector(endEffector);
    return findRestPose(m, e.body).shiftFrameStationToBase(e.p_BE);
}

double along(const Vec3& a, const Vec3& b, const Vec3& axis) {
    return (b[0] - a[0]) * axis[0] + (b[1] - a[1]) * axis[1] + (b[2] - a[2]) * axis[2];
}

}  // namespace

// Oracle: in the rest pose (fingers extended) each fingertip lies, along the hand's long axis,
// (carpus + metacarpal + phalanges) x hand length from the wrist, with hand length = 0.108 x
// stature and the carpus chosen so that the middle finger spans exactly one hand length; the pad
// point sits one distal radius short of the tip.
TEST(HandModel, RestPoseFingertipsSpanTheAnthropometricHandLength) {
    for (const auto sex : {anthropometry::Sex::Male, anthropometry::Sex::Female}) {
        BuildOptions o;
        o.subject = anthropometry::getReferenceSubject(sex);
        const ModelDescription arm = buildBodyModel(o);
        const double HL = calcHandLength(o.subject);
        EXPECT_NEAR(HL, 0.108 * o.subject.stature, 1e-12);
        const Transform X_GH = findRestPose(arm, "palm");
        const Vec3 p_wrist = X_GH.p;
        const Vec3 handAxis = X_GH.xformFrameVecToBase({0, -1, 0});
        const auto table = anthropometry::FingerTable::loadBuchholz();
        const auto& middle = table.getDigit(anthropometry::Digit::Middle);
        const double carpus = 1 - middle.metacarpal - middle.proximal - middle.middle - middle.distal;
        const std::pair<const char*, anthropometry::Digit> fingers[] = {{"index", anthropometry::Digit::Index},
                                                                        {"middle", anthropometry::Digit::Middle},
                                                                        {"ring", anthropometry::Digit::Ring},
                                                                        {"little", anthropometry::Digit::Little}};
        for (const auto& [name, digit] : fingers) {
            const auto& d = table.getDigit(digit);
            const double rD = arm.findBody(std::string(name) + "_distal")->geometry[0].radius;
            const double expected = (carpus + d.metacarpal + d.proximal + d.middle + d.distal) * HL - rD;
            const Vec3 tip = findRestLocation(arm, std::string(name) + "_tip");
            EXPECT_NEAR(along(p_wrist, tip, handAxis), expected, 1e-12) << name;
        }
        const double rMiddle = arm.findBody("middle_distal")->geometry[0].radius;
        EXPECT_NEAR(along(p_wrist, findRestLocation(arm, "middle_tip"), handAxis), HL - rMiddle, 1e-12);
    }
}

TEST(HandModel, HandHangsBelowTheForearmWithThePalmFacingTheBody) {
    const ModelDescription arm = buildBodyModel(BuildOptions{});
    const Transform X_GH = findRestPose(arm, "palm");
    // Neutral forearm: palm normal (hand +x) points medially (-z), thumb side (+z) forward (+x).
    const Vec3 palmNormal = X_GH.xformFrameVecToBase({1, 0, 0});
    const Vec3 radial = X_GH.xformFrameVecToBase({0, 0, 1});
    EXPECT_NEAR(palmNormal[2], -1.0, 1e-12);
    EXPECT_NEAR(radial[0], 1.0, 1e-12);
    EXPECT_LT(X_GH.p[1], -0.5);  // wrist below the shoulder by upper arm + forearm
}

TEST(HandModel, EveryPhalanxHasACapsuleSpanningItsBone) {
    const ModelDescription arm = buildBodyModel(BuildOptions{});
    int capsules = 0;
    for (const Body& b : arm.bodies) {
        if (b.segment != "hand" || b.isVirtual() || b.name == "palm") continue;
        ASSERT_EQ(b.geometry.size(), 1u) << b.name;
        const Geometry& g = b.geometry[0];
        EXPECT_EQ(g.type, Geometry::Type::Capsule) << b.name;
        EXPECT_GT(g.length, 0.0) << b.name;
        ++capsules;
    }
    EXPECT_EQ(capsules, 15);
    EXPECT_EQ(arm.findBody("palm")->geometry.size(), 2u);  // two boxes
}
