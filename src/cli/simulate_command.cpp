#include "simulate_command.h"

#include "approx_flags.h"
#include "capsule_contact_option.h"
#include "friction_option.h"
#include "number_option.h"
#include "output_folder.h"
#include "progress_meter.h"

#include "graspsim/capacity/grasp_capacity.h"
#include "graspsim/capacity/load_direction.h"
#include "graspsim/planning/planned_scenario.h"
#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/opensim/opensim_storage.h"
#include "graspsim/results/result_folder.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_simulation.h"
#include "graspsim/viewer/replay_page.h"
#include "graspsim/simulation/setup_check.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <chrono>
#include <iostream>
#include <sstream>

namespace graspsim::cli {

struct SimulateCommand::Options {
    std::string scenario;
    std::string contact = "compliant";
    std::string friction;
    std::string capsuleContact;
    std::string mode = "full";
    ApproxFlags approx;
    std::string perturbation = "none";
    std::string duration;
    std::string integrator = "auto";
    std::string accuracy;
    std::string stepSize;
    std::string qThreshold;
    std::string ramp, rampRate;
    bool rampTorque = false;
    std::string out = "out";
    bool view = false;
    bool quiet = false;
};

SimulateCommand::SimulateCommand(CLI::App& app) : options_(std::make_shared<Options>()) {
    Options& o = *options_;
    command_ = app.add_subcommand("simulate", "Simulate a grasp scenario (full contact or the grasp approximation) and write the results");
    command_->add_option("scenario", o.scenario, "built-in scenario (" + scenario::joinBuiltinScenarioNames() + ") or a scenario file")->required();
    command_->add_option("--contact", o.contact, "compliant (default) or rigid");
    command_->add_option("--friction", o.friction,
                         "compliant contact's friction law, regularized or anchor (true stiction; default: the "
                         "scenario's contact.friction_model, itself regularized by default)");
    command_->add_option("--capsule-contact", o.capsuleContact,
                         "where a capsule (a phalanx) presses on a solid in compliant contact, deepest (one point, "
                         "default: the scenario's contact.capsule_contact) or ends (each end of its core: continuous as it "
                         "tilts through lying flat; docs/contact.md)");
    command_->add_option("--mode", o.mode, "full (default) or approx");
    addApproxFlags(*command_, o.approx);
    command_->add_option("--perturbation", o.perturbation, "none (default) or a perturbation of the scenario (f1, f2)");
    command_->add_option("--ramp", o.ramp,
                         "also a load on the object growing from zero at the load start of graspsim capacity (settle_time + 0.1 s): "
                         "its direction, an axis (x, -y, ...) or X,Y,Z in the ground frame (a capacity ramp to watch with --view)");
    command_->add_option("--ramp-rate", o.rampRate, "--ramp's rate, N/s (N m/s with --ramp-torque), > 0 (default: capacity's, 2 object weights per second)");
    command_->add_flag("--ramp-torque", o.rampTorque, "--ramp is a torque about the object's centre of mass instead of a force");
    command_->add_option("--duration", o.duration, "simulated time in s (default: the scenario's)");
    command_->add_option("--integrator", o.integrator,
                         "auto (default: implicit, but simbody for --constraint weld, --attach multi and --friction "
                         "anchor), simbody "
                         "(Simbody's CPodes BDF), cvode (the SUNDIALS CVODE BDF reference), implicit (linearly implicit "
                         "Rosenbrock with analytic contact Jacobians, error-controlled steps up to --step-size; compliant "
                         "contact) or implicit-fixed (the same at fixed steps)");
    command_->add_option("--step-size", o.stepSize,
                         "implicit: longest step, implicit-fixed: the step, in s, > 0 (default: the scenario's simulation.step_size, 0.005)");
    command_->add_option("--accuracy", o.accuracy, "integrator relative accuracy in (0, 1) (default: the scenario's)");
    command_->add_option("--q-threshold", o.qThreshold, "approx: grasp quality Q_Th (N) to engage (default: 0.8 x the settled grasp's)");
    command_->add_option("--out", o.out,
                         "output folder (default out); receives trajectory.csv, contacts.csv, summary.json, scenario.yaml, "
                         "model.urdf, provenance.json (and events.csv, constraint.csv in approx mode), and for OpenSim "
                         "motion.mot, object_forces.sto and external_loads.xml");
    command_->add_flag("-q,--quiet", o.quiet, "no progress display (it appears only on a terminal anyway)");
    command_->add_flag("--view", o.view, "also write the 3-D replay, replay.html, into the output folder (as graspsim view)");
}

bool SimulateCommand::parsed() const { return command_->parsed(); }

namespace {

// The perturbation must be one of the scenario's.
void checkPerturbation(const std::string& perturbation, const scenario::Scenario& scenario) {
    if (perturbation == "none" || scenario.findPerturbation(perturbation)) return;
    std::string known;
    for (const auto& p : scenario.perturbations) known += (known.empty() ? "" : ", ") + p.name;
    throw InputError("--perturbation: '" + perturbation + "' is not accepted; scenario '" + scenario.name +
                     "' has none, " + known);
}

// Simulated time as progress: on a terminal only, unless --quiet.
simulation::ProgressCallback makeProgress(ProgressMeter& meter) {
    if (!meter.isShown()) return {};
    return [&meter](double t, double duration) {
        char detail[64];
        std::snprintf(detail, sizeof detail, "t = %.3f / %.3f s", t, duration);
        meter.update(t, duration, detail);
    };
}

}  // namespace

simulation::SimulationOptions SimulateCommand::parseOptions() const {
    const Options& o = *options_;
    simulation::SimulationOptions options;
    options.contact = simulation::parseContactModel(o.contact, "--contact");
    parseFrictionOption(o.friction, options.contact);  // refused before any work
    parseCapsuleContactOption(o.capsuleContact, options.contact);
    options.mode = simulation::parseSimulationMode(o.mode, "--mode");
    std::vector<std::string> approxOnly = getApproxFlagNames();
    approxOnly.push_back("--q-threshold");
    checkApproxOnlyOptions(*command_, o.mode, approxOnly);
    options.duration = parsePositiveNumber(o.duration, "--duration", "s").value_or(0);  // 0: the scenario's
    options.integrator = simulation::parseIntegratorChoice(o.integrator, "--integrator");
    options.accuracy = parseAccuracy(o.accuracy);
    options.stepSize = parseStepSize(o.stepSize);
    parseApproxFlags(o.approx, options.approx);
    options.approx.qThreshold = parsePositiveNumber(o.qThreshold, "--q-threshold", "N").value_or(0);  // 0: automatic
    if (options.approx.qThreshold > 0 && options.approx.qMinimum >= options.approx.qThreshold) {
        throw InputError("--q-minimum: value " + o.approx.qMinimum + " is not accepted; Q_M must be below --q-threshold " + o.qThreshold);
    }
    return options;
}

void SimulateCommand::checkOptions() const {
    parseOptions();
    parseRampDirection();
}

// --ramp's direction; its rate and torque flag need it.
std::optional<capacity::LoadDirection> SimulateCommand::parseRampDirection() const {
    const Options& o = *options_;
    if (o.ramp.empty()) {
        for (const char* flag : {"--ramp-rate", "--ramp-torque"}) {
            if (command_->count(flag) > 0) throw InputError(std::string(flag) + ": is not accepted without --ramp (the load's direction)");
        }
        return std::nullopt;
    }
    if (o.ramp == "all") throw InputError("--ramp: value 'all' is not accepted; give one direction (graspsim capacity --direction all measures all)");
    const capacity::LoadDirection direction = capacity::parseLoadDirection(o.ramp, "--ramp");
    parsePositiveNumber(o.rampRate, "--ramp-rate", "N/s");
    return direction;
}

// The capacity protocol's ramp on this scenario: its load start, and its default rate unless given.
simulation::LoadRampSpec SimulateCommand::makeRamp(const capacity::LoadDirection& direction, const scenario::Scenario& scenario) const {
    const Options& o = *options_;
    capacity::GraspCapacityRequest request;
    request.direction = direction.direction;
    request.directionName = direction.name;
    request.torque = o.rampTorque;
    capacity::checkLoadResistible(scenario, request, {"--ramp", "--ramp-torque"});
    simulation::LoadRampSpec ramp;
    ramp.direction = direction.direction;
    ramp.torque = o.rampTorque;
    ramp.start = capacity::findLoadStart(scenario);
    ramp.rate = parsePositiveNumber(o.rampRate, "--ramp-rate", "N/s").value_or(capacity::findDefaultRate(scenario, o.rampTorque));
    const double duration = parsePositiveNumber(o.duration, "--duration", "s").value_or(scenario.simulation.duration);
    if (!(duration > ramp.start)) {
        char text[200];
        std::snprintf(text, sizeof text, "--ramp: the load starts at %.4g s (simulation.settle_time + %.4g s), not before the run's end at %.4g s; "
                      "give a longer --duration", ramp.start, capacity::kLoadStartDelay, duration);
        throw InputError(text);
    }
    return ramp;
}

namespace {

// A number as it reads back, or "scenario" for 0: the
// scenario's own value, which scenario.yaml records.
std::string formatOverride(double value) {
    if (value <= 0) return "scenario";
    // The shortest of 15 or 17 significant digits that reads back to the same double.
    char text[32];
    std::snprintf(text, sizeof text, "%.15g", value);
    if (std::strtod(text, nullptr) != value) std::snprintf(text, sizeof text, "%.17g", value);
    return text;
}

// "-y force 1.962 N/s from 1.1 s": the load --ramp added (provenance.json, the last line).
std::string describeRamp(const std::string& direction, const simulation::LoadRampSpec& ramp) {
    char text[160];
    std::snprintf(text, sizeof text, "%s %s %.4g %s from %.4g s", direction.c_str(), ramp.torque ? "torque" : "force", ramp.rate,
                  ramp.torque ? "N m/s" : "N/s", ramp.start);
    return text;
}

// The per-run choices of provenance.json, as the options were given (defaults written out).
results::RunProvenance makeRunProvenance(const std::vector<std::string>& commandLine, const scenario::Scenario& scenario,
                                         const simulation::SimulationOptions& options, const std::string& ramp) {
    results::RunProvenance run;
    run.commandLine = commandLine;
    run.run["contact"] = simulation::toString(options.contact);
    run.run["mode"] = simulation::toString(options.mode);
    run.run["perturbation"] = options.perturbation;
    if (!ramp.empty()) run.run["ramp"] = ramp;
    const simulation::IntegratorChoice integrator = simulation::resolveIntegrator(scenario, options);
    run.run["integrator"] = simulation::toString(integrator);
    run.run["duration_s"] = formatOverride(options.duration);
    run.run["accuracy"] = formatOverride(options.accuracy);
    if (integrator >= simulation::IntegratorChoice::LinearlyImplicit) run.run["step_size_s"] = formatOverride(options.stepSize);
    if (options.mode == simulation::SimulationMode::Approx) {
        run.run["constraint"] = simulation::toString(options.approx.constraint);
        run.run["attach"] = simulation::toString(options.approx.attach);
        run.run["q_threshold_n"] = formatOverride(options.approx.qThreshold);
        run.run["q_minimum_n"] = formatOverride(options.approx.qMinimum);
        run.run["limits"] = grasp::toString(options.approx.limitModel);
        const simulation::ApproxOptions approx = simulation::resolveApproxOptions(options.approx, scenario.approximation);
        run.run["release_at"] = simulation::toString(approx.releaseTrigger);
        if (options.approx.handBack != simulation::ApproxHandBack::Engaged) run.run["hand_back"] = simulation::toString(options.approx.handBack);
        if (options.approx.releaseCreep) run.run["release_creep"] = *options.approx.releaseCreep ? "on" : "off";
        run.run["bushing_give"] = simulation::toString(approx.bushingGive);
    }
    return run;
}

// Held and the drift after settling, or why they tell nothing: a run that ends while the object is
// still fixed for the approach has tested no hold, and one that ends before the settle time has
// no drift after it.
std::string describeHold(const scenario::Scenario& scenario, const simulation::SimulationSummary& s) {
    std::ostringstream text;
    const double approach = scenario.controller.approachTime, settle = scenario.simulation.settleTime;
    if (s.simTime < approach) {
        text << "hold not tested (the object is fixed for the approach until " << approach << " s)";
        return text.str();
    }
    text << "held " << (s.held ? "yes" : "no");
    if (s.simTime < settle) {
        text << " (the run ended before the settle time, " << settle << " s: no drift after settling measured)";
    } else {
        text << ", object moved " << s.objectDisplacement * 1000 << " mm after settling";
    }
    return text.str();
}

// The run's summary line, and the approximation's line in approx mode.
void printRunResult(const scenario::Scenario& scenario, const simulation::SimulationResult& result,
                    const simulation::SimulationOptions& options, const std::string& ramp, const std::string& out) {
    const simulation::SimulationSummary& s = result.summary;
    std::cout << scenario.name << " (" << simulation::toString(s.contact) << ", " << simulation::toString(s.mode) << ", perturbation " << s.perturbation
              << (ramp.empty() ? "" : ", ramp " + ramp) << "): " << s.simTime << " s simulated in " << s.wallTime << " s, " << s.steps << " steps, "
              << describeHold(scenario, s) << "; results in " << out << "\n";
    if (s.mode == simulation::SimulationMode::Approx) {
        std::cout << "approximation (" << simulation::toString(options.approx.constraint) << ", "
                  << simulation::toString(options.approx.attach) << "): " << (s.engaged ? "engaged at t = " + std::to_string(s.engageTime) + " s" : "never engaged")
                  << (!s.engaged && !s.engageObstacleAtEnd.empty() ? " (at the end: " + s.engageObstacleAtEnd + ")" : "")
                  << ", " << result.events.size() << " switch event(s) in events.csv\n";
    }
}

}  // namespace

int SimulateCommand::run(const std::vector<std::string>& commandLine) const {
    const Options& o = *options_;
    simulation::SimulationOptions options = parseOptions();
    scenario::Scenario scenario = scenario::loadScenario(o.scenario);
    const auto planStart = std::chrono::steady_clock::now();
    const bool planned = !scenario.graspType.empty();
    planning::completeScenario(scenario);  // plans the grasp if the file asks for one
    const double planTime = planned ? std::chrono::duration<double>(std::chrono::steady_clock::now() - planStart).count() : 0.0;
    if (const auto friction = parseFrictionOption(o.friction, options.contact)) scenario.friction.model = *friction;  // scenario.yaml records it
    if (const auto rule = parseCapsuleContactOption(o.capsuleContact, options.contact)) scenario.contact.capsuleContact = *rule;
    checkPerturbation(o.perturbation, scenario);
    options.perturbation = o.perturbation;
    if (const auto direction = parseRampDirection()) options.loadRamp = makeRamp(*direction, scenario);
    const std::string ramp = options.loadRamp ? describeRamp(o.ramp, *options.loadRamp) : "";
    simulation::checkApproxAttach(scenario, options);
    simulation::checkScenarioSetup(scenario, options);  // refuses a grasp that cannot start before the folder exists
    OutputFolder folder(o.out);  // gone again if the run throws (a step size it cannot use, ...)
    ProgressMeter meter("simulating", o.quiet);
    simulation::SimulationResult result = simulation::runGraspSimulation(scenario, options, makeProgress(meter));
    folder.keep();
    result.summary.planTime = planTime;
    meter.finish();
    results::writeResultFolder(o.out, scenario, result, makeRunProvenance(commandLine, scenario, options, ramp));
    opensim::writeOpenSimResultFiles(o.out, result);
    const std::string replay = o.view ? viewer::writeReplayPage(o.out) : "";
    if (!o.view) io::removeStaleFile(o.out + "/replay.html");  // an earlier run's replay would show another run
    io::removeStaleFile(o.out + "/replay.png");  // and so would its picture (graspsim view --png)
    printRunResult(scenario, result, options, ramp, o.out);
    // The run's result first, where a reader looks; the last line points at the replay.
    if (!replay.empty()) std::cout << "replay written to " << replay << ": open it in a web browser\n";
    if (!result.summary.complete) {
        std::cerr << "graspsim: simulation stopped early: " << result.summary.failure << " (summary.json is marked incomplete)\n";
        return 3;
    }
    return 0;
}

}  // namespace graspsim::cli
