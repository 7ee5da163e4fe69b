#include "graspsim/validation/cost_table.h"

#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_experiment.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/grasp_simulation.h"
#include "graspsim/simulation/grasp_switch.h"

#include "run_timing.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <map>
#include <memory>
#include <tuple>
#include <utility>

namespace graspsim::validation {

namespace {

// The floor state: `state` with the approximation's element off, the fingers and the object locked
// where they are and every finger-object pair off: the same arm and merged hand with no object
// dynamics and no contact. Its cost depends on the System it is in (see ExperimentCost).
SimTK::State makeFloorState(const simulation::GraspExperiment& experiment, const SimTK::State& state) {
    const simulation::GraspScene& scene = experiment.getScene();
    SimTK::State floor = state;
    // First: a weld may own the object's lock.
    if (const simulation::GraspApproximation* approximation = experiment.getApproximation()) {
        approximation->getAttachment().release(floor);
    }
    const SimTK::SimbodyMatterSubsystem& matter = scene.getModel().getMatter();
    for (SimTK::MobilizedBodyIndex finger : scene.getFingerMobilizers()) {
        matter.getMobilizedBody(finger).lock(floor, SimTK::Motion::Position);
    }
    scene.getObject().lock(floor, SimTK::Motion::Position);
    scene.getCompliantContacts().setPairsEnabled(floor, scene.getCompliantContacts().findAllPairIndices(), false);
    return floor;
}

// How long the approximation runs on after its first simulated second engaged (and the floor runs): the hold whose
// steady cost the table reports beside that first second (which carries the switch's restart).
// A simulated second of hold is only ~10 ms of wall time, so one scheduler hiccup moves a window by
// 10 %: twenty windows make the median steady (four moved the phone's hold/floor by 1.26-1.39).
constexpr double kHoldSeconds = 20.0;

// An approximation run's sample observer: times the full-contact and engaged evaluations, marks
// the first engaged second and each second of the hold after it, and integrates the run's own floor
// one simulated second after each of those seconds, all out of the run's clock.
class ApproxRunMeter {
public:
    // `endTime`: the run's last sample, after which its System is gone.
    ApproxRunMeter(ApproxCost& cost, int realizations, double endTime) : cost_(cost), realizations_(realizations), endTime_(endTime) {}

    void observe(const simulation::GraspExperiment& experiment, const SimTK::State& state) {
        const simulation::GraspScene& scene = experiment.getScene();
        const simulation::GraspSwitch* grasp = experiment.findSwitch();
        const Mark here = clock_.mark(state.getTime(), scene.getSystem());
        const double before = clock_.getObservingSeconds();
        clock_.beginObserving(scene.getSystem());
        if (!scene.isObjectHeld(state) && grasp) observeReleased(experiment, state, *grasp, here);
        if (state.getTime() >= endTime_ - 1e-9) ownFloor_.reset();
        clock_.endObserving(scene.getSystem());
        if (engaged_.isSet()) observingWhileEngaged_ += clock_.getObservingSeconds() - before;
    }

    void finish(const simulation::SimulationSummary& summary) {
        cost_.engageTime = summary.engaged ? summary.engageTime : -1;
        if (summary.approxSteps > 0) {
            cost_.stepUs = (summary.approxStepUs * summary.approxSteps - 1e6 * observingWhileEngaged_) / summary.approxSteps;
        }
        cost_.wallPerSimSecond = wallPerSimSecond(engaged_, oneSecond_);
        const HoldCost hold = findHoldCost(holdSeconds_);
        cost_.holdWallPerSimSecond = hold.wallPerSimSecond;
        cost_.holdEvaluationsPerSimSecond = hold.evaluationsPerSimSecond;
        const HoldCost floor = findHoldCostOfSeconds(ownFloorSeconds_);
        cost_.ownFloorHoldWallPerSimSecond = floor.wallPerSimSecond;
        cost_.ownFloorEvaluationsPerSimSecond = floor.evaluationsPerSimSecond;
        cost_.holdOverOwnFloor = findMedianPairedRatio(holdSeconds_, ownFloorSeconds_);
    }

private:
    void observeReleased(const simulation::GraspExperiment& experiment, const SimTK::State& state,
                         const simulation::GraspSwitch& grasp, const Mark& here) {
        const simulation::GraspScene& scene = experiment.getScene();
        if (!grasp.isEngaged(state) && grasp.getEvents(state).empty()) {
            cost_.fullRealizeUs = timeRealization(scene.getSystem(), state, realizations_);
        } else if (grasp.isEngaged(state) && !engaged_.isSet()) {
            engaged_ = here;
            const SimTK::State floor = makeFloorState(experiment, state);
            std::tie(cost_.engagedRealizeUs, cost_.ownFloorRealizeUs) =
                timeRealizationPair(scene.getSystem(), state, floor, realizations_);
            const scenario::Scenario& s = scene.getScenario();
            ownFloor_ = std::make_unique<FloorRun>(scene.getSystem(), floor, s.simulation.accuracy, s.controller.ikInterval);
        }
        if (engaged_.isSet() && !oneSecond_.isSet() && here.time >= engaged_.time + 1.0 - 1e-9) {
            oneSecond_ = here;
            markHoldSecond(here);
        } else if (grasp.isEngaged(state) && !holdSeconds_.empty() && here.time >= holdSeconds_.back().time + 1.0 - 1e-9) {
            markHoldSecond(here);
        }
        if (!grasp.isEngaged(state)) ownFloor_.reset();
    }

    void markHoldSecond(const Mark& here) {
        holdSeconds_.push_back(here);
        if (!ownFloor_ || holdSeconds_.size() < 2) return;
        ownFloorSeconds_.push_back(ownFloor_->advanceOneSecond());
        if (ownFloorSeconds_.size() >= std::size_t(kHoldSeconds)) ownFloor_.reset();  // before the run's System goes
    }

    ApproxCost& cost_;
    int realizations_;
    double endTime_;
    RunClock clock_;
    Mark engaged_, oneSecond_;
    std::vector<Mark> holdSeconds_;       // one mark per whole simulated second of the hold
    std::unique_ptr<FloorRun> ownFloor_;  // this run's floor, one simulated second after each second of hold
    std::vector<Mark> ownFloorSeconds_;
    double observingWhileEngaged_ = 0;
};

ApproxCost measureApprox(const scenario::Scenario& s, simulation::ApproxConstraint constraint, double duration,
                         int realizations, simulation::IntegratorChoice integrator) {
    ApproxCost cost;
    cost.constraint = simulation::toString(constraint);
    simulation::SimulationOptions options;
    options.integrator = integrator;
    options.mode = simulation::SimulationMode::Approx;
    options.approx.constraint = constraint;
    options.duration = duration + kHoldSeconds;
    ApproxRunMeter meter(cost, realizations, options.duration);
    const simulation::SampleObserver observe = [&](const simulation::GraspExperiment& experiment, const SimTK::State& state) {
        meter.observe(experiment, state);
    };
    meter.finish(simulation::runGraspSimulation(s, options, {}, observe).summary);
    return cost;
}

// The floor in a full-contact run's System, which has no approximation elements, from its last
// sample (the grasp in place). A run of its own: the timings would otherwise count in that run's
// per-step figures.
void measureFloor(const scenario::Scenario& s, const simulation::SimulationOptions& options, int realizations,
                  ExperimentCost& cost) {
    const simulation::SampleObserver observe = [&](const simulation::GraspExperiment& experiment, const SimTK::State& state) {
        if (state.getTime() < options.duration - 1e-9) return;
        const simulation::GraspScene& scene = experiment.getScene();
        const SimTK::State floor = makeFloorState(experiment, state);
        cost.floorRealizeUs = timeRealization(scene.getSystem(), floor, realizations);
        const scenario::Scenario& scenario = scene.getScenario();
        const HoldCost hold = timeFloorHold(scene.getSystem(), floor, scenario.simulation.accuracy, scenario.controller.ikInterval,
                                            int(kHoldSeconds));
        cost.floorHoldWallPerSimSecond = hold.wallPerSimSecond;
        cost.floorEvaluationsPerSimSecond = hold.evaluationsPerSimSecond;
    };
    simulation::runGraspSimulation(s, options, {}, observe);
}

// A stepper-table row of a hold: its wall time and evaluations per simulated second only.
StepperCost makeHoldRow(const std::string& scenario, const std::string& run, double wallPerSimSecond,
                        double evaluationsPerSimSecond) {
    StepperCost row;
    row.scenario = scenario;
    row.run = run;
    row.wallPerSimSecond = wallPerSimSecond;
    row.evaluationsPerSimSecond = evaluationsPerSimSecond;
    return row;
}

ExperimentCost measureExperiment(const std::string& name, double duration, int realizations) {
    const scenario::Scenario s = scenario::findBuiltinScenario(name);
    ExperimentCost cost;
    cost.scenario = name;
    // The thesis's comparison (Table 5.1) on one integrator, CPodes, whose engaged hold takes the
    // fewest steps; the stepper table below puts the default (linearly implicit) beside it.
    simulation::SimulationOptions options;
    options.duration = duration;
    options.integrator = simulation::IntegratorChoice::SimbodyCpodes;
    const simulation::SimulationSummary full = simulation::runGraspSimulation(s, options).summary;
    measureFloor(s, options, realizations, cost);
    cost.fullStepUs = full.meanStepUs;
    cost.fullIkUsPerStep = full.ikUsPerStep;
    cost.fullDynamicsUsPerStep = full.dynamicsUsPerStep;
    cost.fullWallPerSimSecond = full.fullWallPerSimSecond;
    for (auto constraint : {simulation::ApproxConstraint::Bushing, simulation::ApproxConstraint::Weld}) {
        cost.approx.push_back(measureApprox(s, constraint, duration, realizations, simulation::IntegratorChoice::SimbodyCpodes));
    }
    for (auto integrator : {simulation::IntegratorChoice::SimbodyCpodes, simulation::IntegratorChoice::LinearlyImplicit}) {
        cost.steppers.push_back(measureFullContactStepper(s, integrator, duration, realizations));
    }
    cost.steppers.push_back(measureHeldFullContact(s, simulation::IntegratorChoice::LinearlyImplicit, kHeldWarmUp, duration));
    for (const ApproxCost& a : cost.approx) {
        cost.steppers.push_back(makeHoldRow(name, "approx, " + a.constraint, a.holdWallPerSimSecond, a.holdEvaluationsPerSimSecond));
    }
    // The default's hold: the bushing on the linearly implicit stepper (resolveIntegrator).
    const ApproxCost implicitHold = measureApprox(s, simulation::ApproxConstraint::Bushing, duration, realizations,
                                                  simulation::IntegratorChoice::LinearlyImplicit);
    cost.steppers.push_back(makeHoldRow(name, "approx, bushing, implicit", implicitHold.holdWallPerSimSecond,
                                        implicitHold.holdEvaluationsPerSimSecond));
    cost.steppers.push_back(makeHoldRow(name, "floor", cost.floorHoldWallPerSimSecond, cost.floorEvaluationsPerSimSecond));
    return cost;
}

EndEffectorCost measureEndEffectors(int count, double duration, int realizations) {
    scenario::Scenario s = scenario::findBuiltinScenario("ball-clutch");
    const char* const order[] = {"thumb_tip", "index_tip", "middle_tip", "ring_tip", "little_tip"};
    std::map<std::string, scenario::Vec3> goals;
    for (int k = 0; k < count; ++k) goals[order[k]] = s.goals.at(order[k]);
    s.goals = goals;
    simulation::SimulationOptions options;
    options.duration = duration;
    EndEffectorCost cost;
    cost.endEffectors = count;
    double endTime = duration;
    const simulation::SampleObserver observe = [&](const simulation::GraspExperiment& experiment, const SimTK::State& state) {
        if (state.getTime() >= endTime - 1e-9) cost.realizeUs = timeRealization(experiment.getScene().getSystem(), state, realizations);
    };
    const simulation::SimulationSummary r = simulation::runGraspSimulation(s, options, {}, observe).summary;
    cost.stepUs = r.meanStepUs;
    cost.ikUsPerStep = r.ikUsPerStep;
    cost.dynamicsUsPerStep = r.dynamicsUsPerStep;
    return cost;
}

}  // namespace

CostTable measureCostTable(double duration, int realizations, const CostProgress& progress) {
    const auto start = std::chrono::steady_clock::now();
    const auto report = [&](std::size_t done, const std::string& next) { if (progress) progress(done, 7, next); };
    CostTable table;
    for (const char* name : {"ball-clutch", "phone-pinch"}) {
        report(table.experiments.size(), name);
        table.experiments.push_back(measureExperiment(name, duration, realizations));
    }
    for (int count = 2; count <= 5; ++count) {
        report(2 + table.scaling.size(), std::to_string(count) + " end-effectors");
        table.scaling.push_back(measureEndEffectors(count, duration, realizations));
    }
    report(6, "capacity ramps");
    for (const char* name : {"ball-clutch", "phone-pinch"}) {
        const scenario::Scenario s = scenario::findBuiltinScenario(name);
        for (const auto mode : {simulation::SimulationMode::Full, simulation::SimulationMode::Approx}) {
            for (const auto integrator : {simulation::IntegratorChoice::SimbodyCpodes, simulation::IntegratorChoice::LinearlyImplicit}) {
                table.capacity.push_back(measureCapacityCost(s, mode, integrator, integrator == simulation::IntegratorChoice::LinearlyImplicit));
            }
        }
    }
    report(7, "done");
    table.wallTime = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return table;
}

namespace {

// Thesis Table 5.1 (Vortex, 2.7 GHz i7-6820HK): full simulation (IK + dynamics) and the approach, µs per step.
struct ThesisRow {
    const char* scenario;
    double full, ik, dynamics, approx;
};
constexpr ThesisRow kThesis[] = {{"ball-clutch", 4400, 4306, 94, 12}, {"phone-pinch", 2300, 2261, 39, 5}};

std::string line(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string line(const char* format, ...) {
    char buffer[512];
    va_list args;
    va_start(args, format);
    std::vsnprintf(buffer, sizeof buffer, format, args);
    va_end(args);
    return std::string(buffer) + "\n";
}

double ratio(double a, double b) { return b > 0 ? a / b : 0; }

}  // namespace

namespace {

std::string formatStepTable(const CostTable& t) {
    std::string text = line("%-12s %-8s %20s %12s %13s %14s", "experiment", "approx", "full (IK + dyn)", "IK", "dynamics", "approx step");
    for (const ExperimentCost& e : t.experiments) {
        const ThesisRow* th = e.scenario == kThesis[0].scenario ? &kThesis[0] : &kThesis[1];
        for (const ApproxCost& a : e.approx) {
            text += line("%-12s %-8s %9.0f [%6.0f] %5.0f [%4.0f] %6.1f [%3.0f] %6.0f [%3.0f]", e.scenario.c_str(), a.constraint.c_str(),
                         e.fullStepUs, th->full, e.fullIkUsPerStep, th->ik, e.fullDynamicsUsPerStep, th->dynamics, a.stepUs,
                         th->approx);
        }
    }
    return text + "(per integrator step; the engaged integrator takes few, long steps, so per step is no fair comparison)\n\n";
}

std::string formatSimSecondTable(const CostTable& t) {
    std::string text = "Per simulated second (wall-clock s per simulated s; a fixed-step engine's per-step cost, as the thesis's):\n";
    text += line("%-12s %-8s %9s %9s %9s %9s %10s %11s %10s %15s", "experiment", "approx", "full", "1st s", "hold", "floor",
                 "full/hold", "hold/floor", "own floor", "hold/own floor");
    for (const ExperimentCost& e : t.experiments) {
        for (const ApproxCost& a : e.approx) {
            text += line("%-12s %-8s %9.3f %9.4f %9.4f %9.4f %10.1f %11.2f %10.4f %15.2f", e.scenario.c_str(), a.constraint.c_str(),
                         e.fullWallPerSimSecond, a.wallPerSimSecond, a.holdWallPerSimSecond, e.floorHoldWallPerSimSecond,
                         ratio(e.fullWallPerSimSecond, a.holdWallPerSimSecond),
                         ratio(a.holdWallPerSimSecond, e.floorHoldWallPerSimSecond), a.ownFloorHoldWallPerSimSecond,
                         a.holdOverOwnFloor);
        }
    }
    return text + "(full: after the release; 1st s: the first simulated second engaged, with the switch's integrator restart;\n"
                  " hold: the 20 s after it, with the switch's check and an output sample every 10 ms; floor: the grasped\n"
                  " state with fingers and object locked and no contact, in the full-contact run's System (no approximation\n"
                  " elements), integrated 20 s at the same accuracy and report times, no grasp checks; own floor: the same\n"
                  " in the approximation run's System, its constraint off, integrated one simulated second after each second\n"
                  " of hold; hold/own floor: the median over those 20 back-to-back pairs of windows, the ratio least moved\n"
                  " by a machine that slows down for a while; the other figures are medians of 1-s windows. Time spent\n"
                  " timing evaluations during a run is not counted.)\n\n";
}

// Counts, not times: what the wall-time ratios above come to on any machine, noise-free.
std::string formatEvaluationCountTable(const CostTable& t) {
    std::string text = "Dynamics evaluations per simulated second (realizations to Acceleration; counts, the same on any machine):\n";
    text += line("%-12s %-8s %9s %9s %11s %10s %15s", "experiment", "approx", "hold", "floor", "hold/floor", "own floor",
                 "hold/own floor");
    for (const ExperimentCost& e : t.experiments) {
        for (const ApproxCost& a : e.approx) {
            text += line("%-12s %-8s %9.0f %9.0f %11.2f %10.0f %15.2f", e.scenario.c_str(), a.constraint.c_str(),
                         a.holdEvaluationsPerSimSecond, e.floorEvaluationsPerSimSecond,
                         ratio(a.holdEvaluationsPerSimSecond, e.floorEvaluationsPerSimSecond), a.ownFloorEvaluationsPerSimSecond,
                         ratio(a.holdEvaluationsPerSimSecond, a.ownFloorEvaluationsPerSimSecond));
        }
    }
    return text + "(integrator steps, Newton iterations, finite-difference Jacobian columns, event-trigger checks and output\n"
                  " samples each realize the system; hold and floors over the same windows as above)\n\n";
}

std::string formatEvaluationTable(const CostTable& t) {
    std::string text = "One dynamics evaluation (realize to Acceleration), µs:\n";
    text += line("%-12s %-8s %9s %9s %9s %10s %13s %14s %18s", "experiment", "approx", "full", "engaged", "floor", "own floor",
                 "full/engaged", "engaged/floor", "engaged/own floor");
    for (const ExperimentCost& e : t.experiments) {
        for (const ApproxCost& a : e.approx) {
            text += line("%-12s %-8s %9.1f %9.1f %9.1f %10.1f %13.2f %14.2f %18.2f", e.scenario.c_str(), a.constraint.c_str(),
                         a.fullRealizeUs, a.engagedRealizeUs, e.floorRealizeUs, a.ownFloorRealizeUs,
                         ratio(a.fullRealizeUs, a.engagedRealizeUs), ratio(a.engagedRealizeUs, e.floorRealizeUs),
                         ratio(a.engagedRealizeUs, a.ownFloorRealizeUs));
        }
    }
    return text + "(engaged and own floor timed in alternating batches, best of ten each; thesis, contact solving per step:\n"
                  " 94/12 = 7.8x and 39/5 = 7.8x; target >= 10x and engaged <= 1.25x floor)\n\n";
}

std::string formatScalingTable(const CostTable& t) {
    std::string text = "Full contact vs fingertip goals (ball-clutch), µs:\n";
    text += line("%-14s %10s %10s %10s %12s", "end-effectors", "step", "IK", "dynamics", "evaluation");
    for (const EndEffectorCost& c : t.scaling) {
        text += line("%-14d %10.0f %10.1f %10.1f %12.1f", c.endEffectors, c.stepUs, c.ikUsPerStep, c.dynamicsUsPerStep, c.realizeUs);
    }
    return text;
}

}  // namespace

std::string formatCostTable(const CostTable& t) {
    std::vector<StepperCost> steppers;
    for (const ExperimentCost& e : t.experiments) steppers.insert(steppers.end(), e.steppers.begin(), e.steppers.end());
    return "Table 5.1 on this machine (µs per step; thesis figures from Vortex in brackets)\n\n" + formatStepTable(t) +
           formatSimSecondTable(t) + formatEvaluationCountTable(t) + formatEvaluationTable(t) + formatStepperTable(steppers) + formatCapacityCostTable(t.capacity) +
           formatScalingTable(t) + line("\nmeasured in %.1f s", t.wallTime);
}

std::string formatCostTableJson(const CostTable& t) {
    nlohmann::ordered_json j;
    for (const ExperimentCost& e : t.experiments) {
        j["experiments"].push_back({{"scenario", e.scenario},
                                    {"full_step_us", e.fullStepUs},
                                    {"full_ik_us_per_step", e.fullIkUsPerStep},
                                    {"full_dynamics_us_per_step", e.fullDynamicsUsPerStep},
                                    {"full_wall_per_sim_s", e.fullWallPerSimSecond},
                                    {"floor_hold_wall_per_sim_s", e.floorHoldWallPerSimSecond},
                                    {"floor_evaluations_per_sim_s", e.floorEvaluationsPerSimSecond},
                                    {"floor_realize_us", e.floorRealizeUs}});
        for (const ApproxCost& a : e.approx) {
            j["experiments"].back()["approx"].push_back({{"constraint", a.constraint},
                                                         {"step_us", a.stepUs},
                                                         {"wall_per_sim_s", a.wallPerSimSecond},
                                                         {"hold_wall_per_sim_s", a.holdWallPerSimSecond},
                                                         {"own_floor_hold_wall_per_sim_s", a.ownFloorHoldWallPerSimSecond},
                                                         {"hold_evaluations_per_sim_s", a.holdEvaluationsPerSimSecond},
                                                         {"own_floor_evaluations_per_sim_s", a.ownFloorEvaluationsPerSimSecond},
                                                         {"hold_over_own_floor", a.holdOverOwnFloor},
                                                         {"engage_time_s", a.engageTime},
                                                         {"full_realize_us", a.fullRealizeUs},
                                                         {"engaged_realize_us", a.engagedRealizeUs},
                                                         {"own_floor_realize_us", a.ownFloorRealizeUs}});
        }
    }
    for (std::size_t k = 0; k < t.experiments.size(); ++k) {
        for (const StepperCost& r : t.experiments[k].steppers) {
            j["experiments"][k]["steppers"].push_back({{"run", r.run},
                                                       {"wall_per_sim_s", r.wallPerSimSecond},
                                                       {"steps_per_sim_s", r.stepsPerSimSecond},
                                                       {"evaluations_per_sim_s", r.evaluationsPerSimSecond},
                                                       {"jacobians_per_sim_s", r.jacobiansPerSimSecond},
                                                       {"factorizations_per_sim_s", r.factorizationsPerSimSecond},
                                                       {"newton_iterations_per_sim_s", r.newtonPerSimSecond},
                                                       {"restarts_per_sim_s", r.restartsPerSimSecond},
                                                       {"step_us", r.stepUs},
                                                       {"dynamics_us_per_step", r.dynamicsUs},
                                                       {"contact_us_per_step", r.contactUs},
                                                       {"linear_solve_us_per_step", r.linearSolveUs},
                                                       {"ik_us_per_step", r.ikUs},
                                                       {"rest_us_per_step", r.restUs}});
        }
    }
    for (const EndEffectorCost& c : t.scaling) {
        j["end_effector_scaling"].push_back({{"end_effectors", c.endEffectors},
                                             {"step_us", c.stepUs},
                                             {"ik_us_per_step", c.ikUsPerStep},
                                             {"dynamics_us_per_step", c.dynamicsUsPerStep},
                                             {"realize_us", c.realizeUs}});
    }
    for (const CapacityCost& c : t.capacity) {
        j["capacity"].push_back({{"scenario", c.scenario},
                                 {"mode", simulation::toString(c.mode)},
                                 {"integrator", simulation::toString(c.integrator)},
                                 {"ramp_wall_s", c.rampWall},
                                 {"ramp_sim_s", c.rampSimTime},
                                 {"simulation_3s_wall_s", c.simulationWall},
                                 {"all_directions_wall_s", c.allWall},
                                 {"ramp_failure", c.failure}});
    }
    j["wall_time_s"] = t.wallTime;
    return j.dump(2) + "\n";
}

}  // namespace graspsim::validation
