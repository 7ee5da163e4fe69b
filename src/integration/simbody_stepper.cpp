#include "graspsim/integration/simbody_stepper.h"

#include "scheduled_times.h"

#include "graspsim/error.h"

#include <algorithm>

namespace graspsim::integration {

SimbodyCpodesStepper::SimbodyCpodesStepper(const SimTK::System& system, double accuracy)
    : system_(system), accuracy_(accuracy) {
    makeIntegrator();
}

void SimbodyCpodesStepper::makeIntegrator() {
    integrator_ = std::make_unique<SimTK::CPodesIntegrator>(system_, SimTK::CPodes::BDF, SimTK::CPodes::Newton);
    integrator_->setAccuracy(accuracy_);
    // CPodes then checks the event triggers at its own steps only. Asked for a report time inside
    // a step, it also evaluates every trigger there, and Simbody's trigger function is a full
    // realization: with any witness in the System (the weld's stick/slip, multi's detach) that
    // doubled the evaluations of an engaged hold (400 against 200 per simulated second, reports
    // every 10 ms). Without triggers the steps are the same either way, the reports to round-off.
    integrator_->setReturnEveryInternalStep(true);
}

// A restart begins on a new integrator (see the header): bank the old one's counters first.
void SimbodyCpodesStepper::initialize(const SimTK::State& initial) {
    if (initialized_) {
        addCurrentCountsTo(totals_);
        makeIntegrator();
        ++restarts_;
    }
    integrator_->initialize(initial);
    lastEventTime_ = lastReportTime_ = -SimTK::Infinity;
    initialized_ = true;
}

void SimbodyCpodesStepper::stepTo(double time) {
    if (!initialized_) throw Error("SimbodyCpodesStepper::stepTo(" + std::to_string(time) + ") before initialize()");
    if (!quiet_) quiet_ = std::make_unique<io::FilteredStderr>(std::vector<std::string>{"[CPODES ERROR]", "[CPODES WARNING]"});
    try {
        advanceTo(time);
    } catch (...) {
        quiet_.reset();  // stderr back before the caller reports the failure
        throw;
    }
    quiet_->forward();
}

// SimTK::TimeStepper's loop with one difference: scheduled events are handled on the integrator's
// interpolated state at their time instead of on its advanced state backed up to that time (and
// restored afterwards), and the integrator restarts from that state only if a handler changed it. Events due exactly at `time` are handled
// at the start of the next call, so the state returned at `time` is the one the ODE reached.
void SimbodyCpodesStepper::advanceTo(double time) {
    handleDueScheduledEvents();  // those due where the last call stopped
    while (!integrator_->isSimulationOver() && integrator_->getTime() < time) {
        const ScheduledTimes next = findScheduledTimes(system_, integrator_->getState(), false, false);
        const SimTK::Integrator::SuccessfulStepStatus status = integrator_->stepTo(std::min({time, next.event, next.report}));
        if (status == SimTK::Integrator::EndOfSimulation) {
            handleEvents(integrator_->updAdvancedState(), SimTK::Event::Cause::Termination, {});
            return;
        }
        // After these the handlers have worked on the advanced state, ahead of getState().
        if (status == SimTK::Integrator::ReachedEventTrigger) {
            triggeredEvents_ += static_cast<long>(integrator_->getTriggeredEvents().size());
            handleEvents(integrator_->updAdvancedState(), SimTK::Event::Cause::Triggered, integrator_->getTriggeredEvents());
        } else if (status == SimTK::Integrator::TimeHasAdvanced) {
            handleEvents(integrator_->updAdvancedState(), SimTK::Event::Cause::TimeAdvanced, {});
        } else if (integrator_->getTime() < time) {
            handleDueScheduledEvents();
        }
    }
}

// Scheduled reports and events due at the current state, which may be interpolated. The handlers
// work on that state in place: getState() returns the integrator's own (non-const) buffer, realized
// through Acceleration, and a copy would need realizing again, which costs what this saves. If the
// handlers change nothing the integrator goes on with its step as if it had not been looked at;
// otherwise the changed state becomes the advanced state and the integrator restarts from it, as
// TimeStepper restarts it from the advanced state backed up to the event time (same values).
void SimbodyCpodesStepper::handleDueScheduledEvents() {
    SimTK::State& now = const_cast<SimTK::State&>(integrator_->getState());
    const double t = now.getTime();
    const ScheduledTimes due = findScheduledTimes(system_, now, lastEventTime_ != t, lastReportTime_ != t);
    if (due.report <= t) {
        system_.reportEvents(now, SimTK::Event::Cause::Scheduled, due.reportIds);
        lastReportTime_ = t;
    }
    if (due.event > t) return;
    lastEventTime_ = t;
    ++scheduledEvents_;
    // Realized through Report, a change to a Report-stage variable shows in the results.
    system_.realize(now, SimTK::Stage::Report);
    const SimTK::HandleEventsResults results = callHandlers(now, SimTK::Event::Cause::Scheduled, due.eventIds);
    const bool terminate = results.getExitStatus() == SimTK::HandleEventsResults::ShouldTerminate;
    if (results.getLowestModifiedStage() >= SimTK::Stage::Report && !terminate) {
        // Nothing the integrator computed changed, but a Report-stage change (such as a ramp of
        // the PD targets planned to start later) must reach the integrator's own state, which
        // may be ahead of the interpolated `now`.
        const bool changed = results.getLowestModifiedStage() == SimTK::Stage::Report;
        if (changed && &now != &integrator_->getAdvancedState()) carryOverToAdvancedState(now);
        return;
    }
    // A change below Stage::Report restarts from `now`, even when the integrator is ahead of it.
    if (&now != &integrator_->getAdvancedState()) integrator_->updAdvancedState() = now;
    restartIntegrator(std::min(results.getLowestModifiedStage(), SimTK::Stage(SimTK::Stage::Acceleration)), terminate);
}

// The advanced state becomes `handled` (its discrete variables) at the advanced time, position
// and velocity: the integrator goes on from where it was. It realizes nothing: the integrator
// realizes its advanced state before using it.
void SimbodyCpodesStepper::carryOverToAdvancedState(const SimTK::State& handled) {
    SimTK::State& advanced = integrator_->updAdvancedState();
    const double t = advanced.getTime();
    const SimTK::Vector y = advanced.getY();
    advanced = handled;
    advanced.updTime() = t;
    advanced.updY() = y;
}

// TimeStepper's way for the events the integrator stopped at: handled on its advanced state.
void SimbodyCpodesStepper::handleEvents(SimTK::State& state, SimTK::Event::Cause cause, const SimTK::Array_<SimTK::EventId>& ids) {
    const SimTK::HandleEventsResults results = callHandlers(state, cause, ids);
    restartIntegrator(results.getLowestModifiedStage(), results.getExitStatus() == SimTK::HandleEventsResults::ShouldTerminate);
}

SimTK::HandleEventsResults SimbodyCpodesStepper::callHandlers(SimTK::State& state, SimTK::Event::Cause cause,
                                                             const SimTK::Array_<SimTK::EventId>& ids) const {
    SimTK::HandleEventsOptions options(integrator_->getConstraintToleranceInUse());
    if (integrator_->isInfinityNormInUse()) options.setOption(SimTK::HandleEventsOptions::UseInfinityNorm);
    SimTK::HandleEventsResults results;
    system_.handleEvents(state, cause, ids, options, results);
    if (results.getExitStatus() == SimTK::HandleEventsResults::Failed) {
        throw NumericalError("event handler failed at t = " + std::to_string(state.getTime()) + " s: " + results.getMessage());
    }
    return results;
}

void SimbodyCpodesStepper::restartIntegrator(SimTK::Stage lowestModified, bool terminate) {
    if (lowestModified < SimTK::Stage::Report) ++restarts_;
    integrator_->reinitialize(lowestModified, terminate);
}

void SimbodyCpodesStepper::addCurrentCountsTo(IntegrationStatistics& s) const {
    s.steps += integrator_->getNumStepsTaken();
    s.rhsEvaluations += integrator_->getNumRealizations();
    s.errorTestFailures += integrator_->getNumErrorTestFailures();
    s.convergenceFailures += integrator_->getNumConvergenceTestFailures();
    s.projections += integrator_->getNumProjections();
    s.newtonIterations = std::max(s.newtonIterations, 0L) + integrator_->getNumIterations();
}

IntegrationStatistics SimbodyCpodesStepper::getStatistics() const {
    IntegrationStatistics all = totals_;
    if (initialized_) addCurrentCountsTo(all);
    all.scheduledEvents = scheduledEvents_;
    all.triggeredEvents = triggeredEvents_;
    all.restarts = restarts_;
    return all;
}

}  // namespace graspsim::integration
