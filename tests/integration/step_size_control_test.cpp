// The error-controlled stepper's step sizes (src/integration/step_size_control.h): the oracle is
// the documented rule itself, in closed form.
#include "step_size_control.h"

#include <gtest/gtest.h>

#include <cmath>

namespace graspsim::integration {
namespace {

constexpr double kCap = 5e-3;  // s

// A control whose next proposal is `proposal` (s): a step of `proposal` / 1.8 accepted with the
// error that grows it by 1.8 (0.9 error^(-1/2) = 1.8).
StepSizeControl makeWithProposal(double proposal) {
    StepSizeControl control(kCap);
    EXPECT_TRUE(control.acceptStep(proposal / 1.8, 0.25));
    EXPECT_NEAR(control.getProposal(), std::min(proposal, kCap), 1e-15);
    return control;
}

TEST(StepSizeControl, AcceptsUpToTheAccuracyAndGrowsByTheSecondOrderRule) {
    StepSizeControl control(kCap);
    EXPECT_DOUBLE_EQ(control.getProposal(), kCap);  // no error seen yet: the cap
    EXPECT_TRUE(control.acceptStep(1e-3, 0.81));
    EXPECT_NEAR(control.getProposal(), 1e-3, 1e-15);  // 0.9 / sqrt(0.81) = 1
    EXPECT_TRUE(control.acceptStep(1e-4, 1e-12));
    EXPECT_NEAR(control.getProposal(), 5e-4, 1e-15);  // growth capped at 5x
    EXPECT_FALSE(control.acceptStep(1e-3, 100));
    EXPECT_NEAR(control.getProposal(), 2e-4, 1e-15);  // shrink floored at 0.2x
    EXPECT_TRUE(control.acceptStep(2e-4, 0.01));
    EXPECT_NEAR(control.getProposal(), 2e-4, 1e-15);  // no growth right after a rejection
    EXPECT_TRUE(control.acceptStep(StepSizeControl::kMinStepSize, 1e6));  // too short to reject
}

TEST(StepSizeControl, AStopWithinOneAndAHalfProposalsIsReachedInOneOrTwoEqualSteps) {
    const StepSizeControl control = makeWithProposal(2e-3);
    EXPECT_NEAR(control.findStepToStop(1.5e-3), 1.5e-3, 1e-15);
    EXPECT_NEAR(control.findStepToStop(2.9e-3), 1.45e-3, 1e-15);
    EXPECT_NEAR(control.findStepToStop(10e-3), 2e-3, 1e-15);  // far: the proposal
}

TEST(StepSizeControl, AProposalNearTheCapReachesAStopInEqualStepsAtMostTheCap) {
    // Engaged: 4.5 ms proposed, the next IK event 10 ms away: two steps of 5 ms, not 4.5 + 2 x 2.75.
    const StepSizeControl control = makeWithProposal(4.5e-3);
    EXPECT_NEAR(control.findStepToStop(10e-3), 5e-3, 1e-15);
    EXPECT_NEAR(control.findStepToStop(5.4e-3), 2.7e-3, 1e-15);
    EXPECT_NEAR(control.findStepToStop(17e-3), 17e-3 / 4, 1e-15);
    EXPECT_NEAR(control.findStepToStop(30e-3), 4.5e-3, 1e-15);  // beyond four caps: the proposal
    // A proposal further from the cap is not stretched: 4 ms toward 10 ms is 4 ms.
    EXPECT_NEAR(makeWithProposal(4e-3).findStepToStop(10e-3), 4e-3, 1e-15);
}

TEST(StepSizeControl, AStepTakenAgainAfterARejectionIsShorter) {
    StepSizeControl control = makeWithProposal(kCap);
    const double rejected = control.findStepToStop(10e-3);
    EXPECT_FALSE(control.acceptStep(rejected, 1.07));  // proposes 0.87x: within 1.15x of the cap
    const double again = control.findStepToStop(10e-3);
    EXPECT_LT(again, rejected);
    EXPECT_NEAR(again, rejected * 0.9 / std::sqrt(1.07), 1e-15);  // the proposal, not stretched
}

// After a landing time the proposal starts again from the step given, then grows by the rule.
TEST(StepSizeControl, ARestartProposesItsStepAndGrowsFromThere) {
    StepSizeControl control = makeWithProposal(kCap);
    EXPECT_FALSE(control.acceptStep(kCap, 4));  // a rejection: growth would be held back
    control.restart(1e-5);
    EXPECT_NEAR(control.getProposal(), 1e-5, 1e-18);
    EXPECT_NEAR(control.findStepToStop(10e-3), 1e-5, 1e-18);
    EXPECT_TRUE(control.acceptStep(1e-5, 1e-6));
    EXPECT_NEAR(control.getProposal(), 5e-5, 1e-18);  // grows 5x: the restart cleared the rejection
}

}  // namespace
}  // namespace graspsim::integration
