// The analytic cases against their closed forms (the same bounds the suite reports), and the
// two-finger limit seen from both sides by both contact models.

#include "graspsim/validation/analytic_cases.h"

#include <gtest/gtest.h>

using namespace graspsim;

TEST(AnalyticCases, EveryCasePassesItsBound) {
    const std::vector<validation::ValidationCheck> checks = validation::runAnalyticCases();
    ASSERT_EQ(checks.size(), 5u);
    for (const validation::ValidationCheck& c : checks) EXPECT_TRUE(c.pass) << c.name << ": " << c.value << " " << c.unit;
}

TEST(AnalyticCases, SqueezeSlidesFasterWithMorePullForBothModels) {
    for (bool rigid : {false, true}) {
        const double limit = 2 * validation::kSqueezeMu * validation::kSqueezePress;
        const auto a = validation::runSqueeze(rigid, 2 * limit, 0.2);
        EXPECT_NEAR(a.acceleration, limit / validation::kSqueezeBoxMass, 0.05 * limit) << rigid;
        EXPECT_GT(a.displacement, 0) << rigid;
    }
}

TEST(AnalyticCases, PendulumPeriodDependsOnAmplitudeAsTheEllipticIntegralSays) {
    const auto small = validation::runPendulum(0.1, 1e-8), large = validation::runPendulum(2.0, 1e-8);
    EXPECT_NEAR(small.measured, small.exact, 1e-5 * small.exact);
    EXPECT_NEAR(large.measured, large.exact, 1e-5 * large.exact);
    EXPECT_GT(large.exact, 1.2 * small.exact);  // 2 rad swings take ~28 % longer
}
