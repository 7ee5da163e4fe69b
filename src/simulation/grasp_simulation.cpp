#include "graspsim/simulation/grasp_simulation.h"

#include "graspsim/error.h"
#include "graspsim/simulation/contact_grasp_quality.h"
#include "graspsim/simulation/grasp_scene.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>

namespace graspsim::simulation {

namespace {

using Clock = std::chrono::steady_clock;

// Output times, plus every instant where the inputs jump (release, perturbation on and off) so
// that no integration step straddles a discontinuity.
std::vector<double> makeSampleTimes(const GraspScene& scene, double duration) {
    std::set<double> times;
    const double dt = scene.getScenario().simulation.outputInterval;
    const long n = static_cast<long>(std::floor(duration / dt + 1e-9));
    for (long k = 1; k <= n; ++k) times.insert(k * dt);
    times.insert(duration);
    const auto addInside = [&](double t) { if (t > 0 && t < duration) times.insert(t); };
    addInside(scene.getReleaseTime());
    addInside(scene.getScenario().simulation.settleTime);
    if (const PerturbationForce* p = scene.getPerturbation()) {
        addInside(p->getStartTime());
        addInside(p->getEndTime());
    }
    return {times.begin(), times.end()};
}

class Recorder {
public:
    Recorder(const GraspScene& scene, SimulationResult& result) : scene_(scene), result_(result) {
        result_.jointNames = scene.getModel().getJointNames();
        qualityOptions_.mu = scene.getScenario().contact.staticFriction;
    }

    void record(const SimTK::State& s) {
        scene_.getSystem().realize(s, SimTK::Stage::Velocity);
        TrajectorySample sample;
        sample.time = s.getTime();
        const SimTK::Transform& X_GO = scene_.getObject().getBodyTransform(s);
        sample.p_GO = X_GO.p();
        sample.q_GO = X_GO.R().convertRotationToQuaternion();
        for (const std::string& j : result_.jointNames) sample.jointAngles.push_back(scene_.getModel().getJointPosition(s, j));
        ContactSample contacts{s.getTime(), scene_.getContacts().findContactReports(s)};
        sample.graspQuality = calcContactGraspQuality(contacts.contacts, X_GO, qualityOptions_);
        result_.summary.maxGraspQuality = std::max(result_.summary.maxGraspQuality, sample.graspQuality);
        result_.trajectory.push_back(std::move(sample));
        for (const auto& c : contacts.contacts) result_.summary.maxPenetration = std::max(result_.summary.maxPenetration, c.depth);
        result_.contacts.push_back(std::move(contacts));
    }

private:
    const GraspScene& scene_;
    SimulationResult& result_;
    grasp::QualityOptions qualityOptions_;  // box friction cone, smallest singular value
};

void checkFinite(const SimTK::State& s, const std::string& lastEvent) {
    const auto finite = [](const SimTK::Vector& v) {
        for (int k = 0; k < v.size(); ++k) if (!std::isfinite(v[k])) return false;
        return true;
    };
    if (finite(s.getQ()) && finite(s.getU())) return;
    throw NumericalError("non-finite state at t = " + std::to_string(s.getTime()) + " s (last event: " + lastEvent + ")");
}

// Held: every goal's fingertip still within the tolerance of its goal point on the object.
void summarizeGrip(const GraspScene& scene, const SimTK::State& s, SimulationSummary& summary) {
    scene.getSystem().realize(s, SimTK::Stage::Position);
    const SimTK::Transform& X_GO = scene.getObject().getBodyTransform(s);
    double worst = 0;
    for (std::size_t k = 0; k < scene.getGoalEndEffectors().size(); ++k) {
        const SimTK::Vec3 p_GE = scene.getModel().findEndEffectorLocationInGround(s, scene.getGoalEndEffectors()[k]);
        worst = std::max(worst, (p_GE - X_GO * scene.getSurfaceGoals()[k]).norm());
    }
    summary.maxFingertipGoalDistance = worst;
    summary.held = summary.complete && worst <= scene.getScenario().simulation.heldTolerance;
}

void summarizeDrift(const SimulationResult& result, SimulationSummary& summary) {
    const auto settled = std::find_if(result.trajectory.begin(), result.trajectory.end(),
                                      [&](const TrajectorySample& t) { return t.time >= summary.settleTime - 1e-12; });
    if (settled == result.trajectory.end()) return;
    summary.objectDisplacement = (result.trajectory.back().p_GO - settled->p_GO).norm();
}

}  // namespace

SimulationResult runGraspSimulation(const scenario::Scenario& scenario, const SimulationOptions& options,
                                    const ProgressCallback& progress) {
    const double duration = options.duration > 0 ? options.duration : scenario.simulation.duration;
    GraspScene scene(scenario, options);
    SimulationResult result;
    SimulationSummary& summary = result.summary;
    summary.scenario = scenario.name;
    summary.contact = toString(options.contact);
    summary.mode = toString(options.mode);
    summary.perturbation = options.perturbation;
    summary.settleTime = std::min(scenario.simulation.settleTime, duration);
    Recorder recorder(scene, result);

    SimTK::CPodesIntegrator integrator(scene.getSystem(), SimTK::CPodes::BDF, SimTK::CPodes::Newton);
    integrator.setAccuracy(scenario.simulation.accuracy);
    SimTK::TimeStepper stepper(scene.getSystem(), integrator);
    SimTK::State initial = scene.makeInitialState();
    stepper.initialize(initial);
    recorder.record(stepper.getState());
    std::string lastEvent = "start";
    const auto start = Clock::now();
    const double ikBefore = scene.getIkTiming().totalSeconds;
    try {
        for (double t : makeSampleTimes(scene, duration)) {
            stepper.stepTo(t);
            checkFinite(stepper.getState(), lastEvent);
            if (std::abs(t - scene.getReleaseTime()) < 1e-12) {
                SimTK::State released = stepper.getState();
                scene.releaseObject(released);
                stepper.initialize(released);  // a lock change is an Instance-stage change
                lastEvent = "object released at t = " + std::to_string(t) + " s";
            }
            recorder.record(stepper.getState());
            if (progress) progress(t, duration);
        }
        summary.complete = true;
    } catch (const NumericalError& e) {
        summary.failure = e.what();
    } catch (const std::exception& e) {
        summary.failure = "integration failed at t = " + std::to_string(stepper.getState().getTime()) +
                          " s (last event: " + lastEvent + "): " + e.what();
    }
    summary.wallTime = std::chrono::duration<double>(Clock::now() - start).count();
    summary.simTime = stepper.getState().getTime();
    summary.steps = integrator.getNumStepsTaken();
    summary.ikSolves = scene.getIkTiming().solves;
    const double ikSeconds = scene.getIkTiming().totalSeconds - ikBefore;
    const double perStep = summary.steps > 0 ? 1e6 / static_cast<double>(summary.steps) : 0;
    summary.meanStepUs = summary.wallTime * perStep;
    summary.ikUsPerStep = ikSeconds * perStep;
    summary.dynamicsUsPerStep = (summary.wallTime - ikSeconds) * perStep;
    summarizeDrift(result, summary);
    summarizeGrip(scene, stepper.getState(), summary);
    return result;
}

}  // namespace graspsim::simulation
