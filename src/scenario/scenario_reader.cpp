#include "scenario_reader.h"

#include "object_reader.h"

#include "graspsim/anthropometry/sex.h"
#include "graspsim/anthropometry/subject.h"
#include "graspsim/anthropometry/units.h"
#include "graspsim/error.h"
#include "graspsim/model/body_model.h"

#include <algorithm>
#include <iomanip>
#include <sstream>

namespace graspsim::scenario {

namespace {

using anthropometry::fromDegrees;

// A goal may sit this far off the object's surface (m): enough for numbers rounded to 0.1 mm,
// small against a fingertip pad (radius about 7.5 mm).
constexpr double kGoalSurfaceTolerance = 0.001;

std::string formatNumber(double value) {
    std::ostringstream text;
    text << value;
    return text.str();
}

// Radians as the degrees a file writes, for messages.
std::string formatDegrees(double radians) { return formatNumber(radians / fromDegrees(1.0)); }

// Millimetres with one decimal, for messages about small distances given in metres.
std::string formatMillimetres(double metres) {
    std::ostringstream text;
    text << std::fixed << std::setprecision(1) << metres / anthropometry::fromMillimetres(1.0);
    return text.str();
}

// An optional number whose default must fit the rule too: when it does not (a static friction
// below the default dynamic friction, a duration shorter than the default settle time), the
// field is required, and its absence is reported with the bounds it must meet.
double readFitting(const YamlField& section, const std::string& key, const NumberRule& rule, double fallback) {
    return rule.accepts(fallback) ? section.findNumber(key, rule, fallback) : section.getNumber(key, rule);
}

void readWorld(const YamlField& root, WorldSpec& world) {
    const YamlField section = root.getSection("world", {"gravity"});
    world.gravity = section.findVec3("gravity", NumberRule::any("gravity", "m/s^2"), world.gravity);
}

void readSubject(const YamlField& root, model::BuildOptions& options) {
    const YamlField section = root.getSection("subject", {"sex", "mass", "stature", "preset"});
    if (const std::optional<YamlField> sex = section.find("sex")) {
        // Mass and stature not given are those of the reference subject of this sex.
        const std::string text = sex->asText("sex must be male or female");
        options.subject = anthropometry::getReferenceSubject(anthropometry::parseSex(text, sex->describePlace()));
    }
    anthropometry::Subject& subject = options.subject;
    subject.mass = section.findNumber(
        "mass", NumberRule::closed("body mass", "kg", anthropometry::kMinBodyMass, anthropometry::kMaxBodyMass),
        subject.mass);
    subject.stature = section.findNumber(
        "stature", NumberRule::closed("stature", "m", anthropometry::kMinStature, anthropometry::kMaxStature),
        subject.stature);
    if (const std::optional<YamlField> preset = section.find("preset")) {
        options.preset = model::parsePreset(preset->asText("preset must be thesis or none"), preset->describePlace());
    }
}

void rejectIfGiven(const YamlField& section, const std::string& key, const std::string& why) {
    if (const std::optional<YamlField> field = section.find(key)) field->reject(why);
}

std::vector<std::string> getJointNames(const model::ModelDescription& body) {
    std::vector<std::string> names;
    for (const model::Joint& joint : body.joints) {
        if (joint.getDofCount() > 0) names.push_back(joint.name);
    }
    return names;
}

// "elbow_flexion must be within its range of motion [0, 150] deg"
std::string describeRange(const model::Joint& joint) {
    return joint.name + " must be within its range of motion [" + formatDegrees(joint.lower) + ", " +
           formatDegrees(joint.upper) + "] deg";
}

std::map<std::string, double> readGraspPose(const YamlField& root, const model::ModelDescription& body) {
    const YamlField section = root.require("grasp_pose", "give the grasp pose as joint name: angle (deg)");
    std::map<std::string, double> pose;
    for (const YamlField& entry : section.getEntries()) {
        const model::Joint* joint = body.findJoint(entry.getKey());
        if (!joint || joint->getDofCount() == 0) {
            entry.reject("'" + entry.getKey() + "' is not a joint of the arm; joints: " +
                         joinNames(getJointNames(body)));
        }
        const double angle = fromDegrees(entry.asNumber(NumberRule::any(entry.getKey(), "deg")));
        // Compared in radians, as the limits are stored, so that a limit written in the file is accepted.
        if (joint->hasLimits() && (angle < joint->lower || angle > joint->upper)) entry.reject(describeRange(*joint));
        pose[entry.getKey()] = angle;
    }
    if (pose.empty()) section.reject("grasp_pose must give at least one joint angle");
    return pose;
}

std::vector<std::string> getEndEffectorNames(const model::ModelDescription& body) {
    std::vector<std::string> names;
    for (const model::EndEffector& effector : body.endEffectors) names.push_back(effector.name);
    return names;
}

// `end_effectors: {name: {body: segment, point: [x, y, z]}}`: goals that are not fingertip pads
// (a lateral pinch's side of the index), points fixed on a segment in its body frame (m).
std::vector<model::SegmentPoint> readSegmentPoints(const YamlField& root, const model::ModelDescription& body) {
    std::vector<model::SegmentPoint> points;
    const std::optional<YamlField> section = root.find("end_effectors");
    if (!section || section->isEmpty()) return points;
    for (const YamlField& entry : section->getEntries()) {
        entry.requireMap({"body", "point"});
        if (body.findEndEffector(entry.getKey())) entry.reject("the arm has an end-effector of that name already");
        const YamlField segment = entry.require("body", "give the segment (body name) the point is fixed on");
        const std::string name = segment.asText("body must be a body name");
        if (!body.findBody(name)) {
            std::vector<std::string> names;
            for (const model::Body& b : body.bodies) names.push_back(b.name);
            segment.reject("'" + name + "' is not a body of the arm; bodies: " + joinNames(names));
        }
        const Vec3 p_B = entry.getVec3("point", NumberRule::any("point", "m, body frame"));
        points.push_back({entry.getKey(), name, {p_B[0], p_B[1], p_B[2]}});
    }
    return points;
}

std::map<std::string, Vec3> readGoals(const YamlField& root, const model::ModelDescription& body,
                                      const ObjectSpec& object) {
    const YamlField section = root.require("goals", "give a goal point (m, object frame) per end-effector");
    std::map<std::string, Vec3> goals;
    for (const YamlField& entry : section.getEntries()) {
        if (!body.findEndEffector(entry.getKey())) {
            entry.reject("'" + entry.getKey() + "' is not an end-effector; end-effectors: " +
                         joinNames(getEndEffectorNames(body)));
        }
        const Vec3 p_OG = entry.asVec3(NumberRule::any("a goal", "m, object frame"));
        const double offSurface = std::abs(object.calcSurfaceDistance(p_OG));
        if (offSurface > kGoalSurfaceTolerance) {
            // A mesh exported in millimetres and read as metres is a thousand times too large.
            const bool unscaledMesh = object.shape == ObjectShape::Mesh && object.meshScale == model::Vec3{1, 1, 1} && offSurface > 0.1;
            entry.reject("it lies " + formatMillimetres(offSurface) + " mm off the " + toString(object.shape) +
                         "'s surface (tolerance " + formatMillimetres(kGoalSurfaceTolerance) + " mm)" +
                         (unscaledMesh ? "; a mesh file in millimetres needs object.scale: 0.001" : ""));
        }
        goals[entry.getKey()] = p_OG;
    }
    if (goals.empty()) section.reject("goals must give at least one end-effector's goal point");
    return goals;
}

// The friction law and the anchor law's parameters (each finite and > 0).
contact::FrictionSettings readFriction(const YamlField& section) {
    contact::FrictionSettings friction;
    if (const std::optional<YamlField> model = section.find("friction_model")) {
        const std::string accepted = "friction_model must be regularized or anchor";
        const std::string text = model->asText(accepted);
        if (text != "regularized" && text != "anchor") model->reject(accepted);
        friction.model = contact::parseFrictionModel(text, "contact.friction_model");
    }
    contact::AnchorFrictionParameters& anchor = friction.anchor;
    anchor.stiffnessRatio = section.findNumber(
        "anchor_stiffness_ratio", NumberRule::positive("anchor stiffness ratio", "k_t / k_n"), anchor.stiffnessRatio);
    anchor.dampingMass =
        section.findNumber("anchor_damping_mass", NumberRule::positive("anchor damping mass", "kg"), anchor.dampingMass);
    anchor.relaxationTime = section.findNumber(
        "anchor_relaxation_time", NumberRule::positive("anchor relaxation time", "s"), anchor.relaxationTime);
    return friction;
}

// The rules between fields (dynamic friction at most static) are ContactParameters::validate()'s
// alone; its message is given the place of the field to change: dynamic_friction, or, when that
// is left at its default, static_friction.
void validateContactParameters(const YamlField& section, const contact::ContactParameters& contact) {
    try {
        contact.validate("contact");
    } catch (const InputError& e) {
        if (const std::optional<YamlField> dynamic = section.find("dynamic_friction")) dynamic->reject(e.what());
        if (const std::optional<YamlField> stat = section.find("static_friction")) {
            stat->reject(std::string(e.what()) + " (dynamic_friction not given: its default)");
        }
        throw InputError(section.describePlace() + ": " + e.what());
    }
}

// The pair's parameters, each with the rule of ContactParameters::validate(), applied here to
// name the file, line and field of a bad value; fields left out keep ContactParameters's defaults.
contact::ContactParameters readContactParameters(const YamlField& section) {
    contact::ContactParameters contact;
    contact.effectiveStiffness =
        section.findNumber("stiffness", NumberRule::positive("stiffness", "Pa"), contact.effectiveStiffness);
    contact.dissipation =
        section.findNumber("dissipation", NumberRule::nonNegative("dissipation", "s/m"), contact.dissipation);
    contact.staticFriction =
        section.findNumber("static_friction", NumberRule::nonNegative("static friction", ""), contact.staticFriction);
    contact.dynamicFriction = section.findNumber(
        "dynamic_friction", NumberRule::nonNegative("dynamic friction", ""), contact.dynamicFriction);
    contact.viscousFriction = section.findNumber(
        "viscous_friction", NumberRule::nonNegative("viscous friction", "s/m"), contact.viscousFriction);
    contact.transitionVelocity = section.findNumber(
        "transition_velocity", NumberRule::positive("transition velocity", "m/s"), contact.transitionVelocity);
    if (const std::optional<YamlField> capsule = section.find("capsule_contact")) {
        const std::string accepted = "capsule_contact must be deepest or ends";
        const std::string text = capsule->asText(accepted);
        if (text != "deepest" && text != "ends") capsule->reject(accepted);
        contact.capsuleContact = contact::parseCapsuleContact(text, "contact.capsule_contact");
    }
    validateContactParameters(section, contact);
    return contact;
}

void readContact(const YamlField& root, Scenario& scenario) {
    const YamlField section = root.getSection(
        "contact", {"stiffness", "dissipation", "static_friction", "dynamic_friction", "viscous_friction",
                    "transition_velocity", "capsule_contact", "friction_model", "anchor_stiffness_ratio",
                    "anchor_damping_mass", "anchor_relaxation_time"});
    scenario.contact = readContactParameters(section);
    scenario.friction = readFriction(section);
}

// `planned`: the grasp is planned on load, which sets the press depth for the object
// (planning::findPlannedPressDepth), so a default that does not fit a thin object is no error.
ControllerSpec readController(const YamlField& root, const ObjectSpec& object, bool planned) {
    const YamlField section =
        root.getSection("controller", {"approach_time", "press_depth", "kp", "kd", "ik_interval"});
    ControllerSpec controller;
    controller.approachTime =
        section.findNumber("approach_time", NumberRule::nonNegative("approach time", "s"), controller.approachTime);
    NumberRule depth =
        NumberRule::closed("press depth (less than half the object's thickness)", "m", 0, object.findHalfThickness());
    depth.upperOpen = true;
    controller.pressDepth = planned ? section.findNumber("press_depth", depth, controller.pressDepth)
                                    : readFitting(section, "press_depth", depth, controller.pressDepth);
    controller.kp = section.findNumber("kp", NumberRule::positive("kp", "N m/rad"), controller.kp);
    controller.kpGiven = section.find("kp").has_value();
    controller.kd = section.findNumber("kd", NumberRule::nonNegative("kd", "N m s/rad"), controller.kd);
    controller.ikInterval =
        section.findNumber("ik_interval", NumberRule::positive("IK interval", "s"), controller.ikInterval);
    return controller;
}

SimulationSpec readSimulation(const YamlField& root, const ControllerSpec& controller) {
    const YamlField section =
        root.getSection("simulation", {"duration", "output_interval", "accuracy", "step_size", "settle_time", "held_tolerance"});
    SimulationSpec simulation;
    simulation.duration = section.findNumber("duration", NumberRule::positive("duration", "s"), simulation.duration);
    NumberRule output = NumberRule::closed("output interval (at most the duration)", "s", 0, simulation.duration);
    output.lowerOpen = true;
    simulation.outputInterval = readFitting(section, "output_interval", output, simulation.outputInterval);
    NumberRule accuracy = NumberRule::closed("accuracy", "", 0, 1);
    accuracy.lowerOpen = accuracy.upperOpen = true;
    simulation.accuracy = section.findNumber("accuracy", accuracy, simulation.accuracy);
    simulation.stepSize = section.findNumber("step_size", NumberRule::positive("step size", "s"), simulation.stepSize);
    const NumberRule settle = NumberRule::closed("settle time (from controller.approach_time to the duration)", "s",
                                                 controller.approachTime, simulation.duration);
    simulation.settleTime = readFitting(section, "settle_time", settle, simulation.settleTime);
    simulation.heldTolerance =
        section.findNumber("held_tolerance", NumberRule::positive("held tolerance", "m"), simulation.heldTolerance);
    return simulation;
}

Perturbation readPerturbation(const YamlField& entry, double simulationDuration) {
    // `--perturbation none` means no perturbation: one of that name could never be chosen.
    if (entry.getKey() == "none") entry.reject("'none' means no perturbation (--perturbation none); give it another name");
    entry.requireMap({"force", "start", "duration"});
    Perturbation perturbation;
    perturbation.name = entry.getKey();
    perturbation.force = entry.getVec3("force", NumberRule::any("force", "N, ground frame"));
    NumberRule start = NumberRule::closed("start (before simulation.duration)", "s", 0, simulationDuration);
    start.upperOpen = true;
    perturbation.start = entry.getNumber("start", start);
    NumberRule duration = NumberRule::closed("duration (ending by simulation.duration)", "s", 0,
                                             simulationDuration - perturbation.start);
    duration.lowerOpen = true;
    perturbation.duration = entry.getNumber("duration", duration);
    return perturbation;
}

std::vector<Perturbation> readPerturbations(const YamlField& root, const SimulationSpec& simulation) {
    std::vector<Perturbation> perturbations;
    // "perturbations:" with every entry commented out means none.
    const std::optional<YamlField> section = root.find("perturbations");
    if (section && !section->isEmpty()) {
        for (const YamlField& entry : section->getEntries()) {
            perturbations.push_back(readPerturbation(entry, simulation.duration));
        }
    }
    return perturbations;
}

std::array<bool, 6> readRelaxedAxes(const YamlField& field) {
    std::vector<std::string> names(std::begin(ApproximationSpec::kAxisNames), std::end(ApproximationSpec::kAxisNames));
    const std::string accepted = "a list of axis names out of " + joinNames(names);
    std::array<bool, 6> relaxed{false, false, false, false, false, false};
    for (const YamlField& item : field.getItems(accepted)) {
        const std::string name = item.asText(accepted);
        const auto it = std::find(names.begin(), names.end(), name);
        if (it == names.end()) item.reject("axis names are " + joinNames(names));
        const std::size_t axis = static_cast<std::size_t>(it - names.begin());
        if (relaxed[axis]) item.reject("'" + name + "' is listed twice; give each axis once");
        relaxed[axis] = true;
    }
    return relaxed;
}

ApproximationSpec readApproximation(const YamlField& root) {
    const YamlField section = root.getSection("approximation", {"relaxed_axes", "q_threshold", "q_minimum"});
    ApproximationSpec approximation;
    if (const std::optional<YamlField> axes = section.find("relaxed_axes")) approximation.relaxedAxes = readRelaxedAxes(*axes);
    approximation.qThreshold = section.findNumber("q_threshold", NumberRule::nonNegative("Q_Th (0 = automatic)", "N"),
                                                  approximation.qThreshold);
    NumberRule minimum = NumberRule::nonNegative("Q_M (0 = half of Q_Th)", "N");
    if (approximation.qThreshold > 0) {
        minimum = NumberRule::closed("Q_M (0 = half of Q_Th; below approximation.q_threshold)", "N", 0, approximation.qThreshold);
        minimum.upperOpen = true;
    }
    approximation.qMinimum = section.findNumber("q_minimum", minimum, approximation.qMinimum);
    return approximation;
}

}  // namespace

// `grasp: {type: power-sphere}`: the grasp type (checked by the planning layer), or "".
std::string readGraspType(const YamlField& root) {
    const std::optional<YamlField> section = root.find("grasp");
    if (!section) return "";
    section->requireMap({"type"});
    for (const char* planned : {"grasp_pose", "goals", "end_effectors"}) {
        rejectIfGiven(root, planned, std::string("the grasp planner finds it: leave out ") + planned + " with grasp.type");
    }
    return section->require("type", "give the grasp type to plan").asText("type must be a grasp type name");
}

Scenario readScenario(const YamlField& root) {
    root.requireMap({"name", "description", "world", "subject", "object", "grasp_pose", "end_effectors", "goals", "grasp",
                     "perturbations", "contact", "controller", "simulation", "approximation"});
    Scenario scenario;
    scenario.source = root.getSource();
    const YamlField name = root.require("name", "give the scenario a name");
    scenario.name = name.asText("name must be text");
    if (scenario.name.empty()) name.reject("name must be a non-empty text");
    if (const std::optional<YamlField> description = root.find("description")) {
        scenario.description = description->asText("description must be text");
    }
    readWorld(root, scenario.world);
    readSubject(root, scenario.bodyOptions);
    scenario.graspType = readGraspType(root);
    scenario.object = readObject(root, !scenario.graspType.empty());
    if (scenario.graspType.empty()) {
        // Joint and end-effector names are checked against the arm this scenario builds.
        scenario.bodyOptions.segmentPoints = readSegmentPoints(root, model::buildBodyModel(scenario.bodyOptions));
        const model::ModelDescription body = model::buildBodyModel(scenario.bodyOptions);
        scenario.graspPose = readGraspPose(root, body);
        scenario.goals = readGoals(root, body, scenario.object);
    }
    readContact(root, scenario);
    scenario.controller = readController(root, scenario.object, !scenario.graspType.empty());
    scenario.simulation = readSimulation(root, scenario.controller);
    scenario.perturbations = readPerturbations(root, scenario.simulation);
    scenario.approximation = readApproximation(root);
    return scenario;
}

}  // namespace graspsim::scenario
