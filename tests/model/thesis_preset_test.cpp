#include "graspsim/model/thesis_preset.h"

#include "graspsim/model/body_model.h"

#include <gtest/gtest.h>

using namespace graspsim::model;

namespace {

BuildOptions thesisOptions(BodyKind body) {
    BuildOptions o;
    o.preset = Preset::Thesis;
    o.body = body;
    return o;
}

}  // namespace

// Oracle: the thesis's section 5.1 numbers.
TEST(ThesisPreset, ReproducesTheThesisMasses) {
    const ModelDescription arm = buildBodyModel(thesisOptions(BodyKind::Arm));
    int fingerSegments = 0;
    for (const Body& b : arm.bodies) {
        if (b.segment != "hand" || b.isVirtual()) continue;
        if (b.name == "palm") {
            EXPECT_DOUBLE_EQ(b.mass, 0.250);
        } else {
            EXPECT_DOUBLE_EQ(b.mass, 0.020) << b.name;
            ++fingerSegments;
        }
    }
    EXPECT_EQ(fingerSegments, 15);
    EXPECT_NEAR(arm.calcTotalMass(), 5.45, 1e-12);
}

TEST(ThesisPreset, KeepsShapesAndScalesInertiaWithMass) {
    const ModelDescription plain = buildBodyModel(BuildOptions{});
    const ModelDescription thesis = buildBodyModel(thesisOptions(BodyKind::Arm));
    for (const char* name : {"index_distal", "palm", "upper_arm"}) {
        const Body& a = *plain.findBody(name);
        const Body& b = *thesis.findBody(name);
        const double ratio = b.mass / a.mass;
        EXPECT_NEAR(b.inertia.xx, a.inertia.xx * ratio, 1e-15) << name;
        EXPECT_NEAR(b.inertia.zz, a.inertia.zz * ratio, 1e-15) << name;
        EXPECT_DOUBLE_EQ(b.p_BCm[1], a.p_BCm[1]) << name;
    }
    // Upper arm and forearm keep their de Leva proportion.
    EXPECT_NEAR(thesis.findBody("upper_arm")->mass / thesis.findBody("forearm")->mass,
                plain.findBody("upper_arm")->mass / plain.findBody("forearm")->mass, 1e-12);
}

TEST(ThesisPreset, AppliesToBothArmsOfTheHumanoid) {
    const ModelDescription humanoid = buildBodyModel(thesisOptions(BodyKind::Humanoid));
    for (const char* side : {"r_", "l_"}) {
        double arm = 0;
        for (const Body& b : humanoid.bodies) {
            const bool onSide = b.name.rfind(side, 0) == 0;
            const bool armPart = b.segment == "hand" || b.segment == "upper_arm" || b.segment == "forearm";
            if (onSide && armPart) arm += b.mass;
        }
        EXPECT_NEAR(arm, 5.45, 1e-12) << side;
    }
}
