#include "graspsim/integration/linearly_implicit_stepper.h"

#include "dense_output.h"
#include "n_matrix.h"
#include "scheduled_times.h"
#include "step_matrix.h"
#include "step_size_control.h"
#include "switch_localization.h"
#include "trigger_crossings.h"

#include "graspsim/error.h"
#include "graspsim/integration/fixed_step_too_long_error.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>

namespace graspsim::integration {

namespace {

void checkOptions(const LinearlyImplicitOptions& o) {
    const auto positive = [](double v) { return v > 0 && std::isfinite(v); };
    if (!positive(o.stepSize)) {
        throw InputError("step size: value " + std::to_string(o.stepSize) + " s is not accepted; use a finite number > 0");
    }
    if (o.order != 1 && o.order != 2) {
        throw InputError("LinearlyImplicitOptions.order: value " + std::to_string(o.order) + " is not accepted; use 1 or 2");
    }
    if (!(o.accuracy >= 0 && std::isfinite(o.accuracy)) || (o.accuracy > 0 && o.order != 2)) {
        throw InputError("LinearlyImplicitOptions.accuracy: value " + std::to_string(o.accuracy) +
                         " is not accepted; use 0 (fixed steps) or, with order 2, a finite number > 0");
    }
    for (double t : o.landingTimes) {
        if (!std::isfinite(t)) throw InputError("LinearlyImplicitOptions.landingTimes: a time is not finite");
    }
    if (!positive(o.constraintTolerance)) {
        throw InputError("LinearlyImplicitOptions.constraintTolerance: value " + std::to_string(o.constraintTolerance) +
                         " is not accepted; use a finite number > 0");
    }
}

std::string timeText(const SimTK::State& s) { return "t = " + std::to_string(s.getTime()) + " s"; }

}  // namespace

LinearlyImplicitStepper::LinearlyImplicitStepper(const SimTK::MultibodySystem& system,
                                                 std::vector<const ForceJacobianContributor*> contributors,
                                                 const LinearlyImplicitOptions& options)
    : system_(system), contributors_(std::move(contributors)), options_(options), n0_(std::make_unique<NMatrix>()),
      dense_(std::make_unique<DenseOutput>()), stepSizes_(std::make_unique<StepSizeControl>(options.stepSize)),
      switches_(std::make_unique<SwitchLocalization>(SwitchLocalization::findWindow(system, options.accuracy))) {
    checkOptions(options_);
    std::sort(options_.landingTimes.begin(), options_.landingTimes.end());
}

LinearlyImplicitStepper::~LinearlyImplicitStepper() = default;

// As Simbody's Integrator::initialize: onto the constraints first, then Initialization events,
// then the auto-update discrete variables.
void LinearlyImplicitStepper::initialize(const SimTK::State& initial) {
    state_ = initial;
    terminated_ = false;
    outputInterpolated_ = false;
    landOnEvents_ = true;
    eventHorizon_ = SimTK::Infinity;
    redo_ = false;
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
    dense_->initialize(state_);
    switches_->clear();
    stepsAtInitialize_ = steps_;
    massMatrixTime_ = -SimTK::Infinity;
    matrixStale_ = true;
    initialized_ = true;
}

// Events due exactly at `time` are handled at the start of the next call, as SimTK::TimeStepper
// does, so the state returned at `time` is the one the steps reached.
void LinearlyImplicitStepper::stepTo(double time) {
    if (!initialized_) throw Error("LinearlyImplicitStepper::stepTo(" + std::to_string(time) + ") before initialize()");
    if (interpolates()) return stepToInterpolating(time);
    while (!terminated_ && state_.getTime() < time) {
        if (handleDueScheduledEvents()) continue;
        const ScheduledTimes next = findScheduledTimes(system_, state_, false, false);
        advance(std::min({time, next.event, next.report}));
    }
}

// Dense output: the steps go on past reports and scheduled events (not past a landing time), and
// each is served on the state interpolated at its time, the next one first. A step that ends
// short of the next one becomes the output itself.
void LinearlyImplicitStepper::stepToInterpolating(double time) {
    while (!terminated_ && getState().getTime() < time) {
        if (handleDueScheduledEvents()) continue;
        const ScheduledTimes next = findScheduledTimes(system_, getState(), false, false);
        const double target = std::min({time, next.event, next.report});
        if (state_.getTime() < target) {
            eventHorizon_ = target;
            const bool triggered = takeControlledStep(findStop(target, next.event));
            eventHorizon_ = SimTK::Infinity;
            outputInterpolated_ = false;  // the integrator's state, until showAt() says otherwise
            if (triggered || state_.getTime() < target) continue;
        }
        showAt(target);
    }
}

// The output at t, at or before the integrator's time: the integrator's state, or the one
// interpolated in its last step (with the step's discrete variables), on the constraints and
// realized through Acceleration as after a step.
void LinearlyImplicitStepper::showAt(double t) {
    if (t >= state_.getTime()) {
        outputInterpolated_ = false;
        return;
    }
    SimTK::State& shown = dense_->interpolate(state_, t);
    project(shown);
    system_.realize(shown, SimTK::Stage::Acceleration);
    ++evaluations_;
    outputInterpolated_ = true;
}

const SimTK::State& LinearlyImplicitStepper::getState() const { return outputInterpolated_ ? dense_->getState() : state_; }

// Where the next step must end at the latest: a landing time, a scheduled event to land on (see
// landOnEvents_), or `target` (the next output) when it is at least half a step away. Interpolating
// costs an evaluation, about half a step; landing on an output half a step or more away costs less.
double LinearlyImplicitStepper::findStop(double target, double nextEvent) const {
    const double t = state_.getTime();
    double stop = findNextLanding(t);
    if (landOnEvents_) stop = std::min(stop, nextEvent);
    if (target - t >= 0.5 * stepSizes_->getProposal()) stop = std::min(stop, target);
    return stop;
}

double LinearlyImplicitStepper::findNextLanding(double t) const {
    const auto next = std::upper_bound(options_.landingTimes.begin(), options_.landingTimes.end(), t);
    return next == options_.landingTimes.end() ? SimTK::Infinity : *next;
}

// Handles the scheduled events and reports due now; true if any was.
bool LinearlyImplicitStepper::handleDueScheduledEvents() {
    SimTK::HandleEventsResults results;
    SimTK::State& now = outputInterpolated_ ? dense_->updState() : state_;
    // Realized through Report, a change of a Report-stage variable shows in the results (Simbody
    // compares the versions of the stages realized before the handlers).
    if (interpolates()) system_.realize(now, SimTK::Stage::Report);
    const DueScheduled done =
        handleDueScheduled(system_, now, options_.constraintTolerance, lastEventTime_, lastReportTime_, results);
    if (done != DueScheduled::Handled) return done == DueScheduled::Reported;
    ++scheduledEvents_;
    // The steps land on the next scheduled event unless this one changed nothing (see landOnEvents_).
    landOnEvents_ = results.getLowestModifiedStage() != SimTK::Stage::Infinity;
    if (outputInterpolated_ && handleInterpolatedEvents(results)) return true;
    handleResults(results);
    return true;
}

// After handlers at an interpolated instant: a change above Stage::Report (none) or of Report-stage
// variables only leaves everything the integrator computed valid, so the variables go on to its
// state ahead (true); a lower change makes the handled state the integrator's own, the rest of
// the step dropped (a one-step method keeps no history), and handleResults() goes on (false).
bool LinearlyImplicitStepper::handleInterpolatedEvents(const SimTK::HandleEventsResults& results) {
    if (dense_->handOn(results, state_)) return true;
    state_ = dense_->getState();
    outputInterpolated_ = false;
    matrixStale_ = true;
    return false;
}

// Up to tStop, or up to the first step whose end triggers an event: equal steps no longer than
// h, or with error control steps chosen from the error estimate, never longer than h.
void LinearlyImplicitStepper::advance(double tStop) {
    if (options_.accuracy > 0) {
        advanceControlled(tStop);
        return;
    }
    const double t0 = state_.getTime();
    const double span = tStop - t0;
    const long n = std::max(1L, static_cast<long>(std::ceil(span / options_.stepSize * (1 - 1e-12))));
    for (long k = 1; k <= n && !terminated_; ++k) {
        const double h = (k == n ? tStop : t0 + span * static_cast<double>(k) / static_cast<double>(n)) - state_.getTime();
        double error = 0;
        if (takeStep(h, error)) return;
    }
}

// A step whose error estimate exceeds the accuracy is taken again from its start, shorter; the
// steps are chosen by StepSizeControl, never longer than h.
void LinearlyImplicitStepper::advanceControlled(double tStop) {
    while (!terminated_ && state_.getTime() < tStop) {
        if (takeControlledStep(tStop)) return;
    }
}

// One accepted step toward tStop (rejected ones taken again); true if its end triggered an event.
// A step past eventHorizon_ whose end triggers one is taken again, ending on the horizon; one that
// loses an active term is taken again shorter (switch_localization.h). After a landing time (a
// jump in the inputs) the steps start again from the localization window, as after a switch.
bool LinearlyImplicitStepper::takeControlledStep(double tStop) {
    for (;;) {
        const double t = state_.getTime(), remaining = tStop - t;
        const double h = switches_->limitStep(t, stepSizes_->findStepToStop(remaining));
        const SimTK::Vector q = state_.getQ(), u = state_.getU(), z = state_.getZ();
        if (interpolates()) dense_->captureStart(state_);
        double error = 0;
        if (takeStep(h, error)) return true;
        if (redo_ || switchCrossed_) {
            if (redo_) tStop = eventHorizon_;
            const bool crossed = switchCrossed_;
            rejectedSteps_ += crossed ? 1 : 0;
            redo_ = switchCrossed_ = false;
            restoreStepStart(t, q, u, z);
            if (crossed) switches_->setEstimate(estimateSwitchTime(t, h));
            continue;
        }
        if (stepSizes_->acceptStep(h, error)) {
            if (state_.getTime() >= findNextLanding(t)) stepSizes_->restart(switches_->getWindow());
            return false;
        }
        matrixStale_ = true;
        ++rejectedSteps_;
        restoreStepStart(t, q, u, z);
    }
}

void LinearlyImplicitStepper::restoreStepStart(double t, const SimTK::Vector& q, const SimTK::Vector& u,
                                               const SimTK::Vector& z) {
    setState(t, q, u, z);
    system_.realize(state_, SimTK::Stage::Acceleration);
    ++evaluations_;
}

namespace {

// An active-set term: its contributor's place in the list (high 32 bits) and the contributor's own
// identifier (low 32 bits).
std::int64_t tagTerm(std::size_t contributor, int id) {
    return static_cast<std::int64_t>(contributor) << 32 | static_cast<std::int64_t>(static_cast<std::uint32_t>(id));
}
std::size_t findTermContributor(std::int64_t term) { return static_cast<std::size_t>(term >> 32); }
int findTermId(std::int64_t term) { return static_cast<int>(static_cast<std::uint32_t>(term & 0xffffffff)); }

// Adds the wall time of its scope to `seconds` (the linear algebra's share, in the statistics).
class ScopeClock {
public:
    explicit ScopeClock(double& seconds) : seconds_(seconds), start_(std::chrono::steady_clock::now()) {}
    ~ScopeClock() { seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count(); }
    ScopeClock(const ScopeClock&) = delete;
    ScopeClock& operator=(const ScopeClock&) = delete;

private:
    double& seconds_;
    std::chrono::steady_clock::time_point start_;
};

bool isFinite(const std::vector<double>& v) {
    return std::all_of(v.begin(), v.end(), [](double x) { return std::isfinite(x); });
}
bool isFinite(const SimTK::Vector& v) {
    for (int i = 0; i < v.size(); ++i) if (!std::isfinite(v[i])) return false;
    return true;
}

std::vector<double> toStd(const SimTK::Vector& v) { return std::vector<double>(&v[0], &v[0] + v.size()); }
SimTK::Vector toSimTK(const std::vector<double>& v) { return SimTK::Vector(static_cast<int>(v.size()), v.data()); }

// a + s b
std::vector<double> addScaled(const std::vector<double>& a, double s, const std::vector<double>& b) {
    std::vector<double> out(a);
    for (std::size_t i = 0; i < out.size(); ++i) out[i] += s * b[i];
    return out;
}

}  // namespace

// One step of size h (see the header); `error` receives its error estimate (weighted RMS
// against the accuracy, at fixed steps against the state's own scale; 0 for Euler). At fixed
// steps a ROS2 step whose estimate exceeds kUntrustedStepEstimate throws FixedStepTooLongError
// (see the header). True if the step's end triggered an event (handled); a
// step about to be rejected (error > 1 under error control) is not looked at for events, one that
// loses an active term sets switchCrossed_, and one that ends past eventHorizon_ and triggers sets
// redo_ instead (the caller takes them again).
bool LinearlyImplicitStepper::takeStep(double h, double& error) {
    const double t0 = state_.getTime();
    error = options_.order == 2 ? takeRosenbrockStep(h) : (takeEulerStep(h), 0.0);
    if (!std::isfinite(error)) {
        // A state gone non-finite (a rate that blew up within the step) is the largest error there
        // is: the step is taken again shorter, and is never realized (Simbody throws on a NaN inertia).
        error = std::numeric_limits<double>::infinity();
        if (options_.accuracy > 0 && h > StepSizeControl::kMinStepSize) return false;
        if (options_.accuracy > 0) {
            char text[160];
            std::snprintf(text, sizeof text, "linearly implicit stepper: the state is not finite after a step of %g s from t = %.9g s, "
                          "the shortest step it takes", h, t0);
            throw NumericalError(text);
        }
    }
    if (options_.accuracy == 0 && error > kUntrustedStepEstimate) throw FixedStepTooLongError(h, t0, error);
    project(state_);
    system_.realize(state_, SimTK::Stage::Acceleration);
    ++evaluations_;
    if (options_.accuracy > 0 && error > 1 && h > StepSizeControl::kMinStepSize) return false;
    if (options_.accuracy > 0) {
        findActiveSet(endSet_);
        const std::vector<std::int64_t> lost = SwitchLocalization::findLostTerms(activeSet_, endSet_);
        switchCrossed_ = !lost.empty() && switches_->crossed(t0, h);
        if (switchCrossed_) {
            findLostMargins(lost);
            return false;
        }
    }
    const SimTK::Array_<SimTK::EventId> triggered = findTriggeredEvents(triggerInfo_, triggers_, state_.getEventTriggers());
    if (!triggered.empty() && state_.getTime() > eventHorizon_) {
        redo_ = true;
        return false;
    }
    ++steps_;
    state_.autoUpdateDiscreteVariables();
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

// (M - h D - h^2 K) du = h (f + h K u), f = M udot; u' = u + du, q' = q + h N u', z' = z + h zdot.
void LinearlyImplicitStepper::takeEulerStep(double h) {
    std::unique_ptr<const StepMatrix> built;
    {
        const ScopeClock clock(linearSolveSeconds_);
        built = std::make_unique<const StepMatrix>(system_.getMatterSubsystem(), contributors_, state_, h);
        ++matrixBuilds_;
    }
    const StepMatrix& A = *built;
    const std::vector<double> u = toStd(state_.getU());
    std::vector<double> du = addScaled(A.multiplyByM(toStd(state_.getUDot())), 1, A.multiplyByGK(u, h));
    solve(A, du);
    const SimTK::Vector uNext = toSimTK(addScaled(u, h, du));
    const SimTK::Vector zNext = state_.getZ() + h * state_.getZDot();
    SimTK::Vector qdot;
    system_.getMatterSubsystem().multiplyByN(state_, false, uNext, qdot);
    const SimTK::Vector qNext = state_.getQ() + h * qdot;
    setState(state_.getTime() + h, qNext, uNext, zNext);
}

// ROS2 (Verwer et al. 1999; L-stable, second order for any approximate Jacobian), on y = (x, u)
// with x' = u (x a mobility-space displacement, q = q0 + N(q0) x), u' = M^-1 f(x, u) and the
// Jacobian [[0, I], [M^-1 K, M^-1 D]]. Each stage solves (I - g J) (a; b) = (r1; r2), g = gamma h,
// which reduces to (M - g D - g^2 K) b = M r2 + g K r1, a = r1 + g b:
//   stage 1: r = F(y0);                 stage 2: r = F(y0 + h k1) - 2 k1;
//   y1 = y0 + h (3/2 k1 + 1/2 k2).
// Z variables get the explicit two-stage (Heun) form of the same tableau. A step that ends on a
// landing time evaluates its second stage just before it: the inputs' jump there belongs to the
// next step (evaluated at the landing time itself, its force at the step's end was on for half of
// the step's weight, the load in effect starting half a step early).
double LinearlyImplicitStepper::takeRosenbrockStep(double h) {
    const double gamma = 1 + 1 / std::sqrt(2.0), g = gamma * h;
    const SimTK::SimbodyMatterSubsystem& matter = system_.getMatterSubsystem();
    const StepMatrix& A = findStepMatrix(g);
    const double t0 = state_.getTime();
    const SimTK::Vector q0 = state_.getQ(), z0 = state_.getZ(), zdot0 = state_.getZDot();
    const std::vector<double> u0 = toStd(state_.getU());
    std::vector<double> b1 = addScaled(A.multiplyByM(toStd(state_.getUDot())), 1, A.multiplyByGK(u0, g));
    solve(A, b1);
    const std::vector<double> a1 = addScaled(u0, g, b1);
    SimTK::Vector qdot1, qdot2;
    matter.multiplyByN(state_, false, toSimTK(a1), qdot1);  // N(q0) a1
    n0_->capture(matter, state_);                           // N(q0) for a2, after stage 2 moved the State
    const double landing = findNextLanding(t0), t1 = t0 + h;
    const bool endsOnLanding = landing <= t1 && t1 - landing <= 1e-12 * std::max(1.0, std::abs(t1));
    if (!isFinite(a1) || !isFinite(b1) || !isFinite(zdot0)) {
        return std::numeric_limits<double>::infinity();  // the stage state would not be finite: no step to realize
    }
    setState(endsOnLanding ? std::nextafter(landing, t0) : t1, q0 + h * qdot1, toSimTK(addScaled(u0, h, b1)), z0 + h * zdot0);
    system_.realize(state_, SimTK::Stage::Acceleration);
    ++evaluations_;
    const SimTK::Vector zdot2 = state_.getZDot();
    const std::vector<double> r1 = addScaled(addScaled(u0, h, b1), -2, a1);
    std::vector<double> b2 = addScaled(A.multiplyByM(addScaled(toStd(state_.getUDot()), -2, b1)), 1, A.multiplyByGK(r1, g));
    solve(A, b2);
    const std::vector<double> a2 = addScaled(r1, g, b2);
    n0_->multiply(a2, qdot2);
    const SimTK::Vector uNext = toSimTK(addScaled(addScaled(u0, 1.5 * h, b1), 0.5 * h, b2));
    setState(t0 + h, q0 + (1.5 * h) * qdot1 + (0.5 * h) * qdot2, uNext, z0 + (0.5 * h) * (zdot0 + zdot2));
    return calcErrorNorm(A, h, a1, a2, b1, b2, u0, options_.accuracy > 0 ? options_.accuracy : 1.0);
}

// The step's matrix: the one kept from an earlier step while nothing says it is out of date (see
// the header's kMatrixAge), else a new one (with M kept for kMassMatrixAge). At fixed steps no
// error estimate watches a stale matrix, so each step builds its own.
const StepMatrix& LinearlyImplicitStepper::findStepMatrix(double g) {
    const ScopeClock clock(linearSolveSeconds_);
    findActiveSet(activeSet_);
    const double t = state_.getTime();
    const bool keep = options_.accuracy > 0 && matrix_ && !matrixStale_ && activeSet_ == matrixActiveSet_ &&
                      t - matrixTime_ < kMatrixAge && g < kMatrixStepRatio * matrix_->getFactor() &&
                      matrix_->getFactor() < kMatrixStepRatio * g;
    if (keep) return *matrix_;
    const bool freshM = !(t - massMatrixTime_ < kMassMatrixAge);
    matrix_ = std::make_unique<StepMatrix>(system_.getMatterSubsystem(), contributors_, state_, g,
                                           freshM ? std::vector<double>() : massMatrix_);
    if (freshM) {
        massMatrix_ = matrix_->getMassMatrix();
        massMatrixTime_ = t;
    }
    matrixTime_ = t;
    matrixActiveSet_ = activeSet_;  // activeSet_ stays the step start's, for findLostTerms
    matrixStale_ = false;
    ++matrixBuilds_;
    return *matrix_;
}

// The margins of the lost terms at the step's end (state_).
void LinearlyImplicitStepper::findLostMargins(const std::vector<std::int64_t>& lost) {
    lostMargins_.clear();
    for (std::int64_t term : lost) lostMargins_.emplace_back(term, findTermMargin(term));
}

double LinearlyImplicitStepper::findTermMargin(std::int64_t term) const {
    return contributors_[findTermContributor(term)]->findTermMargin(state_, findTermId(term));
}

// With state_ back at the step's start t (h long): where the first lost term's margin, linear
// between the two ends, reached zero; NaN if a lost term has no margin, or one that does not go
// from positive to at most zero (then the bracket is bisected).
double LinearlyImplicitStepper::estimateSwitchTime(double t, double h) const {
    double first = 1;
    for (const auto& [term, atEnd] : lostMargins_) {
        const double atStart = findTermMargin(term);
        if (!(atStart > 0 && atEnd <= 0)) return SimTK::NaN;
        first = std::min(first, atStart / (atStart - atEnd));
    }
    return lostMargins_.empty() ? SimTK::NaN : t + first * h;
}

void LinearlyImplicitStepper::findActiveSet(std::vector<std::int64_t>& set) const {
    set.clear();
    for (std::size_t k = 0; k < contributors_.size(); ++k) {
        contributorTerms_.clear();
        contributors_[k]->appendActiveSet(state_, contributorTerms_);
        for (int id : contributorTerms_) set.push_back(tagTerm(k, id));
    }
}

void LinearlyImplicitStepper::solve(const StepMatrix& A, std::vector<double>& b) const {
    const ScopeClock clock(linearSolveSeconds_);
    A.solve(b);
}

// The difference from the embedded first-order solution y0 + h k1, E = h (k1 + k2) / 2, filtered
// by W^-1 = (I - g J)^-1 as Shampine filters stiff estimates (unfiltered, the stiff joint modes'
// share of E rejected about every other step at accuracy 1e-3 on the ball clutch), in the
// weighted RMS norm of Simbody's accuracy convention: each entry over accuracy (1 + |y|), with
// the displacement x for q (its weight 1) and u. At fixed steps `accuracy` is 1: the estimate
// against the state's own scale, for the guard in takeStep().
double LinearlyImplicitStepper::calcErrorNorm(const StepMatrix& A, double h, const std::vector<double>& a1,
                                              const std::vector<double>& a2, const std::vector<double>& b1,
                                              const std::vector<double>& b2, const std::vector<double>& u0,
                                              double accuracy) const {
    const double g = (1 + 1 / std::sqrt(2.0)) * h;
    const std::size_t n = u0.size();
    std::vector<double> ex(n), eu(n);
    for (std::size_t i = 0; i < n; ++i) {
        ex[i] = 0.5 * h * (a1[i] + a2[i]);
        eu[i] = 0.5 * h * (b1[i] + b2[i]);
    }
    std::vector<double> fu = addScaled(A.multiplyByM(eu), 1, A.multiplyByGK(ex, g));
    solve(A, fu);
    const std::vector<double> fx = addScaled(ex, g, fu);
    double sum = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double x = fx[i] / accuracy, u = fu[i] / (accuracy * (1 + std::abs(u0[i])));
        sum += x * x + u * u;
    }
    return n > 0 ? std::sqrt(sum / static_cast<double>(2 * n)) : 0.0;
}

// Onto the constraints, or with none only the quaternions normalized (System::project would
// realize and check the velocity level too: about 8 % of a step).
void LinearlyImplicitStepper::project(SimTK::State& state) {
    const SimTK::SimbodyMatterSubsystem& matter = system_.getMatterSubsystem();
    if (matter.getNumConstraints() == 0) {
        system_.realize(state, SimTK::Stage::Time);
        matter.normalizeQuaternions(state);
        return;
    }
    try {
        system_.project(state, options_.constraintTolerance);
    } catch (const std::exception& e) {
        throw NumericalError("linearly implicit stepper at " + timeText(state) + ": cannot project onto the constraints: " + e.what());
    }
    ++projections_;
}

void LinearlyImplicitStepper::setState(double t, const SimTK::Vector& q, const SimTK::Vector& u, const SimTK::Vector& z) {
    state_.updTime() = t;
    state_.updQ() = q;
    state_.updU() = u;
    state_.updZ() = z;
}

// After any handler: realize the (possibly changed) state again and take its triggers as the
// reference for the next step's crossings (an Instance-stage change may change their number).
void LinearlyImplicitStepper::handleResults(const SimTK::HandleEventsResults& results) {
    dense_->markChanged();  // handlers worked on state_
    if (results.getExitStatus() == SimTK::HandleEventsResults::Failed) {
        throw NumericalError("event handler failed at " + timeText(state_) + ": " + results.getMessage());
    }
    if (results.getExitStatus() == SimTK::HandleEventsResults::ShouldTerminate) terminated_ = true;
    if (results.getLowestModifiedStage() >= SimTK::Stage::Report || !initialized_) return;
    if (results.getLowestModifiedStage() <= SimTK::Stage::Instance) matrixStale_ = true;  // pairs, locks
    system_.realize(state_, SimTK::Stage::Acceleration);
    ++evaluations_;
    system_.calcEventTriggerInfo(state_, triggerInfo_);
    triggers_ = state_.getEventTriggers();
}

IntegrationStatistics LinearlyImplicitStepper::getStatistics() const {
    IntegrationStatistics s;
    s.steps = steps_;
    s.errorTestFailures = rejectedSteps_;
    s.rhsEvaluations = evaluations_;
    s.jacobianEvaluations = matrixBuilds_;
    s.linearSolverSetups = matrixBuilds_;
    s.projections = projections_;
    s.triggeredEvents = triggeredEvents_;
    s.scheduledEvents = scheduledEvents_;
    s.restarts = 0;  // a one-step method has no history to restart
    s.newtonIterations = 0;
    s.linearSolveSeconds = linearSolveSeconds_;
    return s;
}

}  // namespace graspsim::integration
