#include <graspsim/anthropometry/units.h>

#include <gtest/gtest.h>

#include <cmath>

namespace graspsim::anthropometry {
namespace {

static_assert(fromPercent(100.0) == 1.0, "conversions are usable at compile time");

TEST(Units, PercentBecomesFraction) {
    EXPECT_DOUBLE_EQ(fromPercent(43.46), 0.4346);
    EXPECT_DOUBLE_EQ(fromPercent(0.0), 0.0);
}

TEST(Units, MillimetresBecomeMetres) {
    EXPECT_DOUBLE_EQ(fromMillimetres(1741.0), 1.741);
    EXPECT_DOUBLE_EQ(fromMillimetres(86.2), 0.0862);
}

TEST(Units, DegreesBecomeRadians) {
    const double pi = std::acos(-1.0);
    EXPECT_DOUBLE_EQ(fromDegrees(180.0), pi);
    EXPECT_DOUBLE_EQ(fromDegrees(-90.0), -pi / 2.0);
}

}  // namespace
}  // namespace graspsim::anthropometry
