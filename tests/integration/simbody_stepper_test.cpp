// Simbody's CPodes behind the Stepper interface (the grasp simulations' default) on a pendulum. Oracles: a restart continues exactly as a
// stepper started fresh from the same state would (bit for bit), and restarting does not grow
// the heap (re-initializing one Simbody 3.7 CPodesIntegrator leaked ~8 kB each time); with
// scheduled and triggered event handlers, the trajectory is SimTK::TimeStepper's bit for bit
// (the same integrator driven by Simbody's own loop), with fewer dynamics evaluations when the
// scheduled handlers change nothing.

#include "graspsim/integration/simbody_stepper.h"

#include "live_heap.h"

#include <simbody/Simbody.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using graspsim::integration::SimbodyCpodesStepper;

namespace {

struct Pendulum {
    // `addHandlers`: called with the pendulum (pin and a torque on it) before the topology is fixed.
    template <class AddHandlers>
    explicit Pendulum(AddHandlers addHandlers) : matter(system), forces(system), gravity(forces, matter, SimTK::Vec3(0, -9.81, 0)) {
        const SimTK::Body::Rigid body(SimTK::MassProperties(1.0, SimTK::Vec3(0), SimTK::Inertia(0.01)));
        pin = SimTK::MobilizedBody::Pin(matter.Ground(), SimTK::Transform(), body, SimTK::Vec3(0, 0.5, 0));
        torque = SimTK::Force::MobilityConstantForce(forces, pin, 0, 0.0);
        addHandlers(*this);
        system.realizeTopology();
    }
    Pendulum() : Pendulum([](Pendulum&) {}) {}
    SimTK::State makeState() const {
        SimTK::State s = system.getDefaultState();
        pin.setOneQ(s, 0, 1.0);  // rad
        return s;
    }
    SimTK::MultibodySystem system;
    SimTK::SimbodyMatterSubsystem matter;
    SimTK::GeneralForceSubsystem forces;
    SimTK::Force::Gravity gravity;
    SimTK::MobilizedBody::Pin pin;
    SimTK::Force::MobilityConstantForce torque;
};

// Every 10 ms: looks at the state and changes nothing.
class Watcher : public SimTK::PeriodicEventHandler {
public:
    explicit Watcher(const Pendulum& p) : SimTK::PeriodicEventHandler(0.01), p_(p) {}
    void handleEvent(SimTK::State& s, SimTK::Real, bool& terminate) const override {
        p_.system.realize(s, SimTK::Stage::Acceleration);
        terminate = false;
    }

private:
    const Pendulum& p_;
};

// Every 25 ms: sets the torque on the pin to -0.5 q (N m), a Dynamics-stage change.
class Kicker : public SimTK::PeriodicEventHandler {
public:
    explicit Kicker(const Pendulum& p) : SimTK::PeriodicEventHandler(0.025), p_(p) {}
    void handleEvent(SimTK::State& s, SimTK::Real, bool& terminate) const override {
        p_.torque.setForce(s, -0.5 * p_.pin.getOneQ(s, 0));
        terminate = false;
    }

private:
    const Pendulum& p_;
};

// Where the pendulum swings through the vertical (q falling through 0): a fixed 0.2 N m torque.
class Crossing : public SimTK::TriggeredEventHandler {
public:
    explicit Crossing(const Pendulum& p) : SimTK::TriggeredEventHandler(SimTK::Stage::Position), p_(p) {
        getTriggerInfo().setTriggerOnRisingSignTransition(false);
    }
    SimTK::Real getValue(const SimTK::State& s) const override { return p_.pin.getOneQ(s, 0); }
    void handleEvent(SimTK::State& s, SimTK::Real, bool& terminate) const override {
        p_.torque.setForce(s, 0.2);
        terminate = false;
    }

private:
    const Pendulum& p_;
};

struct Sampled {
    std::vector<double> t, q, u;
    long realizations = 0;
};

// Samples every `dt` to `end` with `stepTo` (either stepper's), then counts realizations.
template <class StepTo, class GetState>
Sampled sample(double dt, double end, StepTo stepTo, GetState getState) {
    Sampled out;
    for (int k = 1; k * dt <= end + 1e-12; ++k) {
        stepTo(k * dt);
        const SimTK::State& s = getState();
        out.t.push_back(s.getTime());
        out.q.push_back(s.getQ()[0]);
        out.u.push_back(s.getU()[0]);
    }
    return out;
}

// Which CPodes mode SimTK::TimeStepper's integrator runs in: ours (it returns after every
// internal step) or CPodes's default (it steps on to each report time and interpolates).
enum class ReferenceMode { EveryStep, Default };

struct Compared {
    Sampled ours, theirs;
    long oursSystemRealizations = 0, theirsSystemRealizations = 0;  // of Stage::Acceleration, triggers' included
};

// The same pendulum (built by `make`) run by SimbodyCpodesStepper and by SimTK::TimeStepper with a
// CPodes integrator of the same accuracy, sampled every `dt` for 1 s.
template <class Make>
Compared compareWithTimeStepper(Make make, double dt, ReferenceMode mode) {
    const Pendulum a = make(), b = make();
    Compared c;
    SimbodyCpodesStepper stepper(a.system, 1e-6);
    stepper.initialize(a.makeState());
    c.ours = sample(dt, 1.0, [&](double t) { stepper.stepTo(t); }, [&]() -> const SimTK::State& { return stepper.getState(); });
    c.ours.realizations = stepper.getStatistics().rhsEvaluations;
    SimTK::CPodesIntegrator integrator(b.system, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
    integrator.setAccuracy(1e-6);
    integrator.setReturnEveryInternalStep(mode == ReferenceMode::EveryStep);
    SimTK::TimeStepper reference(b.system, integrator);
    reference.initialize(b.makeState());
    c.theirs = sample(dt, 1.0, [&](double t) { reference.stepTo(t); }, [&]() -> const SimTK::State& { return reference.getState(); });
    c.theirs.realizations = integrator.getNumRealizations();
    c.oursSystemRealizations = a.system.getNumRealizationsOfThisStage(SimTK::Stage::Acceleration);
    c.theirsSystemRealizations = b.system.getNumRealizationsOfThisStage(SimTK::Stage::Acceleration);
    return c;
}

// Every sample within `tolerance` (0: identical).
void expectSameSamples(const Sampled& x, const Sampled& y, double tolerance) {
    ASSERT_EQ(x.t.size(), y.t.size());
    for (std::size_t k = 0; k < x.t.size(); ++k) {
        EXPECT_EQ(x.t[k], y.t[k]);
        EXPECT_NEAR(x.q[k], y.q[k], tolerance) << "at t = " << x.t[k];
        EXPECT_NEAR(x.u[k], y.u[k], tolerance) << "at t = " << x.t[k];
        if (tolerance == 0) {
            EXPECT_EQ(x.q[k], y.q[k]) << "at t = " << x.t[k];
            EXPECT_EQ(x.u[k], y.u[k]) << "at t = " << x.t[k];
        }
    }
}

// TimeStepper driving the same integrator in the same mode: every sample must be identical.
template <class Make>
void expectSameAsTimeStepper(Make make, double dt, long* ours = nullptr, long* theirs = nullptr) {
    const Compared c = compareWithTimeStepper(make, dt, ReferenceMode::EveryStep);
    expectSameSamples(c.ours, c.theirs, 0);
    if (ours) *ours = c.ours.realizations;
    if (theirs) *theirs = c.theirs.realizations;
}

}  // namespace

TEST(SimbodyCpodesStepper, HandlersThatChangeNothingLeaveTheTrajectoryAndSaveEvaluations) {
    const auto make = [] { return Pendulum([](Pendulum& p) { p.system.addEventHandler(new Watcher(p)); }); };
    long ours = 0, theirs = 0;
    expectSameAsTimeStepper(make, 0.01, &ours, &theirs);  // samples at the event times
    // TimeStepper backs the integrator up to each of the 100 events and resumes: two
    // evaluations each that the interpolated handling does not need.
    EXPECT_LT(ours, theirs - 100);
    expectSameAsTimeStepper(make, 0.0375);  // samples between them
}

TEST(SimbodyCpodesStepper, HandlersThatChangeTheStateRestartItAsTimeStepperDoes) {
    const auto make = [] {
        return Pendulum([](Pendulum& p) {
            p.system.addEventHandler(new Kicker(p));
            p.system.addEventHandler(new Crossing(p));
        });
    };
    expectSameAsTimeStepper(make, 0.025);
    expectSameAsTimeStepper(make, 0.01);
    const Pendulum p = make();
    SimbodyCpodesStepper stepper(p.system, 1e-6);
    stepper.initialize(p.makeState());
    stepper.stepTo(1.0);
    const graspsim::integration::IntegrationStatistics s = stepper.getStatistics();
    EXPECT_EQ(s.scheduledEvents, 40);  // t = 0, 0.025, ..., 0.975: the one at 1.0 waits for the next call
    EXPECT_GT(s.triggeredEvents, 0);   // the swing crosses the vertical within 1 s
    EXPECT_GE(s.restarts, s.scheduledEvents - 1);
}

// Largest |q - q_ref| and |u - u_ref| over the samples.
double findLargestDifference(const Sampled& x, const Sampled& reference) {
    double largest = 0;
    for (std::size_t k = 0; k < x.t.size(); ++k) {
        largest = std::max({largest, std::abs(x.q[k] - reference.q[k]), std::abs(x.u[k] - reference.u[k])});
    }
    return largest;
}

// Against CPodes's default mode, which steps on to each report time and interpolates there:
// without triggers the integrator's steps are the same, and the samples differ only by the
// round-off of where the interpolation is done (the kicks read it back in). With a trigger (the
// crossing), the default mode also evaluates it at every report inside a step, a full realization
// each, which returning after every step avoids. The crossing is localized on another bracket and
// the integrator restarts from a slightly different state, so after it the two runs differ by
// their integration error: the oracle is a run at 1e-10, from which ours must be no farther than
// TimeStepper's own (to within a factor of two).
TEST(SimbodyCpodesStepper, TriggersAreCheckedAtStepsNotAtEveryReport) {
    const auto kicked = [] { return Pendulum([](Pendulum& p) { p.system.addEventHandler(new Kicker(p)); }); };
    const Compared k = compareWithTimeStepper(kicked, 0.001, ReferenceMode::Default);
    expectSameSamples(k.ours, k.theirs, 1e-12);
    const auto watched = [] { return Pendulum([](Pendulum& p) { p.system.addEventHandler(new Crossing(p)); }); };
    const Compared c = compareWithTimeStepper(watched, 0.001, ReferenceMode::Default);
    const Pendulum exact = watched();
    SimTK::CPodesIntegrator integrator(exact.system, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
    integrator.setAccuracy(1e-10);
    SimTK::TimeStepper reference(exact.system, integrator);
    reference.initialize(exact.makeState());
    const Sampled r = sample(0.001, 1.0, [&](double t) { reference.stepTo(t); }, [&]() -> const SimTK::State& { return reference.getState(); });
    const double ours = findLargestDifference(c.ours, r), theirs = findLargestDifference(c.theirs, r);
    RecordProperty("largest_difference_from_reference_ours", std::to_string(ours));
    RecordProperty("largest_difference_from_reference_timestepper", std::to_string(theirs));
    RecordProperty("realizations_ours", std::to_string(c.oursSystemRealizations));
    RecordProperty("realizations_timestepper", std::to_string(c.theirsSystemRealizations));
    EXPECT_LT(ours, 2 * theirs) << ours << " vs " << theirs;
    EXPECT_LT(ours, 1e-3);
    // 1000 reports, far more than the integrator's steps: one trigger evaluation each saved.
    EXPECT_LT(c.oursSystemRealizations, c.theirsSystemRealizations - 500)
        << c.oursSystemRealizations << " vs " << c.theirsSystemRealizations;
}

TEST(SimbodyCpodesStepper, RestartContinuesLikeAFreshStepper) {
    const Pendulum p;
    SimbodyCpodesStepper restarted(p.system, 1e-6);
    restarted.initialize(p.makeState());
    restarted.stepTo(0.1);
    const SimTK::State atRestart = restarted.getState();
    restarted.initialize(atRestart);
    restarted.stepTo(0.3);
    SimbodyCpodesStepper fresh(p.system, 1e-6);
    fresh.initialize(atRestart);
    fresh.stepTo(0.3);
    EXPECT_EQ(restarted.getState().getTime(), fresh.getState().getTime());
    EXPECT_EQ(restarted.getState().getQ()[0], fresh.getState().getQ()[0]);
    EXPECT_EQ(restarted.getState().getU()[0], fresh.getState().getU()[0]);
    EXPECT_EQ(restarted.getNumStepsTaken(), fresh.getNumStepsTaken());
    EXPECT_GT(restarted.getNumStepsTaken(), 0);
}

TEST(SimbodyCpodesStepper, RestartsDoNotGrowTheHeap) {
    const Pendulum p;
    SimbodyCpodesStepper stepper(p.system, 1e-6);
    const SimTK::State start = p.makeState();
    const auto restart = [&] {
        stepper.initialize(start);
        stepper.stepTo(0.01);
    };
    for (int k = 0; k < 10; ++k) restart();  // first-use allocations
    const double before = graspsim::testing::findLiveHeapBytes();
    for (int k = 0; k < 100; ++k) restart();
    // 100 leaked vector sets would be several hundred kB; the bound leaves room for allocator noise.
    EXPECT_LT(graspsim::testing::findLiveHeapBytes() - before, 50e3);
}
