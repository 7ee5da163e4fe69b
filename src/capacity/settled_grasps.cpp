#include "graspsim/capacity/settled_grasps.h"

#include "graspsim/error.h"
#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/grasp_switch.h"
#include "graspsim/simulation/rigid_stepping.h"
#include "graspsim/simulation/scene_stepper.h"
#include "graspsim/simulation/stall_guard.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>

namespace graspsim::capacity {

struct SettledGrasps::Scene {
    Scene(const scenario::Scenario& scenario, const simulation::SimulationOptions& options) : experiment(scenario, options) {}
    simulation::GraspExperiment experiment;
    std::optional<SimTK::State> settled;  // just before `start` (kSettledLead), once settled
    std::optional<double> nextIk;         // rigid contact: the next IK update after it (s)
    double start = 0;
};

namespace {

// A shared scene stops this long (s) before the load's start: the run's own stepper then takes the
// step in which the load begins, and the switch's witnesses see a step load cross their limits
// there, at its start, as in a run of its own. Started at the load's start itself, a stepper would
// begin with the witnesses already past their limits and see no crossing.
constexpr double kSettledLead = 1e-3;

// The experiment's stepper, from a given State: the options' integrator for compliant contact
// (scene_stepper.h), the rigid stepper for rigid.
class SceneAdvance {
public:
    SceneAdvance(simulation::GraspExperiment& experiment, const simulation::SimulationOptions& options, const SimTK::State& from,
                 std::optional<double> nextIk)
        : scene_(experiment.getScene()), options_(options) {
        if (options.contact == simulation::ContactModel::Rigid) {
            rigid_ = std::make_unique<simulation::RigidStepper>(scene_);
            rigid_->initialize(from, nextIk);
            return;
        }
        made_ = simulation::makeSceneStepper(experiment, options);
        made_.stepper->initialize(from);
    }

    void advanceTo(double t) {
        const double release = scene_.getReleaseTime();
        if (scene_.isObjectHeld(getState()) && t >= release) {
            stepTo(release);
            releaseObject();
        }
        stepTo(t);
    }

    const SimTK::State& getState() const { return rigid_ ? rigid_->getState() : made_.stepper->getState(); }
    std::optional<double> findNextIkTime() const { return rigid_ ? std::optional<double>(rigid_->getNextIkTime()) : std::nullopt; }

private:
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

    const simulation::GraspScene& scene_;
    const simulation::SimulationOptions& options_;
    simulation::SceneStepper made_;  // compliant contact: the stepper and its force Jacobians
    std::unique_ptr<simulation::RigidStepper> rigid_;
};

// The options a scene is built with: the load is the run's (set on the shared scene's RampLoad
// before each run), and nothing else pushes the object.
simulation::SimulationOptions makeSceneOptions(simulation::SimulationOptions options, const simulation::LoadRampSpec& load) {
    options.perturbation = "none";
    options.loadRamp = load;
    return options;
}

// No load yet, from `start` (s): how a shared scene is built and settled, whatever ran on it.
simulation::LoadRampSpec makeNoLoad(double start) {
    simulation::LoadRampSpec none;
    none.start = start;
    return none;
}

}  // namespace

// One run of a load on a scene: leased settled (Start::Shared) or its own (Start::Own).
class GraspRun : public LoadedRun {
public:
    GraspRun(SettledGrasps& grasps, const simulation::LoadRampSpec& load) : grasps_(grasps), load_(load) {
        if (grasps.startKind_ == SettledGrasps::Start::Own) {
            scene_ = std::make_unique<SettledGrasps::Scene>(grasps.getScenario(), makeSceneOptions(grasps.getOptions(), load));
        } else {
            scene_ = grasps.leaseScene(load.start);
        }
    }

    ~GraspRun() override {
        advance_.reset();  // its stepper refers to the scene's System
        if (grasps_.startKind_ == SettledGrasps::Start::Shared) grasps_.returnScene(std::move(scene_));
    }

    void advanceTo(double t) override {
        if (!advance_) start();
        advance_->advanceTo(t);
    }

    void captureReference() override {
        checkHeldAtLoadStart();
        const simulation::GraspSwitch* grasp = findSwitch();
        if (grasp && !isEngagedUpToNow(*grasp)) {
            // At fixed steps a grasp that never settles is the likelier cause: a step too long to
            // hold it, below what the stepper refuses (docs/performance.md).
            const bool fixed = grasps_.getOptions().integrator == simulation::IntegratorChoice::LinearlyImplicitFixed;
            const std::string obstacle = grasp->findEngageObstacle(getState());
            throw NumericalError("capacity: the approximation is not engaged at the load's start, t = " +
                                 std::to_string(getState().getTime()) + " s" + (obstacle.empty() ? "" : " (" + obstacle + ")") +
                                 "; use --mode full" + (obstacle.find("Q_Th") != std::string::npos ? " or lower --q-threshold" : "") +
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
        s.held = getScene().findMaxFingertipGoalDistance(getState()) <= getScene().getScenario().simulation.heldTolerance;
        if (s.engaged != 1) s.gripForce = calcGripForce();
        return s;
    }

    std::string findReleaseReason() const override {
        const simulation::GraspSwitch* grasp = findSwitch();
        if (!grasp || !advance_) return {};
        for (const simulation::GraspEvent& e : grasp->getEvents(getState())) {
            if (e.kind == simulation::GraspEventKind::Release) return "t = " + std::to_string(e.time) + " s: " + e.reason;
        }
        return {};
    }

private:
    // Shared: the scene settled once (now, if no run has settled it yet), then the run's load is set
    // and its stepper starts from a copy of the settled State, kSettledLead before the load's start.
    // Own: from the scene's start.
    void start() {
        simulation::GraspExperiment& experiment = scene_->experiment;
        if (grasps_.startKind_ == SettledGrasps::Start::Own) {
            advance_.emplace(experiment, grasps_.getOptions(), experiment.makeInitialState(), std::nullopt);
            return;
        }
        if (!scene_->settled) settle();
        experiment.updLoads().updLoadRamp()->setSpec(load_);
        SimTK::State from = *scene_->settled;
        from.invalidateAllCacheAtOrAbove(SimTK::Stage::Dynamics);  // nothing computed under another load may stay
        advance_.emplace(experiment, grasps_.getOptions(), from, scene_->nextIk);
    }

    void settle() {
        simulation::GraspExperiment& experiment = scene_->experiment;
        experiment.updLoads().updLoadRamp()->setSpec(makeNoLoad(scene_->start));  // an earlier run's load is still set
        SceneAdvance settling(experiment, grasps_.getOptions(), experiment.makeInitialState(), std::nullopt);
        settling.advanceTo(scene_->start - kSettledLead);
        scene_->settled = settling.getState();
        scene_->nextIk = settling.findNextIkTime();
        grasps_.countSettle();
    }

    const simulation::GraspScene& getScene() const { return scene_->experiment.getScene(); }
    const simulation::GraspSwitch* findSwitch() const { return scene_->experiment.findSwitch(); }
    const SimTK::State& getState() const { return advance_->getState(); }

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
        const double distance = getScene().findMaxFingertipGoalDistance(getState());
        const double tolerance = getScene().getScenario().simulation.heldTolerance;
        if (distance <= tolerance) return;
        char text[320];
        std::snprintf(text, sizeof text,
                      "capacity: the grasp does not hold the object at the load's start, t = %.4g s: a goal fingertip is "
                      "%.3g mm from its goal (simulation.held_tolerance %.3g mm); graspsim simulate shows the grasp without a load",
                      getState().getTime(), distance * 1e3, tolerance * 1e3);
        throw NumericalError(text);
    }

    SimTK::Transform findObjectInPalm() const {
        const SimTK::State& s = getState();
        getScene().getSystem().realize(s, SimTK::Stage::Position);
        return ~getScene().getPalm().getBodyTransform(s) * getScene().getObject().getBodyTransform(s);
    }

    double calcGripForce() const {
        const SimTK::State& s = getState();
        getScene().getSystem().realize(s, SimTK::Stage::Velocity);
        return contact::sumNormalForces(getScene().findContactReports(s));
    }

    // The goal points (object material points where the fingertips press), in the palm frame H.
    std::vector<SimTK::Vec3> findGoalPointsInPalm() const {
        const SimTK::Transform X_HO = findObjectInPalm();
        std::vector<SimTK::Vec3> points;
        for (const SimTK::Vec3& p_OT : getScene().getSurfaceGoals()) points.push_back(X_HO * p_OT);
        return points;
    }

    SettledGrasps& grasps_;
    simulation::LoadRampSpec load_;
    std::unique_ptr<SettledGrasps::Scene> scene_;
    std::optional<SceneAdvance> advance_;
    std::vector<SimTK::Vec3> reference_;
    SimTK::Vec4 q_HO_reference_{1, 0, 0, 0};  // R_HO at the reference, as a quaternion
};

SettledGrasps::SettledGrasps(const scenario::Scenario& scenario, const simulation::SimulationOptions& options, Start start)
    : scenario_(scenario), options_(options), startKind_(start) {}

SettledGrasps::~SettledGrasps() = default;

std::unique_ptr<LoadedRun> SettledGrasps::makeRun(const simulation::LoadRampSpec& load) { return std::make_unique<GraspRun>(*this, load); }

int SettledGrasps::countSettled() const {
    const std::lock_guard<std::mutex> lock(mutex_);
    return settled_;
}

// A new scene's load is none until its run sets one, from the same start (the run's stepper lands there).
std::unique_ptr<SettledGrasps::Scene> SettledGrasps::leaseScene(double start) {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        const auto found = std::find_if(idle_.begin(), idle_.end(), [start](const std::unique_ptr<Scene>& s) { return s->start == start; });
        if (found != idle_.end()) {
            std::unique_ptr<Scene> scene = std::move(*found);
            idle_.erase(found);
            return scene;
        }
    }
    auto scene = std::make_unique<Scene>(scenario_, makeSceneOptions(options_, makeNoLoad(start)));
    scene->start = start;
    return scene;
}

void SettledGrasps::returnScene(std::unique_ptr<Scene> scene) {
    const std::lock_guard<std::mutex> lock(mutex_);
    idle_.push_back(std::move(scene));
}

void SettledGrasps::countSettle() {
    const std::lock_guard<std::mutex> lock(mutex_);
    ++settled_;
}

LoadedRunFactory makeGraspRuns(SettledGrasps& grasps) {
    return [&grasps](const simulation::LoadRampSpec& load) { return grasps.makeRun(load); };
}

}  // namespace graspsim::capacity
