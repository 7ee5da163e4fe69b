#include "graspsim/integration/cvode_integrator.h"

#include "cvode_solver.h"
#include "scheduled_times.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace graspsim::integration {

namespace {

void checkOptions(const CvodeOptions& o) {
    const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
    if (!positive(o.relativeTolerance)) {
        throw InputError("CvodeOptions.relativeTolerance: value " + std::to_string(o.relativeTolerance) +
                         " is not accepted; use a number > 0");
    }
    if (o.absoluteTolerance < 0 || o.constraintTolerance < 0 || o.maxStepSize < 0) {
        throw InputError("CvodeOptions: absoluteTolerance, constraintTolerance and maxStepSize must be >= 0 (0 = derived)");
    }
    if (o.maxOrder < 1 || o.maxOrder > 5) {
        throw InputError("CvodeOptions.maxOrder: value " + std::to_string(o.maxOrder) + " is not accepted; use 1 to 5");
    }
}

std::string timeText(const SimTK::State& s) { return "t = " + std::to_string(s.getTime()) + " s"; }

}  // namespace

CvodeIntegrator::CvodeIntegrator(const SimTK::System& system, const CvodeOptions& options)
    : system_(system), options_(options) {
    checkOptions(options_);
    solver_ = std::make_unique<CvodeSolver>(system_, options_, getConstraintTolerance());
}

CvodeIntegrator::~CvodeIntegrator() = default;

double CvodeIntegrator::getConstraintTolerance() const {
    return options_.constraintTolerance > 0 ? options_.constraintTolerance : options_.relativeTolerance;
}

// As Simbody's Integrator::initialize: onto the constraints first, then Initialization events,
// then the auto-update discrete variables.
void CvodeIntegrator::initialize(const SimTK::State& initial) {
    state_ = initial;
    terminated_ = false;
    lastEventTime_ = lastReportTime_ = -SimTK::Infinity;
    try {
        system_.realizeModel(state_);
        system_.realize(state_, SimTK::Stage::Instance);
        system_.project(state_, getConstraintTolerance());
    } catch (const std::exception& e) {
        throw NumericalError("CVODE initialize at " + timeText(state_) + ": cannot satisfy the constraints: " + e.what());
    }
    SimTK::HandleEventsResults results;
    system_.handleEvents(state_, SimTK::Event::Cause::Initialization, SimTK::Array_<SimTK::EventId>(),
                         SimTK::HandleEventsOptions(getConstraintTolerance()), results);
    terminated_ = results.getExitStatus() == SimTK::HandleEventsResults::ShouldTerminate;
    system_.realize(state_, SimTK::Stage::Acceleration);
    state_.autoUpdateDiscreteVariables();
    restart();
    initialized_ = true;
    stepsAtInitialize_ = solver_->getStatistics().steps;
}

void CvodeIntegrator::restart() {
    system_.realize(state_, SimTK::Stage::Acceleration);
    solver_->start(state_);
    events_.restarts = std::max(events_.restarts, 0L) + 1;
    saveStageVersions();
}

void CvodeIntegrator::saveStageVersions() { state_.getSystemStageVersions(stageVersions_); }

// Events due exactly at `time` are handled at the start of the next call, as SimTK::TimeStepper
// does, so the state returned at `time` is the one the ODE reached.
void CvodeIntegrator::stepTo(double time) {
    if (!initialized_) throw Error("CvodeIntegrator::stepTo(" + std::to_string(time) + ") before initialize()");
    if (state_.getLowestSystemStageDifference(stageVersions_) < SimTK::Stage::Report) restart();
    while (!terminated_ && state_.getTime() < time) {
        if (handleDueScheduledEvents()) continue;
        const ScheduledTimes next = findScheduledTimes(system_, state_, false, false);
        advance(std::min({time, next.event, next.report}));
    }
}

// Handles the scheduled events and reports due now; true if any was.
bool CvodeIntegrator::handleDueScheduledEvents() {
    SimTK::HandleEventsResults results;
    const DueScheduled done =
        handleDueScheduled(system_, state_, getConstraintTolerance(), lastEventTime_, lastReportTime_, results);
    if (done != DueScheduled::Handled) return done == DueScheduled::Reported;
    events_.scheduledEvents = std::max(events_.scheduledEvents, 0L) + 1;
    if (applyHandlerResults(results)) {
        restart();
    } else {
        solver_->carryDiscreteVariables(state_);
    }
    return true;
}

void CvodeIntegrator::advance(double tStop) {
    const bool atTrigger = solver_->advance(tStop, state_);
    system_.realize(state_, SimTK::Stage::Acceleration);
    if (atTrigger) {
        handleTriggeredEvents();
    } else {
        state_.autoUpdateDiscreteVariables();
        saveStageVersions();
    }
}

// CVODE stops just past the crossing with an interpolated state, which is put back on the
// constraint manifold before the handlers see it. CVODE then restarts from the handled state
// (its own step had gone beyond the crossing).
void CvodeIntegrator::handleTriggeredEvents() {
    const SimTK::Array_<SimTK::EventId> ids = solver_->findTriggeredEvents();
    events_.triggeredEvents = std::max(events_.triggeredEvents, 0L) + static_cast<long>(ids.size());
    try {
        system_.project(state_, getConstraintTolerance());
    } catch (const std::exception& e) {
        throw NumericalError("CVODE at " + timeText(state_) + ": cannot project the event state: " + e.what());
    }
    SimTK::HandleEventsResults results;
    system_.handleEvents(state_, SimTK::Event::Cause::Triggered, ids,
                         SimTK::HandleEventsOptions(getConstraintTolerance()), results);
    applyHandlerResults(results);
    restart();
}

// True when the handlers changed something the ODE depends on (CVODE must restart).
bool CvodeIntegrator::applyHandlerResults(const SimTK::HandleEventsResults& results) {
    if (results.getExitStatus() == SimTK::HandleEventsResults::Failed) {
        throw NumericalError("event handler failed at " + timeText(state_) + ": " + results.getMessage());
    }
    if (results.getExitStatus() == SimTK::HandleEventsResults::ShouldTerminate) terminated_ = true;
    return results.getLowestModifiedStage() < SimTK::Stage::Report;
}

long CvodeIntegrator::getNumStepsTaken() const { return solver_->getStatistics().steps - stepsAtInitialize_; }

IntegrationStatistics CvodeIntegrator::getStatistics() const {
    IntegrationStatistics s = solver_->getStatistics();
    s.triggeredEvents = std::max(events_.triggeredEvents, 0L);
    s.scheduledEvents = std::max(events_.scheduledEvents, 0L);
    s.restarts = std::max(events_.restarts, 0L);
    return s;
}

}  // namespace graspsim::integration
