#include "graspsim/integration/linearly_implicit_stepper.h"

#include "scheduled_times.h"

#include "graspsim/error.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

namespace graspsim::integration {

namespace {

void checkOptions(const LinearlyImplicitOptions& o) {
    const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
    if (!positive(o.stepSize)) {
        throw InputError("step size: value " + std::to_string(o.stepSize) + " s is not accepted; use a finite number > 0");
    }
    if (!positive(o.constraintTolerance)) {
        throw InputError("LinearlyImplicitOptions.constraintTolerance: value " + std::to_string(o.constraintTolerance) +
                         " is not accepted; use a finite number > 0");
    }
}

std::string timeText(const SimTK::State& s) { return "t = " + std::to_string(s.getTime()) + " s"; }

// Whether a trigger going from `before` to `after` crosses zero in a direction `info` asks for.
bool isCrossing(const SimTK::EventTriggerInfo& info, double before, double after) {
    if (before == 0 || (before > 0) == (after > 0)) return false;
    if (after == 0 && before > 0) return info.shouldTriggerOnFallingSignTransition();
    return after > before ? info.shouldTriggerOnRisingSignTransition() : info.shouldTriggerOnFallingSignTransition();
}

}  // namespace

LinearlyImplicitStepper::LinearlyImplicitStepper(const SimTK::MultibodySystem& system,
                                                 std::vector<const ForceJacobianContributor*> contributors,
                                                 const LinearlyImplicitOptions& options)
    : system_(system), contributors_(std::move(contributors)), options_(options) {
    checkOptions(options_);
}

// As Simbody's Integrator::initialize: onto the constraints first, then Initialization events,
// then the auto-update discrete variables.
void LinearlyImplicitStepper::initialize(const SimTK::State& initial) {
    state_ = initial;
    terminated_ = false;
    lastEventTime_ = lastReportTime_ = -SimTK::Infinity;
    try {
        system_.realizeModel(state_);
        system_.realize(state_, SimTK::Stage::Instance);
        system_.project(state_, options_.constraintTolerance);
    } catch (const std::exception& e) {
        throw NumericalError("linearly implicit stepper at " + timeText(state_) + ": cannot satisfy the constraints: " + e.what());
    }
    SimTK::HandleEventsResults results;
    system_.handleEvents(state_, SimTK::Event::Cause::Initialization, SimTK::Array_<SimTK::EventId>(),
                         SimTK::HandleEventsOptions(options_.constraintTolerance), results);
    handleResults(results);
    state_.autoUpdateDiscreteVariables();
    system_.realize(state_, SimTK::Stage::Acceleration);
    ++evaluations_;
    system_.calcEventTriggerInfo(state_, triggerInfo_);
    triggers_ = state_.getEventTriggers();
    stepsAtInitialize_ = steps_;
    initialized_ = true;
}

// Events due exactly at `time` are handled at the start of the next call, as SimTK::TimeStepper
// does, so the state returned at `time` is the one the steps reached.
void LinearlyImplicitStepper::stepTo(double time) {
    if (!initialized_) throw Error("LinearlyImplicitStepper::stepTo(" + std::to_string(time) + ") before initialize()");
    while (!terminated_ && state_.getTime() < time) {
        if (handleDueScheduledEvents()) continue;
        const ScheduledTimes next = findScheduledTimes(system_, state_, false, false);
        advance(std::min({time, next.event, next.report}));
    }
}

// Handles the scheduled events and reports due now; true if any was.
bool LinearlyImplicitStepper::handleDueScheduledEvents() {
    const double t = state_.getTime();
    const ScheduledTimes due = findScheduledTimes(system_, state_, lastEventTime_ != t, lastReportTime_ != t);
    if (due.report <= t) {
        system_.realize(state_, SimTK::Stage::Acceleration);
        system_.reportEvents(state_, SimTK::Event::Cause::Scheduled, due.reportIds);
        lastReportTime_ = t;
        return true;
    }
    if (due.event > t) return false;
    SimTK::HandleEventsResults results;
    system_.handleEvents(state_, SimTK::Event::Cause::Scheduled, due.eventIds,
                         SimTK::HandleEventsOptions(options_.constraintTolerance), results);
    lastEventTime_ = t;
    ++scheduledEvents_;
    handleResults(results);
    return true;
}

// Equal steps no longer than h up to tStop, or up to the first step whose end triggers an event.
void LinearlyImplicitStepper::advance(double tStop) {
    const double t0 = state_.getTime();
    const double span = tStop - t0;
    const long n = std::max(1L, static_cast<long>(std::ceil(span / options_.stepSize * (1 - 1e-12))));
    for (long k = 1; k <= n && !terminated_; ++k) {
        const double h = (k == n ? tStop : t0 + span * static_cast<double>(k) / static_cast<double>(n)) - state_.getTime();
        if (takeStep(h)) return;
    }
}

// One step of size h (see the header). True if the step's end triggered an event (handled).
bool LinearlyImplicitStepper::takeStep(double h) {
    SimTK::Vector du;
    solveVelocityChange(h, du);
    const SimTK::Vector u = state_.getU() + du;
    const SimTK::Vector zNext = state_.getZ() + h * state_.getZDot();
    SimTK::Vector qdot;
    system_.getMatterSubsystem().multiplyByN(state_, false, u, qdot);
    const SimTK::Vector q = state_.getQ() + h * qdot;
    state_.updTime() += h;
    state_.updQ() = q;
    state_.updU() = u;
    state_.updZ() = zNext;
    projectStep();
    system_.realize(state_, SimTK::Stage::Acceleration);
    ++evaluations_;
    ++steps_;
    state_.autoUpdateDiscreteVariables();
    const SimTK::Array_<SimTK::EventId> triggered = findTriggeredEvents();
    if (triggered.empty()) {
        triggers_ = state_.getEventTriggers();
        return false;
    }
    triggeredEvents_ += static_cast<long>(triggered.size());
    SimTK::HandleEventsResults results;
    system_.handleEvents(state_, SimTK::Event::Cause::Triggered, triggered,
                         SimTK::HandleEventsOptions(options_.constraintTolerance), results);
    handleResults(results);
    return true;
}

namespace {

// Solves A x = b in place (A n x n column-major, overwritten by its LU factors; b becomes x) by
// Gaussian elimination with partial pivoting. False if A is singular. A hand-written loop: at
// the sizes of a hand (a few dozen mobilities) SimTK::Matrix's element access and FactorLU's
// copies cost more than the arithmetic.
bool solveInPlace(std::vector<double>& A, int n, std::vector<double>& b) {
    for (int k = 0; k < n; ++k) {
        int pivot = k;
        for (int r = k + 1; r < n; ++r)
            if (std::abs(A[r + n * k]) > std::abs(A[pivot + n * k])) pivot = r;
        if (A[pivot + n * k] == 0) return false;
        if (pivot != k) {
            for (int c = 0; c < n; ++c) std::swap(A[k + n * c], A[pivot + n * c]);
            std::swap(b[k], b[pivot]);
        }
        const double inverse = 1 / A[k + n * k];
        for (int r = k + 1; r < n; ++r) {
            const double factor = A[r + n * k] * inverse;
            if (factor == 0) continue;
            for (int c = k + 1; c < n; ++c) A[r + n * c] -= factor * A[k + n * c];
            b[r] -= factor * b[k];
        }
    }
    for (int k = n - 1; k >= 0; --k) {
        double sum = b[k];
        for (int c = k + 1; c < n; ++c) sum -= A[k + n * c] * b[c];
        b[k] = sum / A[k + n * k];
    }
    return true;
}

}  // namespace

// Onto the constraints, or with none only the quaternions normalized (System::project would
// realize and check the velocity level too: about 8 % of a step).
void LinearlyImplicitStepper::projectStep() {
    const SimTK::SimbodyMatterSubsystem& matter = system_.getMatterSubsystem();
    if (matter.getNumConstraints() == 0) {
        system_.realize(state_, SimTK::Stage::Time);
        matter.normalizeQuaternions(state_);
        return;
    }
    try {
        system_.project(state_, options_.constraintTolerance);
    } catch (const std::exception& e) {
        throw NumericalError("linearly implicit stepper at " + timeText(state_) + ": cannot project onto the constraints: " + e.what());
    }
    ++projections_;
}

// (M - h D - h^2 K) du = h (f + h K u) with f = M udot at the step's start.
void LinearlyImplicitStepper::solveVelocityChange(double h, SimTK::Vector& du) const {
    const SimTK::SimbodyMatterSubsystem& matter = system_.getMatterSubsystem();
    const int nu = state_.getNU();
    SimTK::Matrix M;
    matter.calcM(state_, M);
    SimTK::Vector f;
    matter.multiplyByM(state_, state_.getUDot(), f);
    SimTK::Matrix D(nu, nu, 0.0), K(nu, nu, 0.0);
    for (const ForceJacobianContributor* c : contributors_) c->addForceJacobians(state_, D, K);
    const double* m = M.getContiguousScalarData();
    const double* d = D.getContiguousScalarData();
    const double* k = K.getContiguousScalarData();
    const SimTK::Vector& u = state_.getU();
    std::vector<double> A(static_cast<std::size_t>(nu) * nu), x(static_cast<std::size_t>(nu));
    for (std::size_t i = 0; i < A.size(); ++i) A[i] = m[i] - h * d[i] - h * h * k[i];
    for (int i = 0; i < nu; ++i) {
        double Ku = 0;
        for (int j = 0; j < nu; ++j) Ku += k[i + nu * j] * u[j];
        x[i] = h * (f[i] + h * Ku);
    }
    holdLockedSpeeds(A, x);
    if (!solveInPlace(A, nu, x)) {
        throw NumericalError("linearly implicit stepper at " + timeText(state_) + ": the step's linear system is singular");
    }
    du.resize(nu);
    for (int i = 0; i < nu; ++i) {
        if (!std::isfinite(x[i])) {
            throw NumericalError("linearly implicit stepper at " + timeText(state_) + ": the step's velocity change is not finite");
        }
        du[i] = x[i];
    }
}

// A locked mobilizer's speeds (SimTK::MobilizedBody::lock) do not change: du = 0 there, and the
// other rows see no coupling to them. Their lock force is in f; it keeps the rest at rest.
void LinearlyImplicitStepper::holdLockedSpeeds(std::vector<double>& A, std::vector<double>& rhs) const {
    const SimTK::SimbodyMatterSubsystem& matter = system_.getMatterSubsystem();
    const int n = static_cast<int>(rhs.size());
    for (SimTK::MobilizedBodyIndex b(1); b < matter.getNumBodies(); ++b) {
        const SimTK::MobilizedBody& mobod = matter.getMobilizedBody(b);
        if (!mobod.isLocked(state_)) continue;
        const int first = mobod.getFirstUIndex(state_);
        for (int i = first; i < first + mobod.getNumU(state_); ++i) {
            for (int k = 0; k < n; ++k) A[i + n * k] = A[k + n * i] = 0;
            A[i + n * i] = 1;
            rhs[i] = 0;
        }
    }
}

// The events whose triggers changed sign over the last step, in a direction they ask for.
SimTK::Array_<SimTK::EventId> LinearlyImplicitStepper::findTriggeredEvents() const {
    SimTK::Array_<SimTK::EventId> events;
    const SimTK::Vector& now = state_.getEventTriggers();
    if (now.size() != triggers_.size()) return events;
    for (int i = 0; i < now.size(); ++i) {
        if (isCrossing(triggerInfo_[i], triggers_[i], now[i])) events.push_back(triggerInfo_[i].getEventId());
    }
    return events;
}

// After any handler: realize the (possibly changed) state again and take its triggers as the
// reference for the next step's crossings (an Instance-stage change may change their number).
void LinearlyImplicitStepper::handleResults(const SimTK::HandleEventsResults& results) {
    if (results.getExitStatus() == SimTK::HandleEventsResults::Failed) {
        throw NumericalError("event handler failed at " + timeText(state_) + ": " + results.getMessage());
    }
    if (results.getExitStatus() == SimTK::HandleEventsResults::ShouldTerminate) terminated_ = true;
    if (results.getLowestModifiedStage() >= SimTK::Stage::Report || !initialized_) return;
    system_.realize(state_, SimTK::Stage::Acceleration);
    ++evaluations_;
    system_.calcEventTriggerInfo(state_, triggerInfo_);
    triggers_ = state_.getEventTriggers();
}

IntegrationStatistics LinearlyImplicitStepper::getStatistics() const {
    IntegrationStatistics s;
    s.steps = steps_;
    s.rhsEvaluations = evaluations_;
    s.jacobianEvaluations = steps_;
    s.linearSolverSetups = steps_;
    s.projections = projections_;
    s.triggeredEvents = triggeredEvents_;
    s.scheduledEvents = scheduledEvents_;
    s.restarts = 0;  // a one-step method has no history to restart
    return s;
}

}  // namespace graspsim::integration
