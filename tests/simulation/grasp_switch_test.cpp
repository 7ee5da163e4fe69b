// The grasp approximation (--mode approx, thesis Figure 4.1) checked against the full-contact run
// of the same scenario as the second method: once the switch engages, the object held by the
// friction-limited bushing must stay where full contact keeps it.

#include "graspsim/simulation/grasp_simulation.h"

#include "graspsim/error.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

using namespace graspsim;

namespace {

simulation::SimulationOptions makeOptions(simulation::SimulationMode mode, double duration) {
    simulation::SimulationOptions options;
    options.mode = mode;
    options.duration = duration;
    return options;
}

// Largest distance of the object, at any sample from `from` on, from the point `p_G` (m).
double findLargestDistanceFrom(const simulation::SimulationResult& r, double from, const SimTK::Vec3& p_G) {
    double worst = 0;
    for (const simulation::TrajectorySample& t : r.trajectory) {
        if (t.time >= from) worst = std::max(worst, (t.p_GO - p_G).norm());
    }
    return worst;
}

}  // namespace

// Oracle: the full-contact run. Gravity sags the bushing by g / w^2 = 0.25 mm, well inside 2 mm.
TEST(GraspSwitch, BallClutchEngagesAfterSettlingAndHoldsTheObjectWhereFullContactDoes) {
    const scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    const double duration = s.simulation.settleTime + 1.0;
    const auto approx = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, duration));
    const auto full = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Full, duration));
    ASSERT_TRUE(approx.summary.complete) << approx.summary.failure;
    ASSERT_TRUE(full.summary.complete) << full.summary.failure;
    ASSERT_TRUE(approx.summary.engaged);
    ASSERT_EQ(approx.events.size(), 1u) << approx.events.back().reason;
    EXPECT_EQ(approx.events[0].kind, "engage");
    EXPECT_GT(approx.summary.engageTime, s.controller.approachTime);
    EXPECT_LT(approx.summary.releaseTime, 0);
    EXPECT_GE(approx.summary.qAtEngage, approx.summary.qThreshold);
    EXPECT_GT(approx.summary.qThreshold, 0);
    EXPECT_TRUE(approx.summary.held);
    const double gap = findLargestDistanceFrom(approx, approx.summary.engageTime, full.trajectory.back().p_GO);
    EXPECT_LT(gap, 0.002) << "approx object strays " << gap << " m from the full-contact final position";
    // While engaged there are no contacts to solve and no IK: a simulated second costs far less.
    EXPECT_LT(approx.summary.approxWallPerSimSecond, approx.summary.fullWallPerSimSecond);
}

TEST(GraspSwitch, PhonePinchEngages) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    const auto r = simulation::runGraspSimulation(s, makeOptions(simulation::SimulationMode::Approx, s.simulation.settleTime + 0.3));
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    ASSERT_TRUE(r.summary.engaged);
    EXPECT_GT(r.summary.engageTime, s.controller.approachTime);
    EXPECT_GE(r.summary.qAtEngage, r.summary.qThreshold);
    EXPECT_TRUE(r.summary.held);
}

// A slide allowance below the gravity sag releases at the first check after engagement: the
// contacts come back, the fingers unlock, and the switch re-engages once Q is back above Q_Th.
TEST(GraspSwitch, ReleasesWhenTheObjectSlidesAndReengages) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, s.simulation.settleTime + 0.1);
    options.approx.releaseSlideDistance = 1e-6;
    const auto r = simulation::runGraspSimulation(s, options);
    ASSERT_TRUE(r.summary.complete) << r.summary.failure;
    ASSERT_GE(r.events.size(), 2u);
    EXPECT_EQ(r.events[1].kind, "release");
    EXPECT_NE(r.events[1].reason.find("slid"), std::string::npos) << r.events[1].reason;
    EXPECT_GT(r.summary.releaseTime, r.summary.engageTime);
    for (std::size_t k = 0; k < r.events.size(); ++k) EXPECT_EQ(r.events[k].kind, k % 2 ? "release" : "engage");
    EXPECT_TRUE(r.summary.held);
}

TEST(GraspSwitch, RejectsBadThresholdsBeforeSimulating) {
    const scenario::Scenario s = scenario::findBuiltinScenario("phone-pinch");
    simulation::SimulationOptions options = makeOptions(simulation::SimulationMode::Approx, 0.1);
    options.approx.qThreshold = 1.0;
    options.approx.qMinimum = 2.0;
    EXPECT_THROW(simulation::runGraspSimulation(s, options), InputError);
    options.approx.qMinimum = 0;
    options.approx.releaseSlideDistance = 0;
    EXPECT_THROW(simulation::runGraspSimulation(s, options), InputError);
}
