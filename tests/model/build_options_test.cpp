#include "graspsim/model/build_options.h"

#include "graspsim/error.h"
#include "graspsim/model/body_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace graspsim::model;

namespace {

std::string messageOf(const BuildOptions& o) {
    try {
        buildBodyModel(o);
    } catch (const graspsim::InputError& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST(BuildOptions, ParsesBodyAndPreset) {
    EXPECT_EQ(parseBodyKind("humanoid", "--body"), BodyKind::Humanoid);
    EXPECT_EQ(parsePreset("thesis", "--preset"), Preset::Thesis);
    EXPECT_THROW(parseBodyKind("leg", "--body"), graspsim::InputError);
    EXPECT_THROW(parsePreset("vortex", "--preset"), graspsim::InputError);
}

TEST(BuildOptions, OutOfRangeSubjectsAreRejectedBeforeBuilding) {
    BuildOptions o;
    o.subject.mass = std::numeric_limits<double>::quiet_NaN();
    EXPECT_NE(messageOf(o).find("mass"), std::string::npos);
    o = BuildOptions{};
    o.subject.stature = -1.7;
    EXPECT_NE(messageOf(o).find("stature"), std::string::npos);
    o = BuildOptions{};
    o.fingerDamping = -0.1;
    EXPECT_NE(messageOf(o).find("finger damping"), std::string::npos);
}
