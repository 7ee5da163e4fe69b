// Localizing a force's switch of regime (src/integration/switch_localization.h): the oracle is the
// documented rule itself (bisection to a window, or an estimate's two steps) and Simbody's event
// localization window.
#include "switch_localization.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace graspsim::integration {
namespace {

TEST(SwitchLocalization, ATermLostIsASwitchATermGainedIsNot) {
    using Terms = std::vector<std::int64_t>;
    EXPECT_EQ(SwitchLocalization::findLostTerms({4, 5}, {4, 5}), Terms{});
    EXPECT_EQ(SwitchLocalization::findLostTerms({4}, {4, 5}), Terms{});                // starts sticking
    EXPECT_EQ(SwitchLocalization::findLostTerms({}, {2}), Terms{});                    // touches
    EXPECT_EQ(SwitchLocalization::findLostTerms({4, 5}, {4}), Terms{5});               // starts sliding
    EXPECT_EQ(SwitchLocalization::findLostTerms({2, 4, 5}, {4, 5}), Terms{2});         // lets go
    EXPECT_EQ(SwitchLocalization::findLostTerms({5, 4, 2}, {2, 4, 5, 7}), Terms{});    // order does not matter
    EXPECT_EQ(SwitchLocalization::findLostTerms({3, 3}, {3}), Terms{3});               // counted with multiplicity
}

TEST(SwitchLocalization, TheWindowIsSimbodysEventWindow) {
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter(system);
    EXPECT_NEAR(SwitchLocalization::findWindow(system, 1e-3), 1e-5, 1e-18);  // 1e-3 x 0.1 s x 0.1
    system.setDefaultTimeScale(0.5);
    EXPECT_NEAR(SwitchLocalization::findWindow(system, 1e-3), 5e-5, 1e-18);
}

constexpr double kSwitch = 3.3e-3, kWindow = 1e-5, kCap = 5e-3;

// Steps from t = 0 toward a switch at kSwitch, capped at kCap, until the step that crosses it
// stands; with `estimated`, each crossing step sets the estimate from a margin linear in time
// (m = kSwitch - t) at its two ends. Returns the attempts that crossed; t and h the last step.
int localize(SwitchLocalization& switches, bool estimated, double& t, double& h) {
    const auto margin = [](double time) { return kSwitch - time; };
    t = 0;
    h = switches.limitStep(t, kCap);
    int attempts = 0;
    for (;; ++attempts) {
        if (attempts >= 20) return attempts;
        if (t + h >= kSwitch) {
            if (!switches.crossed(t, h)) break;
            if (estimated) switches.setEstimate(t + h * margin(t) / (margin(t) - margin(t + h)));
        } else {
            t += h;
        }
        h = switches.limitStep(t, kCap);
    }
    return attempts;
}

// A 5 ms step from t = 0 crosses a switch at 3.3 ms: the steps halve the bracket (0, 5 ms] until
// it is no longer than the window, keeping the steps that fall short of the switch.
TEST(SwitchLocalization, BisectsTowardTheSwitchDownToTheWindow) {
    SwitchLocalization switches(kWindow);
    EXPECT_EQ(switches.limitStep(0, kCap), kCap);  // nothing bracketed
    double t = 0, h = 0;
    const int attempts = localize(switches, false, t, h);
    EXPECT_LE(h, kWindow);
    EXPECT_LE(t, kSwitch);
    EXPECT_GE(t + h, kSwitch);
    EXPECT_LE(attempts, 10);  // log2(5 ms / 10 us) = 9
    EXPECT_EQ(switches.limitStep(t + h, kCap), kCap);  // the bracket passed: free again
}

// The same switch with a margin that is linear in time: the estimate from the first step's two
// ends is the switch, and two attempts localize it.
TEST(SwitchLocalization, AnEstimateFromLinearMarginsLocalizesInTwoAttempts) {
    SwitchLocalization switches(kWindow);
    double t = 0, h = 0;
    EXPECT_EQ(localize(switches, true, t, h), 2);  // short of it by half a window, then one window across it
    EXPECT_LE(h, kWindow);
    EXPECT_LE(t, kSwitch);
    EXPECT_GE(t + h, kSwitch);
}

// An estimate is used up to kMaxEstimates times per switch, never past the bracket, and NaN
// means bisection; past the estimate without the switch, the rest of the bracket in one step.
TEST(SwitchLocalization, EstimatesFallBackToBisection) {
    SwitchLocalization switches(1e-5);
    ASSERT_TRUE(switches.crossed(0, 4e-3));
    switches.setEstimate(SimTK::NaN);
    EXPECT_EQ(switches.limitStep(0, 5e-3), 2e-3);
    switches.setEstimate(5e-3);  // beyond the bracket's end
    EXPECT_EQ(switches.limitStep(0, 5e-3), 2e-3);
    switches.setEstimate(1e-3);
    EXPECT_DOUBLE_EQ(switches.limitStep(0, 5e-3), 1e-3 - 5e-6);
    EXPECT_EQ(switches.limitStep(1e-3 - 5e-6, 5e-3), 1e-5);
    EXPECT_DOUBLE_EQ(switches.limitStep(1e-3 + 5e-6, 5e-3), 4e-3 - (1e-3 + 5e-6));
    for (int k = 1; k < SwitchLocalization::kMaxEstimates; ++k) {
        ASSERT_TRUE(switches.crossed(0, 3e-3));  // the same switch, a shorter bracket
        switches.setEstimate(1e-3);
    }
    ASSERT_TRUE(switches.crossed(0, 2e-3));
    switches.setEstimate(1e-3);  // one too many
    EXPECT_EQ(switches.limitStep(0, 5e-3), 1e-3);  // bisection: half of (0, 2 ms]
}

TEST(SwitchLocalization, AShorterProposalStandsAndClearForgetsTheBracket) {
    SwitchLocalization switches(1e-5);
    EXPECT_TRUE(switches.crossed(0, 4e-3));
    EXPECT_EQ(switches.limitStep(0, 1e-3), 1e-3);  // shorter than half the bracket
    EXPECT_EQ(switches.limitStep(0, 5e-3), 2e-3);
    switches.clear();
    EXPECT_EQ(switches.limitStep(0, 5e-3), 5e-3);
}

}  // namespace
}  // namespace graspsim::integration
