#include "capacity_command.h"

#include "approx_flags.h"
#include "capsule_contact_option.h"
#include "friction_option.h"
#include "number_option.h"
#include "output_folder.h"

#include "graspsim/planning/planned_scenario.h"
#include "graspsim/capacity/capacity_files.h"
#include "graspsim/capacity/capacity_plot.h"
#include "graspsim/capacity/capacity_trace.h"
#include "graspsim/capacity/compliance_prediction.h"
#include "graspsim/capacity/load_direction.h"
#include "graspsim/capacity/method_options.h"
#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/capacity/settled_grasps.h"
#include "graspsim/io/parallel_runs.h"
#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/multi_attachment_switch.h"
#include "graspsim/simulation/setup_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <mutex>
#include <optional>

namespace graspsim::cli {

struct CapacityCommand::Options {
    std::string scenario;
    std::string direction = "-y";
    bool torque = false;
    bool rolling = false;
    std::string rate;
    std::string method = "ramp";
    std::string maxDuration = "4";
    std::string initialLoad;
    std::string hold = "1";
    std::string load;
    std::string guess;
    std::string slipThreshold;
    std::string dropThreshold;
    std::string contact = "compliant";
    std::string friction;
    std::string capsuleContact;
    std::string mode = "full";
    ApproxFlags approx;
    std::string releaseSlide;
    std::string releasePenetration;
    std::string limitsFriction;
    std::string accuracy;
    std::string integrator = "auto";
    std::string stepSize;
    std::string jobs = "1";
    std::string out;
};

// The checked options: what to measure along which directions.
struct CapacityCommand::Plan {
    simulation::SimulationOptions simulation;
    std::vector<capacity::GraspCapacityRequest> requests;
    bool bisection = false;
    bool compliance = false;  // predicted by the compliance model, not measured
    bool rolling = false;     // the model with the contacts' rolling stiffness
    bool constant = false;    // one constant load (`load`), held `hold` s
    /// With --direction all, --rate is the forces' rate; the torques' is scaled from it by the
    /// default rates' ratio (a lever, m).
    bool torqueRateFromForceRate = false;
    double hold = 1, guess = 0, load = 0;
    std::optional<contact::FrictionModel> friction;  // --friction, over the scenario's
    std::optional<contact::CapsuleContact> capsuleContact;  // --capsule-contact, over the scenario's
    int jobs = 1;  // directions measured at once
};

CapacityCommand::CapacityCommand(CLI::App& app) : options_(std::make_shared<Options>()) {
    Options& o = *options_;
    command_ = app.add_subcommand("capacity", "Measure how large a load on the object the grasp holds before it slips and drops");
    command_->add_option("scenario", o.scenario, "built-in scenario (" + scenario::joinBuiltinScenarioNames() + ") or a scenario file")->required();
    command_->add_option("--direction", o.direction,
                         "x, y, z, -x, -y, -z (default -y), a vector such as 0,-1,0 (G), or all: the six axes and torques about x, y, z");
    command_->add_flag("--torque", o.torque, "a torque about the object's centre of mass instead of a force");
    command_->add_option("--rate", o.rate, "ramp rate, N/s (N m/s with --torque), > 0 (default: 2 object weights per second; with --direction all "
                         "the forces' rate, the torques' scaled by the farthest goal's distance)");
    command_->add_option("--method", o.method, "ramp (default), bisection (constant loads, --hold s each), constant (one --load "
                         "held --hold s: when the object slips and drops) or compliance (predicted by the grasp's compliance "
                         "model from full contact at the load's start; docs/capacity.md)");
    command_->add_option("--accuracy", o.accuracy, "integrator relative accuracy in (0, 1) (default: the scenario's)");
    command_->add_option("--integrator", o.integrator,
                         "compliant contact: auto (default: implicit, but simbody for --constraint weld, --attach "
                         "multi and the scenario's anchor friction), simbody (CPodes BDF), cvode, implicit (linearly implicit, error-controlled steps up to "
                         "--step-size) or implicit-fixed");
    command_->add_option("--step-size", o.stepSize,
                         "implicit: longest step, implicit-fixed: the step, in s, > 0 (default: the scenario's simulation.step_size)");
    command_->add_option("--max-duration", o.maxDuration, "ramp: longest ramp, s (default 4)");
    command_->add_option("--initial-load", o.initialLoad,
                         "ramp: a load applied at once at the ramp's start, from which the ramp grows (N, N m with --torque; default 0)");
    command_->add_option("--hold", o.hold, "bisection, constant: how long each constant load is held, s (default 1)");
    command_->add_option("--load", o.load, "constant: the load, N (N m with --torque), > 0, applied at once at the load's start");
    command_->add_option("--guess", o.guess, "bisection: first load to try, N or N m (default: rate x 1 s)");
    command_->add_option("--slip-threshold", o.slipThreshold,
                         "slip onset: the object's slip relative to the palm, at the grasp goals, that counts as slipping, m "
                         "(default 0.002; --method compliance predicts the load at it too)");
    command_->add_option("--drop-threshold", o.dropThreshold,
                         "drop: the slip that counts as dropped (so does the scenario's held criterion failing), m, "
                         "above --slip-threshold (default 0.02)");
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
    command_->add_option("--release-slide", o.releaseSlide,
                         "approx: release when the object slid this far in the hand, m (default 0.005)");
    command_->add_option("--release-penetration", o.releasePenetration,
                         "approx: release when a fingertip sank this much deeper into the object, m (default 0.0005)");
    command_->add_option("--limits-friction", o.limitsFriction,
                         "approx: the friction coefficient of the constraint's limits, dynamic or static (default: dynamic, "
                         "static for --limits compliance)");
    command_->add_flag("--rolling", o.rolling,
                       "compliance: the model adds the contacts' rolling stiffness (their forces turning as the object rolls "
                       "on the pads; research option, docs/capacity.md); default: the contacts' geometry frozen");
    command_->add_option("--jobs", o.jobs,
                         "directions measured at once, each on its own thread (default 1; the figures do not depend on it)");
    command_->add_option("--out", o.out, "output folder; receives capacity.json and capacity.csv (default: none written)");
}

bool CapacityCommand::parsed() const { return command_->parsed(); }

namespace {

// The slip onset and drop distances (m): both > 0, the onset below the drop. A refusal of the
// pair names the flag given (--slip-threshold when both are).
capacity::SlipCriteria parseSlipCriteria(const std::string& slipText, const std::string& dropText) {
    capacity::SlipCriteria criteria;
    criteria.slip = parsePositiveNumber(slipText, "--slip-threshold", "m").value_or(criteria.slip);
    criteria.drop = parsePositiveNumber(dropText, "--drop-threshold", "m").value_or(criteria.drop);
    const bool slipGiven = !slipText.empty();
    capacity::checkSlipCriteria(criteria, slipGiven ? "--slip-threshold" : "--drop-threshold", slipGiven ? slipText : dropText);
    return criteria;
}

std::vector<capacity::GraspCapacityRequest> makeRequests(const std::string& direction, bool torque) {
    if (direction != "all") {
        const capacity::LoadDirection d = capacity::parseLoadDirection(direction, "--direction");
        capacity::GraspCapacityRequest r;
        r.direction = d.direction;
        r.directionName = d.name;
        r.torque = torque;
        return {r};
    }
    // all is the six forces and the three torques: --torque would read as "the torques only".
    if (torque) throw InputError("--torque: is not accepted with --direction all, which measures the six axis forces and the three torques");
    return capacity::makeAllDirectionRequests();
}

// The request's rate as given, except a torque's with --direction all: scaled from the forces'.
double findRate(const scenario::Scenario& scenario, bool torqueRateFromForceRate, const capacity::GraspCapacityRequest& r) {
    if (r.torque && r.rate > 0 && torqueRateFromForceRate) {
        return r.rate * capacity::findDefaultRate(scenario, true) / capacity::findDefaultRate(scenario, false);
    }
    return r.rate;
}

// --method compliance predicts from full contact run to the load's start on CPodes, and prints.
void checkComplianceMethodOptions(const std::string& method, const std::string& out, const std::string& integratorText,
                                  simulation::IntegratorChoice integrator) {
    if (method != "compliance") return;
    using simulation::IntegratorChoice;
    if (integrator != IntegratorChoice::Automatic && integrator != IntegratorChoice::SimbodyCpodes) {
        throw InputError("--integrator: value '" + integratorText + "' is not accepted with --method compliance, which runs "
                         "full contact to the load's start on CPodes; use simbody or leave --integrator out");
    }
    if (!out.empty()) throw InputError("--out: --method compliance writes no files; leave --out out");
}

// The method's own load options (method_options.h): one left unused would be silently ignored.
// A constant load is one load for one direction (N or N m).
void checkMethodFlags(const CLI::App& command, const std::string& method, const std::string& direction, const std::string& mode) {
    std::vector<std::string> given;
    const auto flagOf = [](std::string name) {
        std::replace(name.begin(), name.end(), '_', '-');
        return "--" + name;
    };
    for (const std::string& name : capacity::findMethodOptionNames()) {
        if (command.count(flagOf(name)) > 0) given.push_back(name);
    }
    capacity::checkMethodOptions(method, given, flagOf, "--method");
    if (method == "constant" && direction == "all") {
        throw InputError("--direction: value all is not accepted with --method constant (one load, N or N m, for one "
                         "direction); use an axis or a vector");
    }
    if (method != "compliance" && command.count("--rolling") > 0) {
        throw InputError("--rolling: only with --method compliance (the compliance model's rolling stiffness), not --method " + method);
    }
    if (method == "compliance" && mode == "approx") {
        throw InputError("--mode: value approx is not accepted with --method compliance, which predicts from full contact at the "
                         "load's start");
    }
}

}  // namespace

CapacityCommand::Plan CapacityCommand::makePlan() const {
    const Options& o = *options_;
    Plan plan;
    plan.simulation.contact = simulation::parseContactModel(o.contact, "--contact");
    plan.friction = parseFrictionOption(o.friction, plan.simulation.contact);
    plan.capsuleContact = parseCapsuleContactOption(o.capsuleContact, plan.simulation.contact);
    plan.simulation.mode = simulation::parseSimulationMode(o.mode, "--mode");
    std::vector<std::string> approxOnly = getApproxFlagNames();
    approxOnly.insert(approxOnly.end(), {"--release-slide", "--release-penetration", "--limits-friction"});
    checkApproxOnlyOptions(*command_, o.mode, approxOnly);
    plan.simulation.accuracy = parseAccuracy(o.accuracy);
    plan.simulation.integrator = simulation::parseIntegratorChoice(o.integrator, "--integrator");
    plan.simulation.stepSize = parseStepSize(o.stepSize);
    parseApproxFlags(o.approx, plan.simulation.approx);
    plan.simulation.approx.releaseSlideDistance =
        parsePositiveNumber(o.releaseSlide, "--release-slide", "m").value_or(simulation::ApproxOptions{}.releaseSlideDistance);
    plan.simulation.approx.releasePenetration =
        parsePositiveNumber(o.releasePenetration, "--release-penetration", "m").value_or(simulation::ApproxOptions{}.releasePenetration);
    if (!o.limitsFriction.empty() && o.limitsFriction != "dynamic" && o.limitsFriction != "static") {
        throw InputError("--limits-friction: value '" + o.limitsFriction + "' is not accepted; use dynamic or static");
    }
    if (!o.limitsFriction.empty()) plan.simulation.approx.staticFrictionLimits = o.limitsFriction == "static";
    if (o.method != "ramp" && o.method != "bisection" && o.method != "constant" && o.method != "compliance") {
        throw InputError("--method: value '" + o.method + "' is not accepted; use ramp, bisection, constant or compliance");
    }
    plan.bisection = o.method == "bisection";
    plan.compliance = o.method == "compliance";
    plan.rolling = o.rolling;
    plan.constant = o.method == "constant";
    checkMethodFlags(*command_, o.method, o.direction, o.mode);
    plan.load = parsePositiveNumber(o.load, "--load", "N, or N m with --torque").value_or(0);
    checkComplianceMethodOptions(o.method, o.out, o.integrator, plan.simulation.integrator);
    const double rate = parsePositiveNumber(o.rate, "--rate", "N/s, or N m/s with --torque").value_or(0);
    const double maxDuration = parsePositiveNumber(o.maxDuration, "--max-duration", "s").value_or(4);
    const double initialLoad = parseNonNegativeNumber(o.initialLoad, "--initial-load", "N, or N m with --torque");
    const capacity::SlipCriteria criteria = parseSlipCriteria(o.slipThreshold, o.dropThreshold);
    plan.hold = parsePositiveNumber(o.hold, "--hold", "s").value_or(1);
    plan.guess = parsePositiveNumber(o.guess, "--guess", "N, or N m with --torque").value_or(0);
    plan.requests = makeRequests(o.direction, o.torque);
    for (capacity::GraspCapacityRequest& r : plan.requests) {
        r.rate = rate;
        r.maxRampDuration = maxDuration;
        r.initialLoad = initialLoad;
        r.criteria = criteria;
    }
    plan.torqueRateFromForceRate = o.direction == "all";
    plan.jobs = parseCount(o.jobs, "--jobs");
    return plan;
}

void CapacityCommand::checkOptions() const { makePlan(); }

std::vector<capacity::GraspCapacity> CapacityCommand::measureAll(const scenario::Scenario& scenario, const Plan& plan) const {
    std::vector<std::optional<capacity::GraspCapacity>> measured(plan.requests.size());
    std::mutex printing;
    std::size_t printed = 0;  // lines are printed in the requests' order, each once it and those before it are done
    capacity::SettledGrasps grasps(scenario, plan.simulation);  // the directions share the settled grasp
    io::runInParallel(plan.requests.size(), plan.jobs, [&](std::size_t k) {
        capacity::GraspCapacityRequest r = plan.requests[k];
        r.rate = findRate(scenario, plan.torqueRateFromForceRate, r);
        capacity::GraspCapacity c;
        if (plan.constant) {
            c = capacity::measureGraspCapacityConstant(grasps, r, plan.load, plan.hold);
        } else if (plan.bisection) {
            const double rate = r.rate > 0 ? r.rate : capacity::findDefaultRate(scenario, r.torque);
            c = capacity::measureGraspCapacityBisection(grasps, r, plan.guess > 0 ? plan.guess : rate, plan.hold);
        } else {
            c = capacity::measureGraspCapacityRamp(grasps, r);
        }
        const std::lock_guard<std::mutex> lock(printing);
        measured[k] = std::move(c);
        for (; printed < measured.size() && measured[printed]; ++printed) {
            std::cout << scenario.name << " " << capacity::describeCapacity(*measured[printed]) << " [" << measured[printed]->wallTime
                      << " s wall]" << std::endl;
        }
    });
    std::vector<capacity::GraspCapacity> measurements;
    for (std::optional<capacity::GraspCapacity>& m : measured) measurements.push_back(std::move(*m));
    return measurements;
}

int CapacityCommand::run() const {
    const Options& o = *options_;
    const Plan plan = makePlan();
    scenario::Scenario scenario = planning::loadScenario(o.scenario);
    if (plan.friction) scenario.friction.model = *plan.friction;
    if (plan.capsuleContact) scenario.contact.capsuleContact = *plan.capsuleContact;
    simulation::checkApproxAttach(scenario, plan.simulation);
    for (const capacity::GraspCapacityRequest& r : plan.requests) capacity::checkLoadResistible(scenario, r);
    simulation::checkScenarioSetup(scenario, plan.simulation);  // before the folder exists
    if (plan.compliance) {
        std::vector<capacity::GraspCapacityRequest> requests = plan.requests;
        for (capacity::GraspCapacityRequest& r : requests) r.rate = findRate(scenario, plan.torqueRateFromForceRate, r);
        capacity::CompliancePredictionSettings settings;
        settings.rolling = plan.rolling;
        for (const capacity::CompliancePrediction& p : capacity::predictGraspCapacities(scenario, plan.simulation, requests, settings)) {
            std::cout << scenario.name << " " << capacity::describePrediction(p) << "\n";
        }
        return 0;
    }
    std::optional<OutputFolder> folder;  // gone again if a measurement throws (a step size it cannot use, ...)
    if (!o.out.empty()) folder.emplace(o.out);
    const std::vector<capacity::GraspCapacity> measurements = measureAll(scenario, plan);
    if (folder) folder->keep();
    if (!o.out.empty()) capacity::writeCapacityFiles(o.out, scenario.name, measurements);
    if (!o.out.empty() && o.direction == "all") {
        const capacity::CapacityPlot plot = capacity::drawCapacityPlot(o.out);
        std::cout << (plot.skipped.empty() ? "plot: " + plot.file : plot.skipped) << "\n";
    } else if (!o.out.empty()) {  // an earlier --direction all's plot would show other measurements
        for (const char* name : {"/capacity.png", "/plot_capacity.py"}) io::removeStaleFile(o.out + name);
    }
    const capacity::GraspCapacity& first = measurements.front();
    std::string last = "capacity of " + scenario.name + " (" + simulation::toString(first.contact) +
                       (first.friction ? ", " + contact::toString(*first.friction) + " friction" : "") +
                       (first.capsuleContact ? ", capsules at " + contact::toString(*first.capsuleContact) : "") + ", " +
                       simulation::toString(first.mode) +
                       (first.realization.empty() ? "" : ", " + first.realization) + "): ";
    for (std::size_t k = 0; k < measurements.size(); ++k) last += (k ? "; " : "") + capacity::describeCapacity(measurements[k]);
    std::cout << last << (o.out.empty() ? "" : "; files in " + o.out) << "\n";
    for (const capacity::GraspCapacity& c : measurements) {
        if (!c.trace.failure.empty()) {
            std::cerr << "graspsim: a capacity run stopped early (" << c.directionName << "): " << c.trace.failure << "\n";
            return 3;
        }
    }
    return 0;
}

}  // namespace graspsim::cli
