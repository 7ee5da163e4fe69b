#include "graspsim/scenario/scenario_file.h"

#include "graspsim/anthropometry/units.h"
#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

using namespace graspsim;
using namespace graspsim::scenario;
using anthropometry::fromDegrees;

namespace {

// A small valid scenario; each bad-input case changes one line of it.
const std::string kBase = R"(name: test-ball
object:
  shape: sphere
  mass: 0.2
  radius: 0.045
  position: [0.4, -0.2, 0]
grasp_pose:
  elbow_flexion: 90
goals:
  index_tip: [0.045, 0, 0]
  thumb_tip: [-0.045, 0, 0]
contact:
  static_friction: 0.9
  dynamic_friction: 0.7
  stiffness: 5.0e5
perturbations:
  f1: {force: [0, -9.5, 0], start: 1.5, duration: 1.0}
)";

std::string replaceOnce(const std::string& text, const std::string& from, const std::string& to) {
    const std::size_t at = text.find(from);
    EXPECT_NE(at, std::string::npos) << "the test's base text has no '" << from << "'";
    if (at == std::string::npos) return text;
    return text.substr(0, at) + to + text.substr(at + from.size());
}

// The message of the InputError that parsing `text` throws, or "" when it does not throw.
std::string parseError(const std::string& text) {
    try {
        parseScenario(text, "test.yaml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "";
}

void expectVec3(const Vec3& actual, const Vec3& expected) {
    for (int i = 0; i < 3; ++i) EXPECT_DOUBLE_EQ(actual[i], expected[i]) << "component " << i;
}

}  // namespace

TEST(ScenarioFile, BaseTextIsAccepted) {
    const Scenario scenario = parseScenario(kBase, "test.yaml");
    EXPECT_EQ(scenario.name, "test-ball");
    EXPECT_EQ(scenario.source, "test.yaml");
    EXPECT_EQ(scenario.goals.size(), 2u);
}

// Every key, none at its default.
const std::string kEveryField = R"(# every key, none at its default
name: round-trip
description: All fields.
world:
  gravity: [0.5, -9.7, 0.25]
subject:
  sex: female
  mass: 70
  stature: 1.65
  preset: none
object:
  shape: box
  mass: 0.15
  size: [0.06, 0.1, 0.03]
  position: [0.4, -0.1, -0.05]
  orientation: [10, -20, 30]
grasp_pose:
  elbow_flexion: 80
  thumb_cmc_abduction: 45
goals:
  index_tip: [0.01, 0.02, 0.015]
  thumb_tip: [0, -0.01, -0.015]
perturbations:
  push: {force: [1, 2, 3], start: 0.5, duration: 0.25}
  pull:
    force: [-1, 0, 0]
    start: 1
    duration: 2
contact:
  stiffness: 2.0e6
  dissipation: 0.3
  static_friction: 1.1
  dynamic_friction: 0.6
  viscous_friction: 0.01
  transition_velocity: 0.005
controller:
  approach_time: 0.25
  press_depth: 0.003
  kp: 7
  kd: 0.2
  ik_interval: 0.02
simulation:
  duration: 4
  output_interval: 0.05
  accuracy: 1.0e-4
  step_size: 0.002
  settle_time: 0.75
  held_tolerance: 0.03
)";

class ScenarioFileEveryField : public ::testing::Test {
protected:
    const Scenario s = parseScenario(kEveryField, "round-trip.yaml");
};

TEST_F(ScenarioFileEveryField, NameWorldAndSubject) {
    EXPECT_EQ(s.name, "round-trip");
    EXPECT_EQ(s.description, "All fields.");
    EXPECT_EQ(s.source, "round-trip.yaml");
    expectVec3(s.world.gravity, {0.5, -9.7, 0.25});
    EXPECT_EQ(s.bodyOptions.subject.sex, anthropometry::Sex::Female);
    EXPECT_DOUBLE_EQ(s.bodyOptions.subject.mass, 70);
    EXPECT_DOUBLE_EQ(s.bodyOptions.subject.stature, 1.65);
    EXPECT_EQ(s.bodyOptions.preset, model::Preset::None);
}

TEST_F(ScenarioFileEveryField, ObjectWithDegreesAsRadians) {
    EXPECT_EQ(s.object.shape, ObjectShape::Box);
    EXPECT_DOUBLE_EQ(s.object.mass, 0.15);
    expectVec3(s.object.size, {0.06, 0.1, 0.03});
    expectVec3(s.object.position, {0.4, -0.1, -0.05});
    expectVec3(s.object.orientation, {fromDegrees(10), fromDegrees(-20), fromDegrees(30)});
}

TEST_F(ScenarioFileEveryField, PoseInRadiansGoalsAndPerturbationsInFileOrder) {
    ASSERT_EQ(s.graspPose.size(), 2u);
    EXPECT_DOUBLE_EQ(s.graspPose.at("elbow_flexion"), fromDegrees(80));
    EXPECT_DOUBLE_EQ(s.graspPose.at("thumb_cmc_abduction"), fromDegrees(45));
    ASSERT_EQ(s.goals.size(), 2u);
    expectVec3(s.goals.at("index_tip"), {0.01, 0.02, 0.015});
    expectVec3(s.goals.at("thumb_tip"), {0, -0.01, -0.015});
    ASSERT_EQ(s.perturbations.size(), 2u);
    EXPECT_EQ(s.perturbations[0].name, "push");
    expectVec3(s.perturbations[0].force, {1, 2, 3});
    EXPECT_DOUBLE_EQ(s.perturbations[0].start, 0.5);
    EXPECT_DOUBLE_EQ(s.perturbations[0].duration, 0.25);
    EXPECT_EQ(s.perturbations[1].name, "pull");
    expectVec3(s.perturbations[1].force, {-1, 0, 0});
    EXPECT_DOUBLE_EQ(s.perturbations[1].start, 1);
    EXPECT_DOUBLE_EQ(s.perturbations[1].duration, 2);
}

TEST_F(ScenarioFileEveryField, ContactControllerAndSimulation) {
    EXPECT_DOUBLE_EQ(s.contact.effectiveStiffness, 2.0e6);
    EXPECT_DOUBLE_EQ(s.contact.dissipation, 0.3);
    EXPECT_DOUBLE_EQ(s.contact.staticFriction, 1.1);
    EXPECT_DOUBLE_EQ(s.contact.dynamicFriction, 0.6);
    EXPECT_DOUBLE_EQ(s.contact.viscousFriction, 0.01);
    EXPECT_DOUBLE_EQ(s.contact.transitionVelocity, 0.005);
    EXPECT_DOUBLE_EQ(s.controller.approachTime, 0.25);
    EXPECT_DOUBLE_EQ(s.controller.pressDepth, 0.003);
    EXPECT_DOUBLE_EQ(s.controller.kp, 7);
    EXPECT_DOUBLE_EQ(s.controller.kd, 0.2);
    EXPECT_DOUBLE_EQ(s.controller.ikInterval, 0.02);
    EXPECT_DOUBLE_EQ(s.simulation.duration, 4);
    EXPECT_DOUBLE_EQ(s.simulation.outputInterval, 0.05);
    EXPECT_DOUBLE_EQ(s.simulation.accuracy, 1.0e-4);
    EXPECT_DOUBLE_EQ(s.simulation.stepSize, 0.002);
    EXPECT_DOUBLE_EQ(s.simulation.settleTime, 0.75);
    EXPECT_DOUBLE_EQ(s.simulation.heldTolerance, 0.03);
}

TEST(ScenarioFile, OmittedSectionsTakeTheDocumentedDefaults) {
    const Scenario s = parseScenario(kBase, "test.yaml");
    const Scenario defaults;
    expectVec3(s.world.gravity, {0, -9.81, 0});
    EXPECT_DOUBLE_EQ(s.bodyOptions.subject.mass, 73.0);
    EXPECT_DOUBLE_EQ(s.bodyOptions.subject.stature, 1.741);
    EXPECT_EQ(s.bodyOptions.preset, model::Preset::Thesis);
    expectVec3(s.object.orientation, {0, 0, 0});
    EXPECT_DOUBLE_EQ(s.contact.viscousFriction, 0);
    EXPECT_DOUBLE_EQ(s.contact.dissipation, defaults.contact.dissipation);
    EXPECT_DOUBLE_EQ(s.controller.kp, defaults.controller.kp);
    EXPECT_DOUBLE_EQ(s.simulation.duration, defaults.simulation.duration);
    EXPECT_DOUBLE_EQ(s.simulation.settleTime, defaults.simulation.settleTime);
}

TEST(ScenarioFile, SectionsWithEverythingCommentedOutTakeTheDefaults) {
    const std::string text =
        replaceOnce(kBase, "perturbations:\n  f1:", "world:\n  # gravity: [0, 0, 0]\nperturbations:\n  # f1:");
    const Scenario s = parseScenario(text, "test.yaml");
    EXPECT_TRUE(s.perturbations.empty());
    expectVec3(s.world.gravity, {0, -9.81, 0});
}

TEST(ScenarioFile, ApproximationSectionNamesTheRelaxedAxesAndThresholds) {
    const Scenario defaults = parseScenario(kBase, "test.yaml");
    for (bool relaxed : defaults.approximation.relaxedAxes) EXPECT_TRUE(relaxed);
    EXPECT_EQ(defaults.approximation.qThreshold, 0);
    const Scenario s = parseScenario(
        kBase + "approximation:\n  relaxed_axes: [rz, x, y]\n  q_threshold: 0.2\n  q_minimum: 0.1\n", "test.yaml");
    const std::array<bool, 6> expected{false, false, true, true, true, false};
    EXPECT_EQ(s.approximation.relaxedAxes, expected);
    EXPECT_DOUBLE_EQ(s.approximation.qThreshold, 0.2);
    EXPECT_DOUBLE_EQ(s.approximation.qMinimum, 0.1);
}

TEST(ScenarioFile, SexAloneSelectsThatReferenceSubject) {
    const Scenario s = parseScenario(kBase + "subject:\n  sex: female\n", "test.yaml");
    EXPECT_DOUBLE_EQ(s.bodyOptions.subject.mass, 61.9);
    EXPECT_DOUBLE_EQ(s.bodyOptions.subject.stature, 1.735);
}

TEST(ScenarioFile, JointRangeLimitsThemselvesAreAccepted) {
    const Scenario s = parseScenario(replaceOnce(kBase, "elbow_flexion: 90", "elbow_flexion: 150"), "test.yaml");
    EXPECT_DOUBLE_EQ(s.graspPose.at("elbow_flexion"), fromDegrees(150));
}

// One bad input: how to break kBase, and what the message must contain besides the file name.
struct BadInput {
    std::string what;
    std::string from, to;
    std::vector<std::string> expected;
};

class ScenarioFileBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(ScenarioFileBadInput, IsOneLineNamingFileFieldAndValue) {
    const BadInput& bad = GetParam();
    const std::string message = parseError(replaceOnce(kBase, bad.from, bad.to));
    ASSERT_FALSE(message.empty()) << bad.what << " was accepted";
    EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    EXPECT_EQ(message.rfind("test.yaml:", 0), 0u) << message;
    for (const std::string& part : bad.expected) {
        EXPECT_NE(message.find(part), std::string::npos) << bad.what << ": '" << part << "' not in: " << message;
    }
}

INSTANTIATE_TEST_SUITE_P(
    EachCase, ScenarioFileBadInput,
    ::testing::Values(
        BadInput{"negative mass", "mass: 0.2", "mass: -0.2",
                 {"test.yaml:4:", "'object.mass'", "'-0.2'", "mass must be a finite number > 0 kg"}},
        BadInput{"NaN mass", "mass: 0.2", "mass: .nan", {"'object.mass'", "'.nan'"}},
        // 200 g written as 200 (kg): the 45 mm ball, 3.82e-4 m^3, at 5.24e5 kg/m^3.
        BadInput{"grams for kilograms", "mass: 0.2", "mass: 200",
                 {"'object.mass'", "'200'", "200 kg in 0.000382 m^3 is 5.24e+05 kg/m^3, denser than any solid", "mass is in kg"}},
        BadInput{"text for a number", "radius: 0.045", "radius: big", {"'object.radius'", "'big'", "> 0 m"}},
        BadInput{"missing required field", "  mass: 0.2\n", "", {"'object.mass'", "is missing", "> 0 kg"}},
        BadInput{"missing name", "name: test-ball\n", "", {"'name'", "is missing"}},
        BadInput{"missing goals", "goals:\n  index_tip: [0.045, 0, 0]\n  thumb_tip: [-0.045, 0, 0]\n", "",
                 {"'goals'", "is missing"}},
        BadInput{"mistyped section", "object:", "objekt:", {"'objekt'", "is not accepted", "object, grasp_pose"}},
        BadInput{"mistyped key", "radius:", "radus:", {"test.yaml:5:", "'object.radus'", "radius, size"}},
        BadInput{"key given twice", "  mass: 0.2\n", "  mass: 0.2\n  mass: 0.3\n",
                 {"'object.mass'", "twice", "line 4"}},
        BadInput{"short vector", "position: [0.4, -0.2, 0]", "position: [0.4, -0.2]",
                 {"'object.position'", "'[0.4, -0.2]'", "three finite numbers"}},
        BadInput{"map for a number", "mass: 0.2", "mass: {kg: 0.2}", {"'object.mass'", "'{kg: 0.2}'"}},
        BadInput{"unknown shape", "shape: sphere", "shape: cube", {"'object.shape'", "'cube'", "sphere, box, cylinder, capsule, ellipsoid or mesh"}},
        BadInput{"size on a sphere", "radius: 0.045", "radius: 0.045\n  size: [1, 1, 1]",
                 {"'object.size'", "'[1, 1, 1]'", "radius, not a size"}},
        BadInput{"cylinder without length", "shape: sphere", "shape: cylinder",
                 {"'object.length'", "is missing", "> 0 m"}},
        BadInput{"zero cylinder length", "shape: sphere", "shape: cylinder\n  length: 0",
                 {"'object.length'", "'0'", "> 0 m"}},
        BadInput{"negative capsule radius", "shape: sphere\n  mass: 0.2\n  radius: 0.045",
                 "shape: capsule\n  mass: 0.2\n  radius: -0.01\n  length: 0.1", {"'object.radius'", "'-0.01'"}},
        BadInput{"ellipsoid without semi-axes", "shape: sphere\n  mass: 0.2\n  radius: 0.045",
                 "shape: ellipsoid\n  mass: 0.2", {"'object.semi_axes'", "is missing"}},
        BadInput{"zero semi-axis", "shape: sphere\n  mass: 0.2\n  radius: 0.045",
                 "shape: ellipsoid\n  mass: 0.2\n  semi_axes: [0.05, 0, 0.05]", {"'object.semi_axes'", "each > 0 (m)"}},
        BadInput{"radius on an ellipsoid", "shape: sphere\n  mass: 0.2",
                 "shape: ellipsoid\n  mass: 0.2\n  semi_axes: [0.05, 0.05, 0.05]",
                 {"'object.radius'", "semi_axes", "not a radius"}},
        BadInput{"length on a sphere", "radius: 0.045", "radius: 0.045\n  length: 0.1",
                 {"'object.length'", "not a length"}},
        BadInput{"mesh without a file", "shape: sphere\n  mass: 0.2\n  radius: 0.045",
                 "shape: mesh\n  mass: 0.2", {"'object.mesh'", "is missing"}},
        BadInput{"missing mesh file", "shape: sphere\n  mass: 0.2\n  radius: 0.045",
                 "shape: mesh\n  mass: 0.2\n  mesh: no_such.stl", {"'object.mesh'", "no_such.stl", "not a readable file"}},
        BadInput{"negative mesh scale", "shape: sphere\n  mass: 0.2\n  radius: 0.045",
                 "shape: mesh\n  mass: 0.2\n  mesh: box.stl\n  scale: -1", {"'object.scale'", "'-1'", "> 0"}},
        BadInput{"zero mass", "mass: 0.2", "mass: 0", {"'object.mass'", "'0'", "> 0 kg"}},
        BadInput{"negative static friction", "static_friction: 0.9", "static_friction: -0.1",
                 {"'contact.static_friction'", "'-0.1'", ">= 0"}},
        BadInput{"dynamic above static friction", "dynamic_friction: 0.7", "dynamic_friction: 1.2",
                 {"'contact.dynamic_friction'", "'1.2'", "dynamicFriction (1.2) is greater than staticFriction (0.9)"}},
        BadInput{"static below the default dynamic friction", "static_friction: 0.9\n  dynamic_friction: 0.7",
                 "static_friction: 0.5",
                 {"'contact.static_friction'", "'0.5'", "dynamicFriction (0.7) is greater than staticFriction (0.5)",
                  "dynamic_friction not given"}},
        BadInput{"negative stiffness", "stiffness: 5.0e5", "stiffness: -5.0e5",
                 {"'contact.stiffness'", "'-5.0e5'", "> 0 Pa"}},
        BadInput{"zero stiffness", "stiffness: 5.0e5", "stiffness: 0", {"'contact.stiffness'", "'0'"}},
        BadInput{"goal off the object", "index_tip: [0.045, 0, 0]", "index_tip: [0.0573, 0, 0]",
                 {"test.yaml:10:", "'goals.index_tip'", "'[0.0573, 0, 0]'", "12.3 mm off the sphere's surface",
                  "tolerance 1.0 mm"}},
        BadInput{"goal inside the object", "thumb_tip: [-0.045, 0, 0]", "thumb_tip: [0, 0, 0]",
                 {"'goals.thumb_tip'", "45.0 mm off"}},
        BadInput{"unknown end-effector", "thumb_tip:", "pinky_tip:",
                 {"'goals.pinky_tip'", "not an end-effector", "little_tip"}},
        BadInput{"unknown joint", "elbow_flexion: 90", "elbo_flexion: 90",
                 {"'grasp_pose.elbo_flexion'", "'90'", "not a joint", "elbow_flexion", "shoulder_flexion"}},
        BadInput{"angle out of range", "elbow_flexion: 90", "elbow_flexion: 170",
                 {"'grasp_pose.elbow_flexion'", "'170'", "[0, 150] deg"}},
        BadInput{"unknown sex", "name: test-ball", "name: test-ball\nsubject:\n  sex: robot",
                 {"'subject.sex'", "'robot'", "male or female"}},
        BadInput{"unknown preset", "name: test-ball", "name: test-ball\nsubject:\n  preset: fancy",
                 {"'subject.preset'", "'fancy'", "thesis"}},
        BadInput{"body mass out of range", "name: test-ball", "name: test-ball\nsubject:\n  mass: 7300",
                 {"'subject.mass'", "'7300'", "[20, 250] kg"}},
        BadInput{"perturbation past the end", "duration: 1.0}", "duration: 2.0}",
                 {"'perturbations.f1.duration'", "'2.0'", "(0, 1.5] s"}},
        BadInput{"perturbation without force", "force: [0, -9.5, 0], ", "",
                 {"'perturbations.f1.force'", "is missing"}},
        BadInput{"settle before the approach ends", "name: test-ball",
                 "name: test-ball\ncontroller:\n  approach_time: 1.5\nsimulation:\n  settle_time: 1.0",
                 {"'simulation.settle_time'", "'1.0'", "[1.5, 3] s"}},
        BadInput{"press deeper than the object", "name: test-ball", "name: test-ball\ncontroller:\n  press_depth: 0.05",
                 {"'controller.press_depth'", "'0.05'", "[0, 0.045) m"}},
        BadInput{"accuracy of one", "name: test-ball", "name: test-ball\nsimulation:\n  accuracy: 1",
                 {"'simulation.accuracy'", "'1'", "(0, 1)"}},
        BadInput{"step size of zero", "name: test-ball", "name: test-ball\nsimulation:\n  step_size: 0",
                 {"'simulation.step_size'", "'0'", "> 0"}},
        BadInput{"unknown relaxed axis", "name: test-ball", "name: test-ball\napproximation:\n  relaxed_axes: [x, yaw]",
                 {"test.yaml:3:", "'approximation.relaxed_axes[1]'", "'yaw'", "rx, ry, rz, x, y, z"}},
        BadInput{"relaxed axes not a list", "name: test-ball", "name: test-ball\napproximation:\n  relaxed_axes: x",
                 {"'approximation.relaxed_axes'", "'x'", "list of axis names"}},
        BadInput{"Q_M equal to Q_Th", "name: test-ball",
                 "name: test-ball\napproximation:\n  q_threshold: 0.2\n  q_minimum: 0.2",
                 {"'approximation.q_minimum'", "'0.2'", "below approximation.q_threshold", "[0, 0.2) N"}},
        BadInput{"negative Q_Th", "name: test-ball", "name: test-ball\napproximation:\n  q_threshold: -1",
                 {"'approximation.q_threshold'", "'-1'", ">= 0 N"}},
        BadInput{"empty name", "name: test-ball", "name: ''", {"test.yaml:1:", "'name'", "non-empty text"}},
        BadInput{"perturbation named none", "  f1: {", "  none: {",
                 {"'perturbations.none'", "'none' means no perturbation (--perturbation none)"}},
        BadInput{"relaxed axis listed twice", "perturbations:", "approximation:\n  relaxed_axes: [x, rx, x]\nperturbations:",
                 {"'approximation.relaxed_axes[2]'", "'x'", "listed twice"}},
        BadInput{"a second document", "perturbations:", "---\nname: other\nperturbations:",
                 {"test.yaml:", "a second YAML document (after '---') is not accepted"}},
        BadInput{"malformed YAML", "position: [0.4, -0.2, 0]", "position: [0.4, -0.2, 0",
                 {"malformed YAML"}},
        BadInput{"bad indentation", "  radius: 0.045", "   radius: 0.045", {"test.yaml:5:", "malformed YAML"}},
        BadInput{"a list, not a map", kBase, "- a\n- b\n", {"the document", "'[a, b]'", "must be a map"}},
        BadInput{"unknown friction law", "  stiffness: 5.0e5\n", "  stiffness: 5.0e5\n  friction_model: lugre\n",
                 {"'contact.friction_model'", "'lugre'", "regularized or anchor"}},
        BadInput{"unknown capsule contact rule", "  stiffness: 5.0e5\n", "  stiffness: 5.0e5\n  capsule_contact: both\n",
                 {"'contact.capsule_contact'", "'both'", "deepest or ends"}},
        BadInput{"zero anchor damping mass", "  stiffness: 5.0e5\n", "  stiffness: 5.0e5\n  anchor_damping_mass: 0\n",
                 {"'contact.anchor_damping_mass'", "'0'", "> 0 kg"}},
        BadInput{"infinite anchor relaxation time", "  stiffness: 5.0e5\n",
                 "  stiffness: 5.0e5\n  anchor_relaxation_time: .inf\n", {"'contact.anchor_relaxation_time'"}}),
    [](const ::testing::TestParamInfo<BadInput>& param) {
        std::string name;
        for (char c : param.param.what) name += std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
        return name;
    });

// A mesh path is resolved next to the scenario file; a bad mesh is refused in one line naming
// the scenario file, the field and the mesh file.
TEST(ScenarioFile, BadMeshFilesAreRefusedNamingScenarioFieldAndFile) {
    const std::string source = GRASPSIM_TEST_DATA_DIR "/meshes/test.yaml";
    const std::vector<std::pair<std::string, std::string>> cases{
        {"open_box.stl", "is not closed"}, {"inverted_box.obj", "inverted normals"},
        {"l_shape.stl", "is not convex"},  {"empty.stl", "is empty"}};
    for (const auto& [file, why] : cases) {
        const std::string text = replaceOnce(kBase, "shape: sphere\n  mass: 0.2\n  radius: 0.045",
                                             "shape: mesh\n  mass: 0.2\n  mesh: " + file);
        std::string message;
        try {
            parseScenario(text, source);
        } catch (const InputError& e) {
            message = e.what();
        }
        EXPECT_EQ(message.rfind(source + ":5: field 'object.mesh' mesh file '", 0), 0u) << message;
        EXPECT_NE(message.find("/meshes/" + file + "'"), std::string::npos) << message;
        EXPECT_NE(message.find(why), std::string::npos) << message;
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
    }
}

// The test box written in millimetres and read without a scale is a thousand times too large: the
// goals lie metres off it, and the message says what the likely slip is.
TEST(ScenarioFile, AMeshInMillimetresWithoutScaleIsNamed) {
    const std::string folder = ::testing::TempDir() + "mm-mesh";
    std::filesystem::create_directories(folder);
    std::ifstream in(GRASPSIM_TEST_DATA_DIR "/meshes/box.obj");
    std::ofstream out(folder + "/box_mm.obj");
    for (std::string line; std::getline(in, line);) {
        double x = 0, y = 0, z = 0;
        if (std::sscanf(line.c_str(), "v %lf %lf %lf", &x, &y, &z) == 3) line = "v " + std::to_string(1000 * x) + " " +
                                                                            std::to_string(1000 * y) + " " + std::to_string(1000 * z);
        out << line << "\n";
    }
    out.close();
    std::string text = replaceOnce(kBase, "shape: sphere\n  mass: 0.2\n  radius: 0.045", "shape: mesh\n  mass: 0.2\n  mesh: box_mm.obj");
    std::string message;
    try {
        parseScenario(text, folder + "/test.yaml");
    } catch (const InputError& e) {
        message = e.what();
    }
    EXPECT_NE(message.find("'goals.index_tip'"), std::string::npos) << message;
    EXPECT_NE(message.find("mm off the mesh's surface (tolerance"), std::string::npos) << message;
    EXPECT_NE(message.find("; a mesh file in millimetres needs object.scale: 0.001"), std::string::npos) << message;
    std::filesystem::remove_all(folder);
}

TEST(ScenarioFile, MeshObjectIsCentredAtItsCentroid) {
    // The test box has a corner at the file's origin; the object frame is at its centroid, so a
    // goal on the +x face is at x = 0.02 whatever the file's origin.
    std::string text = replaceOnce(kBase, "shape: sphere\n  mass: 0.2\n  radius: 0.045",
                                   "shape: mesh\n  mass: 0.2\n  mesh: box.obj");
    text = replaceOnce(text, "index_tip: [0.045, 0, 0]", "index_tip: [0.02, 0, 0]");
    text = replaceOnce(text, "thumb_tip: [-0.045, 0, 0]", "thumb_tip: [-0.02, 0.01, 0]");
    const Scenario s = parseScenario(text, GRASPSIM_TEST_DATA_DIR "/meshes/test.yaml");
    ASSERT_TRUE(s.object.meshData);
    EXPECT_NEAR(s.object.calcSurfaceDistance({0, 0, 0}), -0.01, 1e-7);
    EXPECT_NEAR(s.object.findHalfThickness(), 0.01, 1e-7);
}

TEST(ScenarioFile, EmptyTextNamesTheSource) {
    const std::string message = parseError("");
    EXPECT_NE(message.find("test.yaml"), std::string::npos) << message;
    EXPECT_NE(message.find("must be a map"), std::string::npos) << message;
}

TEST(ScenarioFile, UserWrittenFileLoads) {
    const std::string path = GRASPSIM_SOURCE_DIR "/tests/scenario/data/user_box.yaml";
    const Scenario s = loadScenarioFile(path);
    EXPECT_EQ(s.name, "tea-box-pinch");
    EXPECT_EQ(s.source, path);
    EXPECT_EQ(s.object.shape, ObjectShape::Box);
    EXPECT_DOUBLE_EQ(s.object.mass, 0.150);
    EXPECT_EQ(s.goals.size(), 3u);
    EXPECT_EQ(s.perturbations.size(), 1u);
    EXPECT_EQ(s.bodyOptions.subject.sex, anthropometry::Sex::Female);
}

TEST(ScenarioFile, MissingFileNamesPathAndBuiltins) {
    try {
        loadScenarioFile("/nonexistent/scenario.yaml");
        FAIL() << "a missing file was accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("/nonexistent/scenario.yaml"), std::string::npos) << message;
        EXPECT_NE(message.find("ball-clutch, ball-tripod, can-power, key-lateral, phone-pinch"), std::string::npos) << message;
    }
}

TEST(ScenarioFile, BuiltinNamesAreTheThesisExperimentsAndThePlannedOnes) {
    EXPECT_EQ(getBuiltinScenarioNames(),
              (std::vector<std::string>{"ball-clutch", "ball-tripod", "can-power", "key-lateral", "phone-pinch"}));
}

TEST(ScenarioFile, BothBuiltinsParse) {
    const Scenario ball = findBuiltinScenario("ball-clutch");
    EXPECT_EQ(ball.name, "ball-clutch");
    EXPECT_EQ(ball.source, "models/scenarios/ball-clutch.yaml");
    EXPECT_EQ(ball.object.shape, ObjectShape::Sphere);
    EXPECT_DOUBLE_EQ(ball.object.mass, 0.200);
    EXPECT_DOUBLE_EQ(ball.object.radius, 0.045);
    EXPECT_EQ(ball.goals.size(), 5u);
    ASSERT_NE(ball.findPerturbation("f1"), nullptr);
    expectVec3(ball.findPerturbation("f1")->force, {0, -9.5, 0});
    expectVec3(ball.findPerturbation("f2")->force, {0, 0, -2.5});

    const Scenario phone = findBuiltinScenario("phone-pinch");
    EXPECT_EQ(phone.name, "phone-pinch");
    EXPECT_EQ(phone.object.shape, ObjectShape::Box);
    EXPECT_DOUBLE_EQ(phone.object.mass, 0.100);
    expectVec3(phone.object.size, {0.070, 0.140, 0.008});
    EXPECT_EQ(phone.goals.size(), 2u);
    expectVec3(phone.findPerturbation("f1")->force, {-2, 0, 0});
    expectVec3(phone.findPerturbation("f2")->force, {0, 0, -0.5});
}

TEST(ScenarioFile, UnknownBuiltinListsTheKnownNames) {
    try {
        findBuiltinScenario("ball-clutsh");
        FAIL() << "an unknown built-in was accepted";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_NE(message.find("'ball-clutsh'"), std::string::npos) << message;
        EXPECT_NE(message.find("ball-clutch, ball-tripod, can-power, key-lateral, phone-pinch"), std::string::npos) << message;
    }
}

TEST(ScenarioFile, LoadScenarioTakesANameOrAPath) {
    EXPECT_EQ(loadScenario("phone-pinch").source, "models/scenarios/phone-pinch.yaml");
    const std::string path = GRASPSIM_SOURCE_DIR "/tests/scenario/data/user_box.yaml";
    EXPECT_EQ(loadScenario(path).name, "tea-box-pinch");
    EXPECT_THROW(loadScenario("no-such-scenario"), InputError);
}
