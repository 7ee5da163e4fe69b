// How the bench times things (src/validation/run_timing). Oracles: medians and rates worked out by
// hand from made-up marks; evaluation counts against Simbody's own realization counter.

#include "run_timing.h"

#include <simbody/Simbody.h>
#include <gtest/gtest.h>

#include <vector>

using graspsim::validation::FloorRun;
using graspsim::validation::Mark;

namespace {

struct Pendulum {
    Pendulum() : matter(system), forces(system), gravity(forces, matter, SimTK::Vec3(0, -9.81, 0)) {
        const SimTK::Body::Rigid body(SimTK::MassProperties(1.0, SimTK::Vec3(0), SimTK::Inertia(0.01)));
        pin = SimTK::MobilizedBody::Pin(matter.Ground(), SimTK::Transform(), body, SimTK::Vec3(0, 0.5, 0));
        system.realizeTopology();
    }
    SimTK::State makeState() const {
        SimTK::State s = system.getDefaultState();
        pin.setOneQ(s, 0, 1.0);  // rad
        return s;
    }
    long countAccelerations() const { return system.getNumRealizationsOfThisStage(SimTK::Stage::Acceleration); }
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter;
    SimTK::GeneralForceSubsystem forces;
    SimTK::Force::Gravity gravity;
    SimTK::MobilizedBody::Pin pin;
};

}  // namespace

TEST(RunTiming, HoldCostIsTheMedianWindowAndTheMeanEvaluationRate) {
    // Windows of 1 s taking 1, 2, 1 and 6 s of wall time: median 1.5; 400 evaluations in 4 s.
    const std::vector<Mark> marks{{0, 0, 0}, {1, 1, 100}, {2, 3, 200}, {3, 4, 300}, {4, 10, 400}};
    const graspsim::validation::HoldCost cost = graspsim::validation::findHoldCost(marks);
    EXPECT_DOUBLE_EQ(cost.wallPerSimSecond, 1.5);
    EXPECT_DOUBLE_EQ(cost.evaluationsPerSimSecond, 100);
    EXPECT_EQ(graspsim::validation::findHoldCost({}).wallPerSimSecond, 0);
    EXPECT_EQ(graspsim::validation::findHoldCost({marks[0]}).evaluationsPerSimSecond, 0);
    // The same stretch as one-second pieces, each counted from zero.
    const graspsim::validation::HoldCost pieces =
        graspsim::validation::findHoldCostOfSeconds({{1, 1, 100}, {1, 2, 100}, {1, 1, 100}, {1, 6, 100}});
    EXPECT_DOUBLE_EQ(pieces.wallPerSimSecond, 1.5);
    EXPECT_DOUBLE_EQ(pieces.evaluationsPerSimSecond, 100);
}

TEST(RunTiming, PairedRatioIsTheMedianOfWindowByWindowRatios) {
    const std::vector<Mark> hold{{0, 0, 0}, {1, 1, 0}, {2, 3, 0}, {3, 4, 0}, {4, 10, 0}};
    // Ratios 1, 2, 2, 2 (a slow window of the hold paired with a slow floor window), median 2;
    // a floor window of zero wall time is left out.
    const auto floor = [](std::vector<double> walls) {
        std::vector<Mark> seconds;
        for (double w : walls) seconds.push_back({1, w, 0});
        return seconds;
    };
    EXPECT_DOUBLE_EQ(graspsim::validation::findMedianPairedRatio(hold, floor({1, 1, 0.5, 3})), 2);
    EXPECT_DOUBLE_EQ(graspsim::validation::findMedianPairedRatio(hold, floor({1, 0, 0.5, 3})), 2);
    EXPECT_EQ(graspsim::validation::findMedianPairedRatio(hold, {}), 0);
}

TEST(RunTiming, RunClockLeavesOutWhatTheObserverEvaluates) {
    const Pendulum p;
    SimTK::State s = p.makeState();
    graspsim::validation::RunClock clock;
    const Mark start = clock.mark(0, p.system);
    const auto evaluate = [&] {
        s.invalidateAllCacheAtOrAbove(SimTK::Stage::Time);
        p.system.realize(s, SimTK::Stage::Acceleration);
    };
    for (int k = 0; k < 3; ++k) evaluate();  // the run's
    clock.beginObserving(p.system);
    for (int k = 0; k < 7; ++k) evaluate();  // the observer's
    clock.endObserving(p.system);
    evaluate();
    EXPECT_EQ(clock.mark(1, p.system).evaluations - start.evaluations, 4);
    EXPECT_GE(clock.getObservingSeconds(), 0);
}

TEST(RunTiming, FloorRunAdvancesOneSimulatedSecondAndCountsItsEvaluations) {
    const Pendulum p;
    FloorRun floor(p.system, p.makeState(), 1e-6, 0.01);
    const long before = p.countAccelerations();
    const Mark one = floor.advanceOneSecond();
    EXPECT_EQ(one.time, 1.0);
    EXPECT_EQ(one.evaluations, p.countAccelerations() - before);
    // At least one interpolated report per 10 ms, each realized to Acceleration.
    EXPECT_GE(one.evaluations, 100);
    EXPECT_GT(one.wall, 0);
    const graspsim::validation::HoldCost cost = graspsim::validation::timeFloorHold(p.system, p.makeState(), 1e-6, 0.01, 2);
    EXPECT_GE(cost.evaluationsPerSimSecond, 100);
}
