#include "graspsim/scenario/scenario.h"

#include "graspsim/anthropometry/subject.h"
#include "graspsim/model/mesh_file.h"
#include "graspsim/model/triangle_mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>
#include <vector>

using namespace graspsim;
using namespace graspsim::scenario;

namespace {

ObjectSpec makeSphere(double radius) {
    ObjectSpec object;
    object.shape = ObjectShape::Sphere;
    object.mass = 0.2;
    object.radius = radius;
    return object;
}

ObjectSpec makeBox(const Vec3& size) {
    ObjectSpec object;
    object.shape = ObjectShape::Box;
    object.mass = 0.1;
    object.size = size;
    return object;
}

void expectNear(const Vec3& actual, const Vec3& expected, double tolerance) {
    for (int i = 0; i < 3; ++i) EXPECT_NEAR(actual[i], expected[i], tolerance) << "component " << i;
}

}  // namespace

TEST(ObjectSpec, PoseIsTranslationAndBodyFixedXyzRotation) {
    ObjectSpec object = makeSphere(0.05);
    object.position = {0.1, -0.2, 0.3};
    object.orientation = {M_PI / 2, 0, 0};
    const model::Transform X_GO = object.findPose();
    expectNear(X_GO.p, {0.1, -0.2, 0.3}, 0);
    // 90 deg about x takes O's y to G's z.
    expectNear(X_GO.xformFrameVecToBase({0, 1, 0}), {0, 0, 1}, 1e-15);
}

TEST(ObjectSpec, EulerAnglesComposeAboutTheNewAxes) {
    ObjectSpec object = makeSphere(0.05);
    object.orientation = {M_PI / 2, M_PI / 2, 0};
    // Body-fixed: after 90 deg about x, the second rotation is about the new y (= G's z), which
    // takes O's x to G's y. A space-fixed sequence would take it to -z instead.
    expectNear(object.findPose().xformFrameVecToBase({1, 0, 0}), {0, 1, 0}, 1e-15);
}

TEST(ObjectSpec, SphereSurfaceDistanceIsSignedRadialDistance) {
    const ObjectSpec ball = makeSphere(0.045);
    EXPECT_NEAR(ball.calcSurfaceDistance({0.045, 0, 0}), 0, 1e-15);
    EXPECT_NEAR(ball.calcSurfaceDistance({0, 0.03, 0.04}), 0.005, 1e-15);
    EXPECT_NEAR(ball.calcSurfaceDistance({0, 0, 0}), -0.045, 1e-15);
}

TEST(ObjectSpec, BoxSurfaceDistanceOutsideIsEuclideanInsideIsNearestFace) {
    const ObjectSpec phone = makeBox({0.07, 0.14, 0.008});
    EXPECT_NEAR(phone.calcSurfaceDistance({0.01, 0.02, 0.004}), 0, 1e-15);     // on the +z face
    EXPECT_NEAR(phone.calcSurfaceDistance({0.01, 0.02, 0.007}), 0.003, 1e-15); // above the face
    EXPECT_NEAR(phone.calcSurfaceDistance({0.038, 0.074, 0.004}), 0.005, 1e-15); // off an edge: 3-4-5
    EXPECT_NEAR(phone.calcSurfaceDistance({0.0, 0.0, 0.001}), -0.003, 1e-15);  // inside, 3 mm under +z
}

// Oracle: the sphere's normal is radial; a box point nearest a face gets that face's normal.
TEST(ObjectSpec, OutwardNormalIsRadialOrTheNearestFaces) {
    ObjectSpec sphere;
    sphere.shape = ObjectShape::Sphere;
    sphere.radius = 0.05;
    const Vec3 n = sphere.findOutwardNormal({0.03, 0.0, -0.04});
    EXPECT_NEAR(n[0], 0.6, 1e-15);
    EXPECT_NEAR(n[2], -0.8, 1e-15);
    ObjectSpec box;
    box.shape = ObjectShape::Box;
    box.size = {0.07, 0.14, 0.008};
    const Vec3 face = box.findOutwardNormal({0.01, 0.02, -0.004});  // on the -z face
    EXPECT_EQ(face[2], -1.0);
    EXPECT_EQ(face[0], 0.0);
    const Vec3 side = box.findOutwardNormal({0.035, 0.0, 0.001});  // on the +x face
    EXPECT_EQ(side[0], 1.0);
}

TEST(ObjectSpec, CylinderDistanceIsRadialAxialOrOffTheRim) {
    ObjectSpec c;
    c.shape = ObjectShape::Cylinder;
    c.radius = 0.03;
    c.length = 0.1;
    EXPECT_NEAR(c.calcSurfaceDistance({0.03, 0, 0.02}), 0, 1e-15);      // on the side
    EXPECT_NEAR(c.calcSurfaceDistance({0, 0.01, 0.05}), 0, 1e-15);      // on the end face
    EXPECT_NEAR(c.calcSurfaceDistance({0, 0, 0.045}), -0.005, 1e-15);   // inside, near the end face
    EXPECT_NEAR(c.calcSurfaceDistance({0.033, 0, 0.054}), 0.005, 1e-15);  // off the rim: 3-4-5
    const Vec3 side = c.findOutwardNormal({0, -0.029, 0});
    EXPECT_NEAR(side[1], -1, 1e-15);
    const Vec3 end = c.findOutwardNormal({0.0, 0.0, -0.049});
    EXPECT_NEAR(end[2], -1, 1e-15);
    EXPECT_NEAR(c.findHalfThickness(), 0.03, 1e-15);
}

TEST(ObjectSpec, CapsuleDistanceIsFromItsAxisSegment) {
    ObjectSpec c;
    c.shape = ObjectShape::Capsule;
    c.radius = 0.02;
    c.length = 0.06;
    EXPECT_NEAR(c.calcSurfaceDistance({0.02, 0, 0.01}), 0, 1e-15);
    EXPECT_NEAR(c.calcSurfaceDistance({0, 0, 0.05}), 0, 1e-15);           // tip of a cap
    EXPECT_NEAR(c.calcSurfaceDistance({0.03, 0, 0.07}), 0.03, 1e-15);     // 3-4-5 from the cap centre
    const Vec3 n = c.findOutwardNormal({0.03, 0, 0.07});
    EXPECT_NEAR(n[0], 0.6, 1e-15);
    EXPECT_NEAR(n[2], 0.8, 1e-15);
}

TEST(ObjectSpec, EllipsoidDistanceIsExactOnTheAxesAndZeroOnTheSurface) {
    ObjectSpec e;
    e.shape = ObjectShape::Ellipsoid;
    e.semiAxes = {0.05, 0.04, 0.03};
    EXPECT_NEAR(e.calcSurfaceDistance({0.05, 0, 0}), 0, 1e-15);
    // A surface point off the axes: (a cos t, b sin t, 0).
    EXPECT_NEAR(e.calcSurfaceDistance({0.05 * std::cos(0.7), 0.04 * std::sin(0.7), 0}), 0, 1e-15);
    // On an axis the first-order estimate is exact to second order: (x^2/a^2 - 1) a^2/(2x).
    EXPECT_NEAR(e.calcSurfaceDistance({0, 0, 0.031}), 0.001, 2e-5);
    const Vec3 n = e.findOutwardNormal({0, 0.04, 0});
    EXPECT_NEAR(n[1], 1, 1e-15);
    EXPECT_NEAR(e.findHalfThickness(), 0.03, 1e-15);
}

TEST(ObjectSpec, ModelIsTheObjectBuilderWithTheSpecsMassAndSize) {
    const model::ModelDescription ball = buildObjectModel(makeSphere(0.05));
    ASSERT_EQ(ball.bodies.size(), 1u);
    EXPECT_DOUBLE_EQ(ball.bodies[0].mass, 0.2);
    EXPECT_DOUBLE_EQ(ball.bodies[0].geometry.at(0).radius, 0.05);
    const model::ModelDescription box = buildObjectModel(makeBox({0.05, 0.1, 0.02}));
    EXPECT_DOUBLE_EQ(box.bodies.at(0).mass, 0.1);
    expectNear(box.bodies[0].geometry.at(0).halfLengths, {0.025, 0.05, 0.01}, 1e-17);
}

// contacts.csv names the object by these: the body is "object" and its geometry is named after the
// scenario's shape, for every shape (not "phone" for any box, "ball" for any sphere, "mesh" and
// "mesh_shape" for a mesh, as the thesis builders name theirs).
TEST(ObjectSpec, ModelIsNamedObjectWithItsGeometryNamedAfterTheShape) {
    ObjectSpec cylinder = makeSphere(0.03);
    cylinder.shape = ObjectShape::Cylinder;
    cylinder.length = 0.1;
    ObjectSpec capsule = cylinder;
    capsule.shape = ObjectShape::Capsule;
    ObjectSpec ellipsoid = makeSphere(0);
    ellipsoid.shape = ObjectShape::Ellipsoid;
    ellipsoid.semiAxes = {0.05, 0.04, 0.03};
    ObjectSpec mesh = makeSphere(0);
    mesh.shape = ObjectShape::Mesh;
    mesh.mesh = "box.stl";
    mesh.meshData = std::make_shared<const model::TriangleMesh>(
        model::readMeshFile(GRASPSIM_TEST_DATA_DIR "/meshes/box.stl", {1, 1, 1}, "test"));
    const std::vector<std::pair<ObjectSpec, std::string>> objects{
        {makeSphere(0.05), "sphere"}, {makeBox({0.07, 0.14, 0.008}), "box"}, {cylinder, "cylinder"},
        {capsule, "capsule"},         {ellipsoid, "ellipsoid"},             {mesh, "mesh"}};
    for (const auto& [object, shape] : objects) {
        const model::ModelDescription m = buildObjectModel(object);
        EXPECT_EQ(m.name, "object") << shape;
        ASSERT_EQ(m.bodies.size(), 1u) << shape;
        EXPECT_EQ(m.bodies[0].name, "object") << shape;
        ASSERT_EQ(m.bodies[0].geometry.size(), 1u) << shape;
        EXPECT_EQ(m.bodies[0].geometry[0].name, shape);
        EXPECT_NO_THROW(m.validate("test")) << shape;
    }
}

TEST(Perturbation, ActsFromStartUntilStartPlusDuration) {
    const Perturbation f1{"f1", {0, -9.5, 0}, 1.5, 1.0};
    EXPECT_FALSE(f1.isActiveAt(1.49));
    EXPECT_TRUE(f1.isActiveAt(1.5));
    EXPECT_TRUE(f1.isActiveAt(2.49));
    EXPECT_FALSE(f1.isActiveAt(2.5));
}

TEST(Scenario, FindsPerturbationsByName) {
    Scenario scenario;
    scenario.perturbations = {{"f1", {1, 0, 0}, 0, 1}, {"f2", {0, 1, 0}, 0, 1}};
    ASSERT_NE(scenario.findPerturbation("f2"), nullptr);
    EXPECT_DOUBLE_EQ(scenario.findPerturbation("f2")->force[1], 1);
    EXPECT_EQ(scenario.findPerturbation("f3"), nullptr);
}

TEST(Scenario, DefaultsAreTheMaleReferenceSubjectWithTheThesisPreset) {
    const Scenario scenario;
    const anthropometry::Subject reference = anthropometry::getReferenceSubject(anthropometry::Sex::Male);
    EXPECT_EQ(scenario.bodyOptions.subject.sex, anthropometry::Sex::Male);
    EXPECT_DOUBLE_EQ(scenario.bodyOptions.subject.mass, reference.mass);
    EXPECT_DOUBLE_EQ(scenario.bodyOptions.subject.stature, reference.stature);
    EXPECT_EQ(scenario.bodyOptions.preset, model::Preset::Thesis);
    EXPECT_EQ(scenario.bodyOptions.body, model::BodyKind::Arm);
    expectNear(scenario.world.gravity, {0, -9.81, 0}, 0);
    EXPECT_DOUBLE_EQ(scenario.contact.viscousFriction, 0);
    EXPECT_LE(scenario.contact.dynamicFriction, scenario.contact.staticFriction);
}
