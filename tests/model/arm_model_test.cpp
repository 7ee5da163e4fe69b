#include "graspsim/model/arm_model.h"

#include "graspsim/anthropometry/segment_table.h"
#include "graspsim/model/body_model.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace graspsim;
using namespace graspsim::model;

namespace {

struct SubjectCase {
    anthropometry::Sex sex;
    double mass;
    double stature;
};

class ArmForSubject : public ::testing::TestWithParam<SubjectCase> {
protected:
    BuildOptions options() const {
        BuildOptions o;
        o.subject = {GetParam().sex, GetParam().mass, GetParam().stature};
        return o;
    }
};

}  // namespace

// Oracle: de Leva (1996) fractions x the subject, computed here from the table directly.
TEST_P(ArmForSubject, SegmentsAreDeLevaFractionsOfTheSubject) {
    const ModelDescription arm = buildBodyModel(options());
    const anthropometry::SegmentTable table = anthropometry::SegmentTable::loadDeLeva(GetParam().sex);
    const double scale = GetParam().stature / anthropometry::getReferenceSubject(GetParam().sex).stature;
    for (const char* name : {"upper_arm", "forearm"}) {
        SCOPED_TRACE(name);
        const auto& seg = table.getSegment(name);
        const Body& body = *arm.findBody(name);
        const double L = seg.length * scale;
        const double m = seg.massFraction * GetParam().mass;
        EXPECT_NEAR(body.mass, m, 1e-12);
        EXPECT_NEAR(body.p_BCm[1], -seg.comFraction * L, 1e-12);
        EXPECT_NEAR(body.p_BCm[0], 0.0, 1e-15);
        EXPECT_NEAR(body.inertia.xx, m * std::pow(seg.gyrationSagittal * L, 2), 1e-12);
        EXPECT_NEAR(body.inertia.yy, m * std::pow(seg.gyrationLongitudinal * L, 2), 1e-12);
        EXPECT_NEAR(body.inertia.zz, m * std::pow(seg.gyrationTransverse * L, 2), 1e-12);
    }
    const double handMass = table.getSegment("hand").massFraction * GetParam().mass;
    double handParts = 0;
    for (const Body& b : arm.bodies) handParts += b.segment == "hand" ? b.mass : 0.0;
    EXPECT_NEAR(handParts, handMass, 1e-12);
}

TEST_P(ArmForSubject, HasTheDocumentedDegreesOfFreedom) {
    const ModelDescription arm = buildBodyModel(options());
    // shoulder 3 + elbow 1 + forearm 1 + wrist 2 + four fingers x 4 + thumb 4
    EXPECT_EQ(arm.getDofCount(), 3 + 1 + 1 + 2 + 4 * 4 + 4);
    EXPECT_EQ(arm.endEffectors.size(), 5u);
}

INSTANTIATE_TEST_SUITE_P(BothSexes, ArmForSubject,
                         ::testing::Values(SubjectCase{anthropometry::Sex::Male, 73.0, 1.741},
                                           SubjectCase{anthropometry::Sex::Female, 61.9, 1.735},
                                           SubjectCase{anthropometry::Sex::Male, 95.0, 1.90},
                                           SubjectCase{anthropometry::Sex::Female, 50.0, 1.55}));

TEST(ArmModel, FingerJointsCarryTheThesisPassiveParameters) {
    const ModelDescription arm = buildBodyModel(BuildOptions{});
    int fingerJoints = 0;
    for (const Joint& j : arm.joints) {
        const Body& child = *arm.findBody(j.child);
        const bool finger = child.segment == "hand" && j.name.find("wrist") == std::string::npos;
        if (!finger) continue;
        ++fingerJoints;
        EXPECT_DOUBLE_EQ(j.stiffness, 0.25) << j.name;
        EXPECT_DOUBLE_EQ(j.damping, 0.05) << j.name;
        EXPECT_LT(j.lower, j.upper) << j.name;
    }
    EXPECT_EQ(fingerJoints, 20);
}

TEST(ArmModel, PassiveParametersAreOverridable) {
    BuildOptions o;
    o.fingerStiffness = 0.4;
    o.fingerDamping = 0.01;
    const ModelDescription arm = buildBodyModel(o);
    EXPECT_DOUBLE_EQ(arm.findJoint("index_pip_flexion")->stiffness, 0.4);
    EXPECT_DOUBLE_EQ(arm.findJoint("thumb_ip_flexion")->damping, 0.01);
}

TEST(ArmModel, JointRangesComeFromTheTable) {
    const ModelDescription arm = buildBodyModel(BuildOptions{});
    const Joint& elbow = *arm.findJoint("elbow_flexion");
    EXPECT_NEAR(elbow.lower, 0.0, 1e-12);
    EXPECT_NEAR(elbow.upper, 150.0 * M_PI / 180.0, 1e-12);
}
