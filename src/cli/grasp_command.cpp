#include "grasp_command.h"

#include "number_option.h"
#include "output_file.h"

#include "graspsim/anthropometry/sex.h"
#include "graspsim/anthropometry/subject.h"
#include "graspsim/error.h"
#include "graspsim/io/atomic_file.h"
#include "graspsim/planning/grasp_planner.h"
#include "graspsim/planning/planned_scenario.h"
#include "graspsim/simulation/grasp_simulation.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <iterator>
#include <sstream>

namespace graspsim::cli {

struct GraspCommand::Options {
    std::string sex = "male", mass, stature, preset = "thesis";
    std::string object, type = "power-sphere", output, name;
    bool noHoldCheck = false;
};

namespace {

// Every shape `--object` accepts, with its fields: one list for the parser, the help and the
// error messages, so that none of them names fewer shapes than the others.
struct ObjectForm {
    const char* shape;
    scenario::ObjectShape kind;
    const char* fields;
};
constexpr ObjectForm kObjectForms[] = {
    {"sphere", scenario::ObjectShape::Sphere, "radius=R,mass=M"},
    {"box", scenario::ObjectShape::Box, "size=XxYxZ,mass=M"},
    {"cylinder", scenario::ObjectShape::Cylinder, "radius=R,length=L,mass=M"},
    {"capsule", scenario::ObjectShape::Capsule, "radius=R,length=L,mass=M"},
    {"ellipsoid", scenario::ObjectShape::Ellipsoid, "semi_axes=AxBxC,mass=M"},
};

// "sphere:radius=R,mass=M, box:size=XxYxZ,mass=M, ... or ellipsoid:semi_axes=AxBxC,mass=M".
std::string listObjectForms() {
    std::string list;
    const std::size_t count = std::size(kObjectForms);
    for (std::size_t i = 0; i < count; ++i) {
        list += std::string(i == 0 ? "" : i + 1 == count ? " or " : ", ") + kObjectForms[i].shape + ":" + kObjectForms[i].fields;
    }
    return list;
}

}  // namespace

GraspCommand::GraspCommand(CLI::App& app) : options_(std::make_shared<Options>()) {
    grasp_ = app.add_subcommand("grasp", "Plan grasps");
    grasp_->require_subcommand(0, 1);
    Options& o = *options_;
    plan_ = grasp_->add_subcommand("plan", "Plan a grasp (pose, object placement, goals) and write it as a scenario file");
    plan_->add_option("--sex", o.sex, "male or female (default male)");
    plan_->add_option("--mass", o.mass, "body mass in kg, 20 to 250 (default: de Leva reference subject)");
    plan_->add_option("--stature", o.stature, "stature in m, 1.0 to 2.5 (default: de Leva reference subject)");
    plan_->add_option("--preset", o.preset, "thesis (default: finger segments 20 g, palm 250 g, arm 5.45 kg) or none");
    plan_->add_option("--object", o.object, "the object: " + listObjectForms() + " (m, kg)")->required();
    plan_->add_option("--type", o.type, "power-sphere (default), pinch, tripod, power-cylinder or lateral");
    plan_->add_option("--name", o.name, "the scenario's name (default planned-<type>)");
    plan_->add_option("-o,--output", o.output, "scenario file to write")->required();
    plan_->add_flag("--no-hold-check", o.noHoldCheck,
                    "write the plan without first simulating it (full contact, under gravity, to 0.5 s after its settle time) "
                    "to check that it holds its object");
}

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
    std::vector<std::string> parts;
    std::istringstream in(text);
    for (std::string part; std::getline(in, part, separator);) parts.push_back(part);
    return parts;
}

// "--object sphere:radius=0.045,mass=0.2" or "box:size=0.07x0.14x0.008,mass=0.1".
scenario::ObjectSpec parseObject(const std::string& text) {
    const std::string accepted = "accepted: " + listObjectForms() + " (m, kg, each > 0)";
    const size_t colon = text.find(':');
    scenario::ObjectSpec object;
    const std::string shape = text.substr(0, colon);
    const auto known = std::find_if(std::begin(kObjectForms), std::end(kObjectForms), [&](const ObjectForm& f) { return f.shape == shape; });
    if (known == std::end(kObjectForms)) throw InputError("--object: shape '" + shape + "' is not known; " + accepted);
    object.shape = known->kind;
    const bool round = shape == "sphere" || shape == "cylinder" || shape == "capsule";
    const bool elongated = shape == "cylinder" || shape == "capsule";
    const std::string fields = colon == std::string::npos ? "" : text.substr(colon + 1);
    std::vector<std::string> seen;  // a field given twice would silently take its last value
    for (const std::string& field : split(fields, ',')) {
        const size_t equals = field.find('=');
        const std::string key = field.substr(0, equals), value = equals == std::string::npos ? "" : field.substr(equals + 1);
        if (std::find(seen.begin(), seen.end(), key) != seen.end()) {
            throw InputError("--object: field '" + key + "' is given twice in '" + text + "'; give each field once");
        }
        seen.push_back(key);
        auto positive = [&](const std::string& v) {
            const double x = parseNumber(v, "--object " + key, accepted);
            if (!(x > 0) || !std::isfinite(x)) throw InputError("--object " + key + ": value '" + v + "' is not accepted; " + accepted);
            return x;
        };
        const std::vector<std::string> triple = split(value, 'x');
        if (key == "mass") {
            object.mass = positive(value);
        } else if (key == "radius" && round) {
            object.radius = positive(value);
        } else if (key == "length" && elongated) {
            object.length = positive(value);
        } else if (key == "size" && shape == "box" && triple.size() == 3) {
            for (int i = 0; i < 3; ++i) object.size[i] = positive(triple[i]);
        } else if (key == "semi_axes" && shape == "ellipsoid" && triple.size() == 3) {
            for (int i = 0; i < 3; ++i) object.semiAxes[i] = positive(triple[i]);
        } else {
            throw InputError("--object: field '" + field + "' is not accepted; " + accepted);
        }
    }
    const bool sized = shape == "box" ? object.size[0] > 0 : shape == "ellipsoid" ? object.semiAxes[0] > 0
                                                                                   : object.radius > 0 && (!elongated || object.length > 0);
    if (object.mass <= 0 || !sized) throw InputError("--object '" + text + "' lacks a size or mass; " + accepted);
    return object;
}

model::BuildOptions parseSubject(const std::string& sex, const std::string& mass, const std::string& stature,
                                 const std::string& preset) {
    model::BuildOptions options = scenario::Scenario::makeDefaultBodyOptions();
    options.subject = anthropometry::getReferenceSubject(anthropometry::parseSex(sex, "--sex"));
    if (!mass.empty()) options.subject.mass = parseNumber(mass, "--mass", "body mass must be a number in [20, 250] kg");
    if (!stature.empty()) {
        options.subject.stature = parseNumber(stature, "--stature", "stature must be a number in [1.0, 2.5] m");
    }
    anthropometry::validateBodyMass(options.subject.mass, "--mass");
    anthropometry::validateStature(options.subject.stature, "--stature");
    options.preset = model::parsePreset(preset, "--preset");
    return options;
}

// The force-closure figure the planner checked: Q for three or more contacts; for two, whose Q
// is round-off (nothing resists a turn about their line), the antipodal test's.
std::string describeClosure(const planning::PlanDiagnostics& d) {
    if (d.goals.size() == 2) return planning::describeAntipodal(d);
    std::ostringstream text;
    text << "Q " << d.quality;
    return text.str();
}

// How long after the settle time the planned grasp is simulated before it counts as holding.
constexpr double kHoldCheckAfterSettle = 0.5;  // s

// The plan under gravity in full compliant contact: the planner's checks are static (reach,
// closure, a frictionless release), and a grasp whose contacts cannot carry the object's weight
// passes them and drops it once released. Refused like a plan that fails a check.
std::string checkPlanHolds(const scenario::Scenario& planned, const std::string& type) {
    simulation::SimulationOptions options;
    options.duration = planned.simulation.settleTime + kHoldCheckAfterSettle;
    const simulation::SimulationSummary s = simulation::runGraspSimulation(planned, options).summary;
    char numbers[160];
    if (!s.complete || !s.held) {
        std::snprintf(numbers, sizeof numbers, " by t = %.3g s (a goal fingertip %.3g mm from its goal, held_tolerance %.3g mm",
                      options.duration, s.maxFingertipGoalDistance * 1e3, planned.simulation.heldTolerance * 1e3);
        throw planning::NoGraspError("no " + type + " grasp found that holds the object: the plan, simulated in full contact, " +
                                     (s.complete ? "loses the object" : "stopped") + numbers + (s.complete ? "" : "; " + s.failure) +
                                     "); --no-hold-check writes it anyway");
    }
    std::snprintf(numbers, sizeof numbers, "holds its object %.3g s after settling (drift %.2f mm)", kHoldCheckAfterSettle,
                  s.objectDisplacement * 1e3);
    return numbers;
}

}  // namespace

bool GraspCommand::parsed() const { return grasp_->parsed(); }

void GraspCommand::checkOptions() const {
    const Options& o = *options_;
    if (!plan_->parsed()) return;
    parseSubject(o.sex, o.mass, o.stature, o.preset);
    parseObject(o.object);
    planning::parseGraspType(o.type, "--type");
    checkOutputFile(o.output, "--output");
}

int GraspCommand::run() const {
    const Options& o = *options_;
    if (!plan_->parsed()) throw InputError("grasp: a subcommand is required: plan (see graspsim grasp --help)");
    checkOptions();  // before the planning's seconds of work
    const planning::GraspType type = planning::parseGraspType(o.type, "--type");
    scenario::Scenario base;
    base.name = o.name.empty() ? "planned-" + o.type : o.name;
    base.description = "A " + o.type + " grasp planned by graspsim grasp plan.";
    base.bodyOptions = parseSubject(o.sex, o.mass, o.stature, o.preset);
    base.object = parseObject(o.object);
    const planning::GraspPlan plan = planning::planGrasp(planning::makeGraspRequest(base, type));
    const scenario::Scenario planned = planning::applyPlan(base, plan);
    const std::string hold = o.noHoldCheck ? "hold not checked" : checkPlanHolds(planned, o.type);
    io::writeFileAtomically(o.output, planning::formatPlannedScenario(planned, plan));
    std::cout << "wrote " << o.output << ": " << o.type << " grasp, deepest segment "
              << plan.diagnostics.maxPenetration * 1000 << " mm, " << describeClosure(plan.diagnostics) << ", " << hold << "\n";
    return 0;
}

}  // namespace graspsim::cli
