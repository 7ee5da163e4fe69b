#include "graspsim/capacity/settled_grasps.h"

#include "graspsim/capacity/grasp_capacity.h"
#include "graspsim/scenario/scenario_file.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace graspsim::capacity {
namespace {

simulation::SimulationOptions makeOptions(simulation::SimulationMode mode) {
    simulation::SimulationOptions options;
    options.integrator = simulation::IntegratorChoice::LinearlyImplicit;
    options.accuracy = 3e-4;
    options.mode = mode;
    return options;
}

GraspCapacityRequest makeRequest(const SimTK::Vec3& direction, bool torque) {
    GraspCapacityRequest request;
    request.direction = SimTK::UnitVec3(direction);
    request.directionName = "v";
    request.torque = torque;
    return request;
}

bool isSame(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

// Sample for sample, bit for bit.
void expectSameTrace(const CapacityTrace& a, const CapacityTrace& b) {
    ASSERT_EQ(a.samples.size(), b.samples.size());
    for (std::size_t k = 0; k < a.samples.size(); ++k) {
        const CapacitySample& p = a.samples[k];
        const CapacitySample& q = b.samples[k];
        EXPECT_TRUE(p.time == q.time && p.load == q.load && p.slip == q.slip && p.rotation == q.rotation && p.held == q.held &&
                    p.engaged == q.engaged && isSame(p.gripForce, q.gripForce))
            << "sample " << k << " at t = " << p.time << " s: slip " << p.slip << " against " << q.slip << " m";
    }
    EXPECT_EQ(a.releaseReason, b.releaseReason);
    EXPECT_EQ(a.failure, b.failure);
}

// Whatever another run did on the shared scene (here a pull that the approximation hands back to
// full contact, which then slides the ball off), a run started from it again repeats its first run
// exactly: nothing a run changes outlives it outside the State.
TEST(SettledGrasps, ARunRepeatsBitForBitWhateverRanOnTheSceneBefore) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    SettledGrasps grasps(ball, makeOptions(simulation::SimulationMode::Approx));
    const GraspCapacityRequest twist = makeRequest(SimTK::Vec3(1, 0, 0), true);
    const GraspCapacity first = measureGraspCapacityRamp(grasps, twist);
    const GraspCapacity pull = measureGraspCapacityRamp(grasps, makeRequest(SimTK::Vec3(-1, 0, 0), false));
    const GraspCapacity again = measureGraspCapacityRamp(grasps, twist);
    EXPECT_EQ(grasps.countSettled(), 1);
    ASSERT_TRUE(pull.trace.figures.released) << "the pull between must hand the grasp back";
    ASSERT_TRUE(first.trace.figures.slipped);
    expectSameTrace(first.trace, again.trace);
}

// The second method: a run of its own steps through the load's start without stopping. The shared
// start restarts the stepper there, which changes nothing a figure resolves: the slip onset and the
// drop agree within one sample's load (the ramp's resolution), in both modes.
TEST(SettledGrasps, ASharedStartMeasuresWhatARunThroughTheLoadsStartMeasures) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    for (const simulation::SimulationMode mode : {simulation::SimulationMode::Full, simulation::SimulationMode::Approx}) {
        SCOPED_TRACE(simulation::toString(mode));
        const simulation::SimulationOptions options = makeOptions(mode);
        SettledGrasps shared(ball, options), own(ball, options, SettledGrasps::Start::Own);
        for (const GraspCapacityRequest& request : {makeRequest(SimTK::Vec3(1, 0, 0), true), makeRequest(SimTK::Vec3(0, 0, 1), false)}) {
            const GraspCapacity a = measureGraspCapacityRamp(shared, request);
            const GraspCapacity b = measureGraspCapacityRamp(own, request);
            const double sample = a.rate * request.sampleInterval;
            ASSERT_TRUE(a.trace.figures.slipped && b.trace.figures.slipped);
            EXPECT_NEAR(a.trace.figures.slipOnsetLoad, b.trace.figures.slipOnsetLoad, sample);
            ASSERT_EQ(a.trace.figures.dropped, b.trace.figures.dropped);
            if (a.trace.figures.dropped) EXPECT_NEAR(a.trace.figures.dropLoad, b.trace.figures.dropLoad, sample);
        }
        EXPECT_EQ(shared.countSettled(), 1);
        EXPECT_EQ(own.countSettled(), 0);
    }
}

// Rigid contact's stepper is fixed-step and keeps its IK schedule outside the State: a shared run
// resumes that schedule where the settle left it (RigidStepper::initialize's nextIk), and then
// follows a run of its own (the oracle) to round-off until the slip onset. Restarted on a fresh
// schedule instead, the two part by 3e-7 m within 0.2 s.
TEST(SettledGrasps, ARigidContactRunResumesOnItsOwnSchedule) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    simulation::SimulationOptions options;
    options.contact = simulation::ContactModel::Rigid;
    SettledGrasps shared(ball, options), own(ball, options, SettledGrasps::Start::Own);
    const GraspCapacityRequest twist = makeRequest(SimTK::Vec3(1, 0, 0), true);
    const GraspCapacity a = measureGraspCapacityRamp(shared, twist);
    const GraspCapacity b = measureGraspCapacityRamp(own, twist);
    ASSERT_TRUE(a.trace.figures.slipped && b.trace.figures.slipped);
    ASSERT_EQ(a.trace.samples.size(), b.trace.samples.size());
    double apart = 0;  // m
    for (std::size_t k = 0; k < a.trace.samples.size() && a.trace.samples[k].time < a.trace.figures.slipOnsetTime; ++k) {
        apart = std::max(apart, std::abs(a.trace.samples[k].slip - b.trace.samples[k].slip));
    }
    EXPECT_LT(apart, 1e-12);
    EXPECT_NEAR(a.trace.figures.slipOnsetLoad, b.trace.figures.slipOnsetLoad, 1e-9);
    EXPECT_EQ(shared.countSettled(), 1);
}

// Every constant load of a bisection starts from the one settled grasp.
TEST(SettledGrasps, ABisectionSettlesOnce) {
    const scenario::Scenario ball = scenario::findBuiltinScenario("ball-clutch");
    SettledGrasps grasps(ball, makeOptions(simulation::SimulationMode::Full));
    const GraspCapacity c = measureGraspCapacityBisection(grasps, makeRequest(SimTK::Vec3(1, 0, 0), true), 0.3, 0.3);
    EXPECT_GE(c.bisection.runs, 4);
    EXPECT_EQ(grasps.countSettled(), 1);
}

}  // namespace
}  // namespace graspsim::capacity
