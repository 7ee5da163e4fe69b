#include "graspsim/capacity/grasp_capacity.h"

#include "graspsim/capacity/overload.h"

#include "graspsim/error.h"
#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/grasp_switch.h"
#include "graspsim/simulation/rigid_stepping.h"
#include "graspsim/simulation/scene_stepper.h"
#include "graspsim/simulation/stall_guard.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iterator>

namespace graspsim::capacity {

namespace {

constexpr double kGravity = 9.81;  // m/s^2, for the default rate only

// The scene and its stepper: the options' integrator for compliant contact (scene_stepper.h), the
// rigid stepper for rigid.
class GraspRun : public LoadedRun {
public:
    GraspRun(const scenario::Scenario& scenario, simulation::SimulationOptions options)
        : experiment_(scenario, options), scene_(experiment_.getScene()), options_(options) {
        if (options.contact == simulation::ContactModel::Rigid) {
            rigid_ = std::make_unique<simulation::RigidStepper>(scene_);
            rigid_->initialize(experiment_.makeInitialState());
            return;
        }
        made_ = simulation::makeSceneStepper(experiment_, options);
        made_.stepper->initialize(experiment_.makeInitialState());
    }

    void advanceTo(double t) override {
        const double release = scene_.getReleaseTime();
        if (scene_.isObjectHeld(getState()) && t >= release) {
            stepTo(release);
            releaseObject();
        }
        stepTo(t);
    }

    void captureReference() override {
        checkHeldAtLoadStart();
        const simulation::GraspSwitch* grasp = findSwitch();
        if (grasp && !isEngagedUpToNow(*grasp)) {
            // At fixed steps a grasp that never settles is the likelier cause: a step too long to
            // hold it, below what the stepper refuses (docs/performance.md).
            const bool fixed = options_.integrator == simulation::IntegratorChoice::LinearlyImplicitFixed;
            throw NumericalError("capacity: the approximation is not engaged at the load's start, t = " +
                                 std::to_string(getState().getTime()) + " s; use --mode full or lower --q-threshold" +
                                 (fixed ? ", or at fixed steps a shorter --step-size (0.001) or --integrator implicit" : ""));
        }
        reference_ = findGoalPointsInPalm();
        q_HO_reference_ = findObjectInPalm().R().convertRotationToQuaternion().asVec4();
    }

    CapacitySample sampleNow() override {
        CapacitySample s;
        const std::vector<SimTK::Vec3> now = findGoalPointsInPalm();
        const SimTK::Rotation R_HO0{SimTK::Quaternion(q_HO_reference_)};
        const SimTK::Rotation R_change = ~R_HO0 * findObjectInPalm().R();
        s.rotation = std::abs(R_change.convertRotationToAngleAxis()[0]);
        for (std::size_t k = 0; k < now.size(); ++k) s.slip = std::max(s.slip, (now[k] - reference_[k]).norm());
        if (const simulation::GraspSwitch* grasp = findSwitch()) s.engaged = grasp->isEngaged(getState()) ? 1 : 0;
        s.held = scene_.findMaxFingertipGoalDistance(getState()) <= scene_.getScenario().simulation.heldTolerance;
        if (s.engaged != 1) s.gripForce = calcGripForce();
        return s;
    }

    std::string findReleaseReason() const override {
        const simulation::GraspSwitch* grasp = findSwitch();
        if (!grasp) return {};
        for (const simulation::GraspEvent& e : grasp->getEvents(getState())) {
            if (e.kind == simulation::GraspEventKind::Release) return "t = " + std::to_string(e.time) + " s: " + e.reason;
        }
        return {};
    }

private:
    const simulation::GraspSwitch* findSwitch() const { return experiment_.findSwitch(); }

    // A step load the grasp cannot carry is handed back at its start (the compliance trigger sees
    // the load itself): the grasp was engaged up to the load.
    bool isEngagedUpToNow(const simulation::GraspSwitch& grasp) const {
        if (grasp.isEngaged(getState())) return true;
        const std::vector<simulation::GraspEvent>& events = grasp.getEvents(getState());
        return !events.empty() && events.back().kind == simulation::GraspEventKind::Release &&
               events.back().time >= getState().getTime();
    }

    // A grasp that has lost its object before the load has no capacity to measure: its slip and
    // drop would both read 0 at the first sample, a figure of the fall, not of the grasp.
    void checkHeldAtLoadStart() const {
        const double distance = scene_.findMaxFingertipGoalDistance(getState());
        const double tolerance = scene_.getScenario().simulation.heldTolerance;
        if (distance <= tolerance) return;
        char text[320];
        std::snprintf(text, sizeof text,
                      "capacity: the grasp does not hold the object at the load's start, t = %.4g s: a goal fingertip is "
                      "%.3g mm from its goal (simulation.held_tolerance %.3g mm); graspsim simulate shows the grasp without a load",
                      getState().getTime(), distance * 1e3, tolerance * 1e3);
        throw NumericalError(text);
    }

    const SimTK::State& getState() const { return rigid_ ? rigid_->getState() : made_.stepper->getState(); }

    // A fixed step the stepper cannot trust ends the measurement (no figures from it), named in
    // the run's terms; other failures end the run's trace (runLoadedScene).
    void stepTo(double t) {
        if (rigid_) {
            rigid_->stepTo(t);
        } else {
            const double from = getState().getTime();
            const long stepsBefore = made_.stepper->getStatistics().steps;
            try {
                made_.stepper->stepTo(t);
            } catch (const integration::FixedStepTooLongError& e) {
                throw simulation::describeFixedStepTooLong(scene_.getScenario(), options_, e);
            }
            simulation::checkNotStalled("capacity", from, getState().getTime(), made_.stepper->getStatistics().steps - stepsBefore);
        }
        const SimTK::State& s = getState();
        for (int k = 0; k < s.getNQ(); ++k) {
            if (!std::isfinite(s.getQ()[k])) throw NumericalError("capacity: non-finite state at t = " + std::to_string(s.getTime()) + " s");
        }
    }

    void releaseObject() {
        if (rigid_) {
            rigid_->releaseObject();
            return;
        }
        SimTK::State released = made_.stepper->getState();
        scene_.releaseObject(released);
        made_.stepper->initialize(released);
    }

    SimTK::Transform findObjectInPalm() const {
        const SimTK::State& s = getState();
        scene_.getSystem().realize(s, SimTK::Stage::Position);
        return ~scene_.getPalm().getBodyTransform(s) * scene_.getObject().getBodyTransform(s);
    }

    double calcGripForce() const {
        const SimTK::State& s = getState();
        scene_.getSystem().realize(s, SimTK::Stage::Velocity);
        return contact::sumNormalForces(scene_.findContactReports(s));
    }

    // The goal points (object material points where the fingertips press), in the palm frame H.
    std::vector<SimTK::Vec3> findGoalPointsInPalm() const {
        const SimTK::Transform X_HO = findObjectInPalm();
        std::vector<SimTK::Vec3> points;
        for (const SimTK::Vec3& p_OT : scene_.getSurfaceGoals()) points.push_back(X_HO * p_OT);
        return points;
    }

    simulation::GraspExperiment experiment_;
    const simulation::GraspScene& scene_;
    simulation::SimulationOptions options_;
    simulation::SceneStepper made_;  // compliant contact: the stepper and its force Jacobians
    std::unique_ptr<simulation::RigidStepper> rigid_;
    std::vector<SimTK::Vec3> reference_;
    SimTK::Vec4 q_HO_reference_{1, 0, 0, 0};  // R_HO at the reference, as a quaternion
};

GraspCapacity makeHeader(const simulation::SimulationOptions& options, const GraspCapacityRequest& request,
                         const scenario::Scenario& scenario, const char* method) {
    GraspCapacity c;
    c.directionName = request.directionName;
    c.direction = request.direction;
    c.torque = request.torque;
    c.method = method;
    c.contact = options.contact;
    if (options.contact == simulation::ContactModel::Compliant && scenario.friction.model != contact::FrictionModel::Regularized) {
        c.friction = scenario.friction.model;
    }
    if (options.contact == simulation::ContactModel::Compliant && scenario.contact.capsuleContact != contact::CapsuleContact::Deepest) {
        c.capsuleContact = scenario.contact.capsuleContact;
    }
    c.mode = options.mode;
    if (options.mode == simulation::SimulationMode::Approx) {
        const simulation::ApproxOptions approx = simulation::resolveApproxOptions(options.approx, scenario.approximation);
        c.realization = simulation::toString(approx.constraint) + " " + simulation::toString(approx.attach) + ", limits " +
                        grasp::toString(approx.limitModel) + ", release at " + simulation::toString(approx.releaseTrigger);
        if (approx.releaseGive) {  // the default's text stays as it was
            char give[48];
            std::snprintf(give, sizeof give, " (give %.3g mm)", 1e3 * *approx.releaseGive);
            c.realization += give;
        }
        if (approx.handBack != simulation::ApproxHandBack::Engaged) c.realization += ", hand back " + simulation::toString(approx.handBack);
        if (approx.bushingGive != simulation::ApproxBushingGive::Stiff) c.realization += ", bushing give " + simulation::toString(approx.bushingGive);
    }
    c.start = findLoadStart(scenario);
    c.criteria = request.criteria;
    return c;
}

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

double findDefaultRate(const scenario::Scenario& scenario, bool torque) {
    const double force = 2 * scenario.object.mass * kGravity;
    if (!torque) return force;
    double lever = 0;
    for (const auto& goal : scenario.goals) {
        const model::Vec3& p = goal.second;
        lever = std::max(lever, std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    }
    return force * lever;
}

void checkLoadResistible(const scenario::Scenario& scenario, const GraspCapacityRequest& request,
                         const std::pair<std::string, std::string>& flags) {
    if (!request.torque || scenario.goals.size() != 2) return;
    const auto first = scenario.goals.begin(), second = std::next(first);
    const model::Transform X_GO = scenario.object.findPose();
    const model::Vec3 a = X_GO.xformFrameVecToBase(first->second), b = X_GO.xformFrameVecToBase(second->second);
    const SimTK::Vec3 line(b[0] - a[0], b[1] - a[1], b[2] - a[2]);
    if (!(line.norm() > 0)) return;
    const double angle = std::acos(std::min(1.0, std::abs(~SimTK::Vec3(request.direction) * line) / line.norm()));
    if (angle > kPinchAxisTolerance) return;
    char degrees[32];
    std::snprintf(degrees, sizeof degrees, "%.3g", angle * 180 / SimTK::Pi);
    throw InputError(flags.first + " " + request.directionName + " " + flags.second + ": the axis is " + degrees + " deg from the line through the goals " +
                     first->first + " and " + second->first + "; two point contacts cannot resist a torque about it (no torsional "
                     "friction), so there is no capacity to measure; choose an axis more than 5 deg away");
}

double findLoadStart(const scenario::Scenario& scenario) { return scenario.simulation.settleTime + kLoadStartDelay; }

LoadedRunFactory makeGraspRuns(const scenario::Scenario& scenario, const simulation::SimulationOptions& options) {
    return [&scenario, options](const simulation::LoadRampSpec& load) -> std::unique_ptr<LoadedRun> {
        simulation::SimulationOptions loaded = options;
        loaded.perturbation = "none";
        loaded.loadRamp = load;
        return std::make_unique<GraspRun>(scenario, loaded);
    };
}

GraspCapacity measureGraspCapacityRamp(const scenario::Scenario& scenario, const simulation::SimulationOptions& options,
                                       const GraspCapacityRequest& request) {
    const auto clock = std::chrono::steady_clock::now();
    GraspCapacity c = makeHeader(options, request, scenario, "ramp");
    c.rate = request.rate > 0 ? request.rate : findDefaultRate(scenario, request.torque);
    RampProtocol protocol;
    protocol.direction = request.direction;
    protocol.torque = request.torque;
    protocol.start = c.start;
    protocol.rate = c.rate;
    protocol.initial = request.initialLoad;
    protocol.maxDuration = request.maxRampDuration;
    protocol.sampleInterval = request.sampleInterval;
    protocol.criteria = request.criteria;
    c.trace = runRamp(makeGraspRuns(scenario, options), protocol);
    c.wallTime = secondsSince(clock);
    return c;
}

GraspCapacity measureGraspCapacityBisection(const scenario::Scenario& scenario, const simulation::SimulationOptions& options,
                                            const GraspCapacityRequest& request, double guess, double hold) {
    const auto clock = std::chrono::steady_clock::now();
    GraspCapacity c = makeHeader(options, request, scenario, "bisection");
    BisectionProtocol protocol;
    protocol.direction = request.direction;
    protocol.torque = request.torque;
    protocol.start = c.start;
    protocol.hold = hold;
    protocol.high = guess;
    c.hold = hold;
    protocol.tolerance = 0.02;
    protocol.sampleInterval = request.sampleInterval;
    protocol.criteria = request.criteria;
    c.bisection = runBisection(makeGraspRuns(scenario, options), protocol);
    c.wallTime = secondsSince(clock);
    return c;
}

GraspCapacity measureGraspCapacityConstant(const scenario::Scenario& scenario, const simulation::SimulationOptions& options,
                                           const GraspCapacityRequest& request, double load, double hold) {
    const auto clock = std::chrono::steady_clock::now();
    GraspCapacity c = makeHeader(options, request, scenario, "constant");
    c.load = load;
    c.hold = hold;
    OverloadProtocol protocol;
    protocol.direction = request.direction;
    protocol.torque = request.torque;
    protocol.start = c.start;
    protocol.load = load;
    protocol.hold = hold;
    protocol.criteria = request.criteria;
    c.trace = runOverload(makeGraspRuns(scenario, options), protocol);
    c.wallTime = secondsSince(clock);
    return c;
}

}  // namespace graspsim::capacity
