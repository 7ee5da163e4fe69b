// The resolved scenario a result folder keeps must read back to the scenario that ran: oracle is
// the reader itself (parseScenario of the written text equals the original, field by field).

#include "graspsim/scenario/scenario_file.h"
#include "graspsim/scenario/scenario_writer.h"

#include "graspsim/anthropometry/units.h"
#include "graspsim/error.h"
#include "graspsim/model/mesh_file.h"
#include "graspsim/model/triangle_mesh.h"

#include <gtest/gtest.h>

#include <cmath>

namespace graspsim::scenario {
namespace {

constexpr double kAngleTolerance = 1e-14;  // rad: round-off of the degree conversion

void expectVec3Eq(const Vec3& a, const Vec3& b, double tolerance = 0) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(a[k], b[k], tolerance) << "component " << k;
}

void expectSameScenario(const Scenario& a, const Scenario& b) {
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.description, b.description);
    expectVec3Eq(a.world.gravity, b.world.gravity);
    EXPECT_EQ(a.bodyOptions.subject.sex, b.bodyOptions.subject.sex);
    EXPECT_EQ(a.bodyOptions.subject.mass, b.bodyOptions.subject.mass);
    EXPECT_EQ(a.bodyOptions.subject.stature, b.bodyOptions.subject.stature);
    EXPECT_EQ(a.bodyOptions.preset, b.bodyOptions.preset);
    EXPECT_EQ(a.object.shape, b.object.shape);
    EXPECT_EQ(a.object.mass, b.object.mass);
    EXPECT_EQ(a.object.radius, b.object.radius);
    expectVec3Eq(a.object.size, b.object.size);
    EXPECT_EQ(a.object.length, b.object.length);
    expectVec3Eq(a.object.semiAxes, b.object.semiAxes);
    EXPECT_EQ(a.object.meshPath, b.object.meshPath);
    expectVec3Eq(a.object.meshScale, b.object.meshScale);
    EXPECT_EQ(a.object.meshData == nullptr, b.object.meshData == nullptr);
    if (a.object.meshData && b.object.meshData) EXPECT_EQ(a.object.meshData->vertices, b.object.meshData->vertices);
    expectVec3Eq(a.object.meshCentroid, b.object.meshCentroid);
    expectVec3Eq(a.object.position, b.object.position);
    expectVec3Eq(a.object.orientation, b.object.orientation, kAngleTolerance);
    ASSERT_EQ(a.graspPose.size(), b.graspPose.size());
    for (const auto& [joint, angle] : a.graspPose) EXPECT_NEAR(angle, b.graspPose.at(joint), kAngleTolerance) << joint;
    ASSERT_EQ(a.goals.size(), b.goals.size());
    for (const auto& [effector, p] : a.goals) expectVec3Eq(p, b.goals.at(effector));
    ASSERT_EQ(a.perturbations.size(), b.perturbations.size());
    for (std::size_t i = 0; i < a.perturbations.size(); ++i) {
        EXPECT_EQ(a.perturbations[i].name, b.perturbations[i].name);
        expectVec3Eq(a.perturbations[i].force, b.perturbations[i].force);
        EXPECT_EQ(a.perturbations[i].start, b.perturbations[i].start);
        EXPECT_EQ(a.perturbations[i].duration, b.perturbations[i].duration);
    }
    EXPECT_EQ(a.contact.effectiveStiffness, b.contact.effectiveStiffness);
    EXPECT_EQ(a.contact.dissipation, b.contact.dissipation);
    EXPECT_EQ(a.contact.staticFriction, b.contact.staticFriction);
    EXPECT_EQ(a.contact.dynamicFriction, b.contact.dynamicFriction);
    EXPECT_EQ(a.contact.viscousFriction, b.contact.viscousFriction);
    EXPECT_EQ(a.contact.transitionVelocity, b.contact.transitionVelocity);
    EXPECT_EQ(a.contact.capsuleContact, b.contact.capsuleContact);
    EXPECT_EQ(a.friction.model, b.friction.model);
    EXPECT_EQ(a.friction.anchor.stiffnessRatio, b.friction.anchor.stiffnessRatio);
    EXPECT_EQ(a.friction.anchor.dampingMass, b.friction.anchor.dampingMass);
    EXPECT_EQ(a.friction.anchor.relaxationTime, b.friction.anchor.relaxationTime);
    EXPECT_EQ(a.controller.approachTime, b.controller.approachTime);
    EXPECT_EQ(a.controller.pressDepth, b.controller.pressDepth);
    EXPECT_EQ(a.controller.kp, b.controller.kp);
    EXPECT_EQ(a.controller.kd, b.controller.kd);
    EXPECT_EQ(a.controller.ikInterval, b.controller.ikInterval);
    EXPECT_EQ(a.simulation.duration, b.simulation.duration);
    EXPECT_EQ(a.simulation.outputInterval, b.simulation.outputInterval);
    EXPECT_EQ(a.simulation.accuracy, b.simulation.accuracy);
    EXPECT_EQ(a.simulation.settleTime, b.simulation.settleTime);
    EXPECT_EQ(a.simulation.heldTolerance, b.simulation.heldTolerance);
    EXPECT_EQ(a.approximation.relaxedAxes, b.approximation.relaxedAxes);
    EXPECT_EQ(a.approximation.qThreshold, b.approximation.qThreshold);
    EXPECT_EQ(a.approximation.qMinimum, b.approximation.qMinimum);
}

TEST(ScenarioWriter, BuiltinScenariosReadBackUnchanged) {
    for (const std::string& name : getBuiltinScenarioNames()) {
        SCOPED_TRACE(name);
        const Scenario original = findBuiltinScenario(name);
        expectSameScenario(original, parseScenario(formatScenarioYaml(original, "resolved"), "written.yaml"));
    }
}

TEST(ScenarioWriter, DefaultsAndEditedFieldsAreWrittenOut) {
    Scenario edited = findBuiltinScenario("phone-pinch");
    edited.description = "a: text # with YAML's \"special\" characters";
    edited.perturbations.clear();
    edited.approximation.relaxedAxes = {false, true, false, true, false, false};
    edited.approximation.qThreshold = 1.25;
    edited.approximation.qMinimum = 0.5;
    edited.contact.viscousFriction = 0.1;
    edited.object.orientation = {0.1, -0.2, 0.3};
    const std::string text = formatScenarioYaml(edited);
    // Every key of the format is there, defaults included.
    for (const char* key : {"viscous_friction:", "transition_velocity:", "held_tolerance:", "ik_interval:", "preset:"}) {
        EXPECT_NE(text.find(key), std::string::npos) << key;
    }
    expectSameScenario(edited, parseScenario(text, "written.yaml"));
}

// A step left unset stays unset (the integrator's own default, simulation::findStepSize): no
// step_size key, and 0 read back; a step set is written and read back.
TEST(ScenarioWriter, StepSizeIsWrittenOnlyWhenSet) {
    Scenario s = findBuiltinScenario("ball-clutch");
    ASSERT_EQ(s.simulation.stepSize, 0);
    EXPECT_EQ(formatScenarioYaml(s).find("step_size:"), std::string::npos);
    EXPECT_EQ(parseScenario(formatScenarioYaml(s), "written.yaml").simulation.stepSize, 0);
    s.simulation.stepSize = 0.002;
    EXPECT_NE(formatScenarioYaml(s).find("step_size: 0.002"), std::string::npos);
    EXPECT_EQ(parseScenario(formatScenarioYaml(s), "written.yaml").simulation.stepSize, 0.002);
}

// Numbers are written as the shortest text that reads back to the same double: the step a user
// typed as 0.005 reads 0.005 (not 0.0050000000000000001), and awkward doubles still read back bit
// for bit. Oracle: the text itself, and the reader.
TEST(ScenarioWriter, NumbersAreShortAndReadBackExactly) {
    Scenario s = findBuiltinScenario("ball-clutch");
    s.simulation.outputInterval = 0.005;
    s.world.gravity = {0, -9.81, 0};
    s.object.mass = 0.1 + 0.2;  // 0.30000000000000004: needs all 17 digits
    s.object.position = {-0.0, 1.0 / 3.0, 1e-300};
    const std::string text = formatScenarioYaml(s);
    EXPECT_NE(text.find("gravity: [0, -9.81, 0]"), std::string::npos) << text;
    EXPECT_NE(text.find("output_interval: 0.005\n"), std::string::npos) << text;
    EXPECT_EQ(text.find("-0,"), std::string::npos) << "a signed zero is written as 0";
    const Scenario back = parseScenario(text, "written.yaml");
    EXPECT_EQ(back.object.mass, 0.1 + 0.2);
    EXPECT_EQ(back.object.position[1], 1.0 / 3.0);
    EXPECT_EQ(back.object.position[2], 1e-300);
    EXPECT_EQ(back.simulation.outputInterval, 0.005);
}

// Angles are written in degrees as the shortest text the reader turns back into the same radians:
// what was typed (30, 16.4), not the quotient radians / (pi / 180) (29.999999999999996,
// 16.400000000000002), which reads back a bit away. Oracle: the typed text, and the reader.
TEST(ScenarioWriter, AnglesAreWrittenAsTypedAndReadBackExactly) {
    Scenario s = findBuiltinScenario("phone-pinch");
    s.graspPose["shoulder_flexion"] = anthropometry::fromDegrees(30);  // as the reader makes "30"
    s.graspPose["index_dip_flexion"] = anthropometry::fromDegrees(16.4);
    s.graspPose["thumb_cmc_flexion"] = anthropometry::fromDegrees(-15);
    s.object.orientation = {anthropometry::fromDegrees(97.6), anthropometry::fromDegrees(20.9), anthropometry::fromDegrees(-145)};
    const std::string text = formatScenarioYaml(s);
    for (const char* line : {"\n  shoulder_flexion: 30\n", "\n  index_dip_flexion: 16.4\n", "\n  thumb_cmc_flexion: -15\n",
                             "\n  orientation: [97.6, 20.9, -145]  # deg\n"}) {
        EXPECT_NE(text.find(line), std::string::npos) << line << text;
    }
    const Scenario back = parseScenario(text, "written.yaml");
    for (const auto& [joint, angle] : s.graspPose) EXPECT_EQ(back.graspPose.at(joint), angle) << joint;
    for (int i = 0; i < 3; ++i) EXPECT_EQ(back.object.orientation[i], s.object.orientation[i]) << i;
}

// The default friction law writes nothing new (result folders stay as they were); the anchor
// law writes itself and its parameters, and reads back.
TEST(ScenarioWriter, AnchorFrictionIsWrittenOnlyWhenChosen) {
    Scenario s = findBuiltinScenario("ball-clutch");
    EXPECT_EQ(formatScenarioYaml(s).find("friction_model"), std::string::npos);
    s.friction.model = contact::FrictionModel::Anchor;
    s.friction.anchor.dampingMass = 0.05;
    const std::string text = formatScenarioYaml(s);
    EXPECT_NE(text.find("friction_model: anchor"), std::string::npos);
    expectSameScenario(s, parseScenario(text, "written.yaml"));
}

// The default capsule rule writes nothing new; the ends rule writes itself and reads back.
TEST(ScenarioWriter, CapsuleContactIsWrittenOnlyWhenChosen) {
    Scenario s = findBuiltinScenario("phone-pinch");
    EXPECT_EQ(formatScenarioYaml(s).find("capsule_contact"), std::string::npos);
    s.contact.capsuleContact = contact::CapsuleContact::Ends;
    const std::string text = formatScenarioYaml(s);
    EXPECT_NE(text.find("capsule_contact: ends"), std::string::npos);
    const Scenario back = parseScenario(text, "written.yaml");
    EXPECT_EQ(back.contact.capsuleContact, contact::CapsuleContact::Ends);
    expectSameScenario(s, back);
}

// The point where the ray from O through p meets the surface (every shape is star-shaped from
// its centre of mass), by bisection on the signed distance.
Vec3 projectToSurface(const ObjectSpec& object, const Vec3& p) {
    double inside = 0, outside = 1;
    while (object.calcSurfaceDistance({p[0] * outside, p[1] * outside, p[2] * outside}) < 0) outside *= 2;
    for (int i = 0; i < 200; ++i) {
        const double t = (inside + outside) / 2;
        (object.calcSurfaceDistance({p[0] * t, p[1] * t, p[2] * t}) < 0 ? inside : outside) = t;
    }
    return {p[0] * outside, p[1] * outside, p[2] * outside};
}

// The ball-clutch scenario with its object swapped for another shape, goals moved onto it.
Scenario makeShapeScenario(const ObjectSpec& object) {
    Scenario s = findBuiltinScenario("ball-clutch");
    const Vec3 position = s.object.position;
    s.object = object;
    s.object.position = position;
    s.object.orientation = {0.1, 0.2, -0.3};
    for (auto& [effector, p] : s.goals) p = projectToSurface(s.object, p);
    return s;
}

TEST(ScenarioWriter, EveryShapeReadsBackUnchanged) {
    std::vector<ObjectSpec> objects(5);
    objects[0].shape = ObjectShape::Cylinder;
    objects[0].radius = 0.03;
    objects[0].length = 0.12;
    objects[1].shape = ObjectShape::Capsule;
    objects[1].radius = 0.025;
    objects[1].length = 0.05;
    objects[2].shape = ObjectShape::Ellipsoid;
    objects[2].semiAxes = {0.05, 0.04, 0.03};
    objects[3].shape = ObjectShape::Box;
    objects[3].size = {0.05, 0.09, 0.03};
    objects[4].shape = ObjectShape::Sphere;
    objects[4].radius = 0.04;
    for (ObjectSpec& object : objects) {
        SCOPED_TRACE(toString(object.shape));
        object.mass = 0.3;
        const Scenario original = makeShapeScenario(object);
        const std::string text = formatScenarioYaml(original);
        const Scenario read = parseScenario(text, "written.yaml");
        expectSameScenario(original, read);
        EXPECT_EQ(formatScenarioYaml(read), text);
    }
}

TEST(ScenarioWriter, MeshObjectReadsBackWithItsPathAndScale) {
    // The written path is absolute, so the text reads back wherever it is said to lie.
    const std::string source = "elsewhere/written.yaml";
    for (const Vec3& scale : {Vec3{2, 2, 2}, Vec3{1, 2, 1.5}}) {
        ObjectSpec object;
        object.shape = ObjectShape::Mesh;
        object.mass = 0.1;
        object.mesh = "box.stl";
        object.meshPath = GRASPSIM_TEST_DATA_DIR "/meshes/box.stl";
        object.meshScale = scale;
        object.meshData = std::make_shared<const model::TriangleMesh>(
            model::readMeshFile(GRASPSIM_TEST_DATA_DIR "/meshes/box.stl", scale, "test"));
        object.meshCentroid = model::calcMeshMassProperties(*object.meshData).p_BCm;
        const Scenario original = makeShapeScenario(object);
        const std::string text = formatScenarioYaml(original);
        EXPECT_NE(text.find(scale[0] == scale[1] ? "scale: 2\n" : "scale: [1, 2, 1.5]\n"), std::string::npos) << text;
        const Scenario read = parseScenario(text, source);
        expectSameScenario(original, read);
        EXPECT_EQ(formatScenarioYaml(read), text);
    }
}

}  // namespace
}  // namespace graspsim::scenario
