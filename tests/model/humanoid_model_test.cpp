#include "graspsim/model/humanoid_model.h"

#include "graspsim/anthropometry/segment_table.h"
#include "graspsim/model/body_model.h"

#include <gtest/gtest.h>

using namespace graspsim;
using namespace graspsim::model;

namespace {

BuildOptions humanoidOptions(anthropometry::Sex sex) {
    BuildOptions o;
    o.subject = anthropometry::getReferenceSubject(sex);
    o.body = BodyKind::Humanoid;
    return o;
}

}  // namespace

TEST(HumanoidModel, HasTheDocumentedDegreesOfFreedom) {
    const ModelDescription h = buildBodyModel(humanoidOptions(anthropometry::Sex::Male));
    // lumbar 3 + thoracic 3 + neck 3 + two arms x 27 + two legs x (hip 3 + knee 1 + ankle 2)
    EXPECT_EQ(h.getDofCount(), 9 + 2 * 27 + 2 * 6);
    EXPECT_EQ(h.endEffectors.size(), 10u);
}

// Oracle: the whole body's mass is the subject's mass times the sum of de Leva's fractions.
TEST(HumanoidModel, TotalMassIsTheSubjectsMass) {
    for (const auto sex : {anthropometry::Sex::Male, anthropometry::Sex::Female}) {
        const BuildOptions o = humanoidOptions(sex);
        const ModelDescription h = buildBodyModel(o);
        const double fractions = anthropometry::SegmentTable::loadDeLeva(sex).calcWholeBodyMassFractionSum();
        EXPECT_NEAR(h.calcTotalMass(), fractions * o.subject.mass, 1e-9);
        EXPECT_NEAR(h.calcTotalMass(), o.subject.mass, 2e-4 * o.subject.mass);
    }
}

TEST(HumanoidModel, SidesAreMirrorImages) {
    const ModelDescription h = buildBodyModel(humanoidOptions(anthropometry::Sex::Female));
    for (const Body& right : h.bodies) {
        if (right.name.rfind("r_", 0) != 0) continue;
        std::string leftName = "l_" + right.name.substr(2);
        const std::size_t chain = leftName.find("__r_");  // virtual links of joint chains
        if (chain != std::string::npos) leftName.replace(chain, 4, "__l_");
        const Body* left = h.findBody(leftName);
        ASSERT_NE(left, nullptr) << right.name;
        EXPECT_DOUBLE_EQ(left->mass, right.mass) << right.name;
        EXPECT_DOUBLE_EQ(left->p_BCm[2], -right.p_BCm[2]) << right.name;
        EXPECT_DOUBLE_EQ(left->inertia.xz, -right.inertia.xz) << right.name;
    }
    const Joint& r = *h.findJoint("r_shoulder_flexion");
    const Joint& l = *h.findJoint("l_shoulder_flexion");
    EXPECT_DOUBLE_EQ(l.X_PJ.p[2], -r.X_PJ.p[2]);
    EXPECT_GT(r.X_PJ.p[2], 0.0);  // right shoulder on the subject's right (+z)
}
