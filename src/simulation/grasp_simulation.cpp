#include "graspsim/simulation/grasp_simulation.h"


#include "graspsim/error.h"
#include "graspsim/simulation/contact_grasp_quality.h"
#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/simulation/rigid_stepping.h"
#include "graspsim/simulation/scene_stepper.h"
#include "graspsim/simulation/stall_guard.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <memory>
#include <set>

namespace graspsim::simulation {

namespace {

using Clock = std::chrono::steady_clock;

// Output times, plus every instant where the inputs jump (release, perturbation on and off) so
// that no integration step straddles a discontinuity.
std::vector<double> makeSampleTimes(const GraspExperiment& experiment, double duration) {
    const GraspScene& scene = experiment.getScene();
    std::set<double> times;
    const double dt = scene.getScenario().simulation.outputInterval;
    const long n = static_cast<long>(std::floor(duration / dt + 1e-9));
    for (long k = 1; k <= n; ++k) times.insert(k * dt);
    times.insert(duration);
    const auto addInside = [&](double t) { if (t > 0 && t < duration) times.insert(t); };
    addInside(scene.getReleaseTime());
    addInside(scene.getScenario().simulation.settleTime);
    if (const PerturbationForce* p = experiment.getLoads().getPerturbation()) {
        addInside(p->getStartTime());
        addInside(p->getEndTime());
    }
    return {times.begin(), times.end()};
}

class Recorder {
public:
    Recorder(const GraspExperiment& experiment, SimulationResult& result)
        : scene_(experiment.getScene()), approximation_(experiment.getApproximation()),
          grasp_(experiment.findSwitch()), result_(result) {
        const GraspScene& scene = experiment.getScene();
        result_.jointNames = scene.getModel().getJointNames();
        for (const std::string& j : result_.jointNames) jointQ_.push_back(scene.getModel().getJointQIndex(j));
        qualityOptions_ = makeQualityOptions(scene.getContactParameters());
    }

    void record(const SimTK::State& s) {
        scene_.getSystem().realize(s, SimTK::Stage::Velocity);
        TrajectorySample sample;
        sample.time = s.getTime();
        const SimTK::Transform& X_GO = scene_.getObject().getBodyTransform(s);
        sample.p_GO = X_GO.p();
        sample.q_GO = X_GO.R().convertRotationToQuaternion();
        for (const SimTK::QIndex q : jointQ_) sample.jointAngles.push_back(s.getQ()[q]);
        ContactSample contacts{s.getTime(), scene_.findContactReports(s)};
        if (grasp_ && grasp_->isEngaged(s)) {
            // No contacts are solved while engaged: record the estimate the release test uses.
            sample.graspQuality = grasp_->calcEngagedQuality(s);
            const double q = sample.graspQuality;
            double& lowest = result_.summary.minEngagedGraspQuality;
            lowest = engagedSamples_++ == 0 ? q : std::min(lowest, q);
        } else {
            sample.graspQuality = calcContactGraspQuality(contacts.contacts, X_GO, qualityOptions_);
        }
        if (approximation_) {
            if (auto constraint = findConstraintSample(approximation_->getContext(), s)) result_.constraint.push_back(*constraint);
        }
        result_.summary.maxGraspQuality = std::max(result_.summary.maxGraspQuality, sample.graspQuality);
        result_.trajectory.push_back(std::move(sample));
        for (const auto& c : contacts.contacts) result_.summary.maxPenetration = std::max(result_.summary.maxPenetration, c.depth);
        result_.contacts.push_back(std::move(contacts));
    }

private:
    const GraspScene& scene_;
    const GraspApproximation* approximation_;  // approx mode only
    const GraspSwitch* grasp_;                 // approx mode only
    SimulationResult& result_;
    grasp::QualityOptions qualityOptions_;  // box friction cone, smallest singular value
    std::vector<SimTK::QIndex> jointQ_;     // per joint name, looked up once: a sample is taken every 10 ms
    long engagedSamples_ = 0;
};

void checkFinite(const SimTK::State& s, const std::string& lastEvent) {
    const auto finite = [](const SimTK::Vector& v) {
        for (int k = 0; k < v.size(); ++k) if (!std::isfinite(v[k])) return false;
        return true;
    };
    if (finite(s.getQ()) && finite(s.getU())) return;
    throw NumericalError("non-finite state at t = " + std::to_string(s.getTime()) + " s (last event: " + lastEvent + ")");
}

// The phases of a run the timer tells apart, in the order a run goes through them.
enum class RunPhase {
    Held,             // the object held at its initial pose
    FullContact,      // from its release to the first engagement
    FirstEngagement,  // the approximation's first engagement
    AfterEngagement   // after its first release
};
constexpr int kRunPhases = 4;
constexpr int toIndex(RunPhase phase) { return static_cast<int>(phase); }

// Wall time and integrator steps per phase of the run, split at output samples.
class PhaseTimer {
public:
    PhaseTimer(const GraspScene& scene, const GraspSwitch* grasp) : scene_(scene), grasp_(grasp) {}

    void mark(const SimTK::State& s, long steps) {
        const double now = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
        const long taken = steps - lastSteps_;
        seconds_[toIndex(phase_)] += now - lastWall_;
        simSeconds_[toIndex(phase_)] += s.getTime() - lastTime_;
        steps_[toIndex(phase_)] += taken;
        lastTime_ = s.getTime();
        totalSteps_ += taken;
        lastWall_ = now;
        lastSteps_ = steps;
        phase_ = std::max(phase_, findPhase(s));
    }
    /// After the integrator was initialized again: new step-count baseline, and the new phase.
    void rebase(const SimTK::State& s, long steps) {
        lastSteps_ = steps;
        phase_ = std::max(phase_, findPhase(s));
    }
    long getTotalSteps() const { return totalSteps_; }
    double findUsPerStep(RunPhase phase) const {
        const int k = toIndex(phase);
        return steps_[k] > 0 ? 1e6 * seconds_[k] / steps_[k] : 0;
    }
    /// Wall-clock seconds per simulated second of `phase`.
    double findWallPerSimSecond(RunPhase phase) const {
        const int k = toIndex(phase);
        return simSeconds_[k] > 0 ? seconds_[k] / simSeconds_[k] : 0;
    }
    long getSteps(RunPhase phase) const { return steps_[toIndex(phase)]; }

private:
    RunPhase findPhase(const SimTK::State& s) const {
        if (scene_.isObjectHeld(s)) return RunPhase::Held;
        if (!grasp_ || grasp_->getEvents(s).empty()) return RunPhase::FullContact;
        const auto& events = grasp_->getEvents(s);
        const bool released = std::any_of(events.begin(), events.end(), [](const GraspEvent& e) { return e.kind == GraspEventKind::Release; });
        return grasp_->isEngaged(s) && !released ? RunPhase::FirstEngagement : RunPhase::AfterEngagement;  // detach events (multi) keep the first engagement
    }

    const GraspScene& scene_;
    const GraspSwitch* grasp_;  // approx mode only
    RunPhase phase_ = RunPhase::Held;
    double lastWall_ = std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
    long lastSteps_ = 0, totalSteps_ = 0;
    double lastTime_ = 0;
    double seconds_[kRunPhases] = {0, 0, 0, 0};
    double simSeconds_[kRunPhases] = {0, 0, 0, 0};
    long steps_[kRunPhases] = {0, 0, 0, 0};
};

// Releasing the object is an Instance-stage change: each kind of stepper restarts its own way.
void releaseObject(const GraspScene& scene, integration::Stepper& stepper) {
    SimTK::State released = stepper.getState();
    scene.releaseObject(released);
    stepper.initialize(released);
}
void releaseObject(const GraspScene&, RigidStepper& stepper) { stepper.releaseObject(); }
long countSteps(const integration::Stepper& stepper) { return stepper.getNumStepsTaken(); }
long countSteps(const RigidStepper& stepper) { return stepper.getNumSteps(); }

// Steps from sample to sample, releasing the object on time; `lastEvent` says what happened last.
// AnyStepper: an integration::Stepper (CPodes, CVODE) or the rigid model's RigidStepper.
template <class AnyStepper>
void stepThroughSamples(const GraspExperiment& experiment, AnyStepper& stepper, Recorder& recorder, PhaseTimer& phases,
                        double duration, const ProgressCallback& progress, const SampleObserver& observer,
                        std::string& lastEvent) {
    const GraspScene& scene = experiment.getScene();
    for (double t : makeSampleTimes(experiment, duration)) {
        const double from = stepper.getState().getTime();
        const long stepsBefore = countSteps(stepper);
        stepper.stepTo(t);
        checkNotStalled("simulation", from, stepper.getState().getTime(), countSteps(stepper) - stepsBefore);
        checkFinite(stepper.getState(), lastEvent);
        phases.mark(stepper.getState(), countSteps(stepper));
        if (std::abs(t - scene.getReleaseTime()) < 1e-12) {
            releaseObject(scene, stepper);
            phases.rebase(stepper.getState(), countSteps(stepper));  // a restart resets the step count
            lastEvent = "object released at t = " + std::to_string(t) + " s";
        }
        recorder.record(stepper.getState());
        if (observer) observer(experiment, stepper.getState());
        if (progress) progress(t, duration);
    }
}

SimulationSummary makeSummaryHeader(const scenario::Scenario& scenario, const SimulationOptions& options, double duration) {
    SimulationSummary summary;
    summary.scenario = scenario.name;
    summary.contact = options.contact;
    summary.mode = options.mode;
    summary.perturbation = options.perturbation;
    summary.settleTime = std::min(scenario.simulation.settleTime, duration);
    if (options.mode == SimulationMode::Approx) summary.constraint = options.approx.constraint;
    return summary;
}

// Steps are counted by the phase timer over the whole run: the release's initialize() restarts
// the integrator's own count, which would leave the held phase's steps out.
void summarizeCost(const GraspScene& scene, const PhaseTimer& timer, double ikSeconds, SimulationSummary& summary) {
    summary.steps = timer.getTotalSteps();
    summary.ikSolves = scene.getIkTiming().solves;
    const double perStep = summary.steps > 0 ? 1e6 / static_cast<double>(summary.steps) : 0;
    summary.meanStepUs = summary.wallTime * perStep;
    summary.ikUsPerStep = ikSeconds * perStep;
    summary.dynamicsUsPerStep = (summary.wallTime - ikSeconds) * perStep;
}

void summarizeSwitch(const GraspSwitch* grasp, const PhaseTimer& timer, const SimTK::State& last, SimulationResult& result) {
    SimulationSummary& summary = result.summary;
    summary.fullStepUs = timer.findUsPerStep(RunPhase::FullContact);
    summary.approxStepUs = timer.findUsPerStep(RunPhase::FirstEngagement);
    summary.fullWallPerSimSecond = timer.findWallPerSimSecond(RunPhase::FullContact);
    summary.approxWallPerSimSecond = timer.findWallPerSimSecond(RunPhase::FirstEngagement);
    summary.fullSteps = timer.getSteps(RunPhase::FullContact);
    summary.approxSteps = timer.getSteps(RunPhase::FirstEngagement);
    if (!grasp) return;
    result.events = grasp->getEvents(last);
    if (summary.complete) summary.engageObstacleAtEnd = grasp->findEngageObstacle(last);
    summary.qThreshold = grasp->getQualityThreshold(last);
    summary.qMinimum = grasp->getQualityMinimum(last);
    const PenetrationStats& penetration = grasp->getTracker(last).getPenetration();
    summary.engagedPenetrationAtEngage = penetration.atEngage;
    summary.maxEngagedPenetration = penetration.maxWhileEngaged;
    summary.maxEngagedPenetrationGrowth = penetration.maxGrowth;
    result.replacedPairs = penetration.replacedPairs;
    for (const GraspEvent& e : result.events) summary.maxReleaseVelocityJump = std::max(summary.maxReleaseVelocityJump, e.velocityJump);
    if (result.events.empty()) return;
    summary.engaged = true;
    summary.engageTime = result.events.front().time;
    summary.qAtEngage = result.events.front().quality;
    const auto release = std::find_if(result.events.begin(), result.events.end(), [](const GraspEvent& e) { return e.kind == GraspEventKind::Release; });
    if (release != result.events.end()) summary.releaseTime = release->time;
}


// Held: every goal's fingertip still within the tolerance of its goal point on the object.
void summarizeGrip(const GraspScene& scene, const SimTK::State& s, SimulationSummary& summary) {
    // After a numerical failure the last state may hold NaNs, which Simbody refuses to realize;
    // such a run is not held anyway.
    if (!summary.complete) return;
    summary.maxFingertipGoalDistance = scene.findMaxFingertipGoalDistance(s);
    summary.held = summary.maxFingertipGoalDistance <= scene.getScenario().simulation.heldTolerance;
}

void summarizeDrift(const SimulationResult& result, SimulationSummary& summary) {
    const auto settled = std::find_if(result.trajectory.begin(), result.trajectory.end(),
                                      [&](const TrajectorySample& t) { return t.time >= summary.settleTime - 1e-12; });
    if (settled == result.trajectory.end()) return;
    summary.objectDisplacement = (result.trajectory.back().p_GO - settled->p_GO).norm();
}

void summarizeRun(const GraspScene& scene, const GraspSwitch* grasp, const PhaseTimer& phases, double ikSeconds,
                  const SimTK::State& last, SimulationResult& result) {
    SimulationSummary& summary = result.summary;
    summary.simTime = last.getTime();
    summarizeCost(scene, phases, ikSeconds, summary);
    summarizeDrift(result, summary);
    summarizeGrip(scene, last, summary);
    summarizeSwitch(grasp, phases, last, result);
}

// Runs `scene` on `stepper` (an integration::Stepper or the rigid model's RigidStepper) from its
// initial state to `duration`, filling `result` except the integrator's name and statistics.
// `failureVerb` says what failed when the stepper throws something other than a NumericalError.
template <class AnyStepper>
void runScene(GraspExperiment& experiment, AnyStepper& stepper, double duration, const char* failureVerb,
              const ProgressCallback& progress, const SampleObserver& observer, SimulationResult& result) {
    const GraspScene& scene = experiment.getScene();
    const GraspSwitch* grasp = experiment.findSwitch();
    Recorder recorder(experiment, result);
    stepper.initialize(experiment.makeInitialState());
    result.summary.initialPenetration = scene.getSetupCheck().initialPenetration;
    recorder.record(stepper.getState());
    std::string lastEvent = "start";
    PhaseTimer phases(scene, grasp);
    const auto start = Clock::now();
    const double ikBefore = scene.getIkTiming().totalSeconds;
    try {
        stepThroughSamples(experiment, stepper, recorder, phases, duration, progress, observer, lastEvent);
        result.summary.complete = true;
    } catch (const integration::FixedStepTooLongError&) {
        throw;  // no result at all: the caller names the step's source (describeFixedStepTooLong)
    } catch (const InputError&) {
        throw;  // bad input found only once the run knows it (an automatic threshold): no result either
    } catch (const NumericalError& e) {
        result.summary.failure = foldToOneLine(e.what());
    } catch (const SimTK::Exception::Base& e) {  // its what() starts with a source file and spans lines
        result.summary.failure = std::string(failureVerb) + " at t = " + std::to_string(stepper.getState().getTime()) +
                                 " s (last event: " + lastEvent + "): Simbody: " + foldToOneLine(e.getMessageText());
    } catch (const std::exception& e) {
        result.summary.failure = std::string(failureVerb) + " at t = " + std::to_string(stepper.getState().getTime()) +
                                 " s (last event: " + lastEvent + "): " + foldToOneLine(e.what());
    }
    result.summary.wallTime = std::chrono::duration<double>(Clock::now() - start).count();
    summarizeRun(scene, grasp, phases, scene.getIkTiming().totalSeconds - ikBefore, stepper.getState(), result);
}

}  // namespace

SimulationResult runGraspSimulation(const scenario::Scenario& scenario, const SimulationOptions& options,
                                    const ProgressCallback& progress, const SampleObserver& observer) {
    const double duration = options.duration > 0 ? options.duration : scenario.simulation.duration;
    GraspExperiment experiment(scenario, options);
    const GraspScene& scene = experiment.getScene();
    SimulationResult result;
    result.summary = makeSummaryHeader(scenario, options, duration);
    if (options.contact == ContactModel::Rigid) {
        // Rigid contact: Simbody's SemiExplicitEulerTimeStepper at a fixed step (rigid_stepping.h).
        RigidStepper stepper(scene);
        runScene(experiment, stepper, duration, "stepping failed", progress, observer, result);
        result.summary.integrator = "simbody-semiexpliciteuler-pgs";
        return result;
    }
    const SceneStepper made = makeSceneStepper(experiment, options);
    const std::unique_ptr<integration::Stepper>& stepper = made.stepper;
    try {
        runScene(experiment, *stepper, duration, "integration failed", progress, observer, result);
    } catch (const integration::FixedStepTooLongError& e) {
        throw describeFixedStepTooLong(scenario, options, e);
    }
    result.summary.integrator = stepper->getMethodName();
    result.summary.integratorStatistics = stepper->getStatistics();
    return result;
}

}  // namespace graspsim::simulation
