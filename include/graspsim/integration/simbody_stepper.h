#pragma once
/// @file
/// Simbody's own implicit integrator behind the Stepper interface: CPodes (variable-order BDF,
/// Newton iteration) driven as SimTK::TimeStepper drives it, but without backing its state up
/// and restoring it around scheduled events that change nothing. The default of grasp
/// simulations, whose finger joints are stiff (µs time constants).

#include "graspsim/integration/stepper.h"
#include "graspsim/io/filtered_stderr.h"

#include "graspsim/simbody.h"

#include <memory>

namespace graspsim::integration {

/// SimTK::CPodesIntegrator(BDF, Newton) stepped by SimTK::TimeStepper's loop, with two changes.
/// First, a scheduled event is handled on the integrator's state interpolated at the event time
/// (the values TimeStepper's handlers see, where the integrator backs its state up to the event
/// time), and the integrator is restarted from that state only when a handler changed it below
/// Stage::Report. A Report-stage change (a discrete variable that nothing computed up to the
/// integrator's advanced time depends on, such as control::JointPdController::rampTargets) is
/// carried over to the advanced state and the integrator goes on without a restart.
/// Second, the integrator returns after every internal step (setReturnEveryInternalStep), so
/// that CPodes checks the System's event triggers (witness functions) at the ends of its steps
/// only: asked to stop at a report inside a step, it evaluates every trigger there too, and each
/// trigger evaluation is a full realization of the System. With the grasp checks every 10 ms and
/// the engaged integrator's steps far longer, that doubled an engaged weld's dynamics evaluations
/// (`graspsim bench`: 400 against 200 per simulated second). Without triggers the integrator takes
/// the same steps and the samples agree to round-off (where the interpolation is done differs);
/// with them, a trigger's crossing is localized on a different bracket, to the same root
/// tolerance (tests/integration/simbody_stepper_test.cpp).
/// TimeStepper makes the integrator back up and resume at every scheduled event, two extra
/// dynamics evaluations each: with the grasp switch's check every 10 ms that was about a quarter
/// of an engaged approximation's cost (ball hold, `graspsim bench`: 0.014 -> 0.010 s per simulated
/// s), for checks that mostly change nothing. The trajectory is the same
/// bit for bit (tests/integration/simbody_stepper_test.cpp). Events due exactly at the time a
/// stepTo() reaches are handled at the start of the next call. The System must outlive it.
/// initialize() (again after an Instance-stage change, e.g. the object's release) starts on a
/// NEW integrator: Simbody 3.7's CPodes::init allocates the integrator's vectors anew on every
/// call without freeing those of the previous one (CPodeInit -> cpAllocVectors), which leaked
/// about 8 kB per restart in parameter sweeps (tests/integration/simbody_stepper_test.cpp).
///
/// CPodes prints its own "[CPODES ERROR]" block to stderr when it gives up, before the exception
/// that graspsim turns into one line; stepTo() keeps it off the terminal with an io::FilteredStderr
/// that lives from the first stepTo() until the stepper is destroyed or a step throws (setting one
/// up per step cost 1-2 % of an engaged run). Anything else written to stderr meanwhile is passed on
/// at the end of the next stepTo().
class SimbodyCpodesStepper : public Stepper {
public:
    /// `accuracy`: Simbody's integrator accuracy (relative, also the constraint tolerance).
    SimbodyCpodesStepper(const SimTK::System& system, double accuracy);

    void initialize(const SimTK::State& initial) override;
    void stepTo(double time) override;
    const SimTK::State& getState() const override { return integrator_->getState(); }
    long getNumStepsTaken() const override { return integrator_->getNumStepsTaken(); }

    /// Counts since construction; scheduledEvents, triggeredEvents and restarts (integrator
    /// restarts after a handler changed the state, and initialize() after the first) included.
    IntegrationStatistics getStatistics() const override;
    std::string getMethodName() const override { return "simbody-cpodes-bdf"; }

private:
    void addCurrentCountsTo(IntegrationStatistics& statistics) const;
    void makeIntegrator();
    void advanceTo(double time);
    void handleDueScheduledEvents();
    void handleEvents(SimTK::State& state, SimTK::Event::Cause cause, const SimTK::Array_<SimTK::EventId>& ids);
    SimTK::HandleEventsResults callHandlers(SimTK::State& state, SimTK::Event::Cause cause,
                                            const SimTK::Array_<SimTK::EventId>& ids) const;
    void restartIntegrator(SimTK::Stage lowestModified, bool terminate);
    void carryOverToAdvancedState(const SimTK::State& handled);

    const SimTK::System& system_;
    double accuracy_;
    std::unique_ptr<SimTK::CPodesIntegrator> integrator_;
    IntegrationStatistics totals_;  // of the runs before the last initialize()
    double lastEventTime_ = -SimTK::Infinity, lastReportTime_ = -SimTK::Infinity;
    long scheduledEvents_ = 0, triggeredEvents_ = 0, restarts_ = 0;
    bool initialized_ = false;
    std::unique_ptr<io::FilteredStderr> quiet_;  // see the class comment
};

}  // namespace graspsim::integration
