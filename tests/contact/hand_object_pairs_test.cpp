#include "graspsim/contact/hand_object_pairs.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>
#include <vector>

#include "graspsim/error.h"
#include "graspsim/model/body_model.h"
#include "graspsim/model/object_model.h"

namespace graspsim::contact {
namespace {

model::Geometry makeGeometry(model::Geometry::Type type, const std::string& name) {
    model::Geometry g;
    g.type = type;
    g.name = name;
    g.radius = 0.01;
    g.length = 0.03;
    g.halfLengths = {0.04, 0.01, 0.04};
    return g;
}

model::Body makeBody(const std::string& name, const std::string& segment, double mass,
                     model::BodyRole role = model::BodyRole::Other) {
    model::Body b;
    b.name = name;
    b.segment = segment;
    b.role = role;
    b.mass = mass;
    b.inertia.xx = b.inertia.yy = b.inertia.zz = mass * 1e-4;
    return b;
}

model::Joint makeJoint(const std::string& name, model::Joint::Type type, const std::string& parent,
                       const std::string& child) {
    model::Joint j;
    j.name = name;
    j.type = type;
    j.parent = parent;
    j.child = child;
    j.lower = -1;
    j.upper = 1;
    return j;
}

// palm (2 boxes, palm role) -> virtual link (massless, no geometry) -> finger (capsule, digit
// role); palm -> ball (sphere, no role) on a slider; forearm (capsule, no role) welded to palm.
model::ModelDescription makeHandWithBall() {
    model::ModelDescription m;
    m.name = "toy_hand";
    model::Body palm = makeBody("palm", "hand", 0.25, model::BodyRole::Palm);
    model::Geometry proximal = makeGeometry(model::Geometry::Type::Box, "palm_proximal_box");
    proximal.X_BG = model::Transform::translation({0, -0.02, 0});
    palm.geometry = {proximal, makeGeometry(model::Geometry::Type::Box, "palm_distal_box")};
    model::Body finger = makeBody("index_proximal", "hand", 0.02, model::BodyRole::Digit);
    finger.geometry = {makeGeometry(model::Geometry::Type::Capsule, "index_capsule")};
    model::Body forearm = makeBody("forearm", "forearm", 1.0);
    forearm.geometry = {makeGeometry(model::Geometry::Type::Capsule, "forearm_capsule")};
    model::Body ball = makeBody("ball", "", 0.2);
    ball.geometry = {makeGeometry(model::Geometry::Type::Sphere, "ball_sphere")};
    m.bodies = {palm, makeBody("index_mcp__link", "hand", 0, model::BodyRole::Digit), finger, forearm, ball};
    m.joints = {
        makeJoint("index_abduction", model::Joint::Type::Revolute, "palm", "index_mcp__link"),
        makeJoint("index_flexion", model::Joint::Type::Revolute, "index_mcp__link",
                  "index_proximal"),
        makeJoint("wrist", model::Joint::Type::Fixed, "palm", "forearm"),
        makeJoint("ball_slide", model::Joint::Type::Prismatic, "palm", "ball")};
    return m;
}

TEST(HandObjectPairs, EveryHandGeometryAgainstEveryObjectGeometry) {
    const system::MultibodyModel model(makeHandWithBall());
    ContactParameters parameters;
    parameters.effectiveStiffness = 0.66e6;
    const std::vector<ContactPair> pairs =
        makeHandObjectPairs(model, isHandSegmentBody, "ball", parameters);
    ASSERT_EQ(pairs.size(), 3u);  // two palm boxes and the finger capsule; not the forearm
    EXPECT_EQ(pairs[0].a.shapeName, "palm_proximal_box");
    EXPECT_EQ(pairs[1].a.shapeName, "palm_distal_box");
    EXPECT_EQ(pairs[2].a.bodyName, "index_proximal");
    EXPECT_EQ(pairs[2].a.shape.type, ContactShape::Type::Capsule);
    EXPECT_EQ(pairs[2].a.body.getMobilizedBodyIndex(),
              model.getMobilizedBody("index_proximal").getMobilizedBodyIndex());
    EXPECT_EQ(pairs[0].a.X_BS.p(), SimTK::Vec3(0, -0.02, 0));
    for (const ContactPair& pair : pairs) {
        EXPECT_EQ(pair.b.bodyName, "ball");
        EXPECT_EQ(pair.b.shape.type, ContactShape::Type::Sphere);
        EXPECT_EQ(pair.parameters.effectiveStiffness, 0.66e6);
        EXPECT_TRUE(pair.enabledByDefault);
    }
}

TEST(HandObjectPairs, BadObjectChoicesAreRejected) {
    const system::MultibodyModel model(makeHandWithBall());
    const ContactParameters p;
    try {
        makeHandObjectPairs(model, isHandSegmentBody, "cup", p);
        FAIL() << "unknown object accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "hand-object contact: model 'toy_hand' has no object body named 'cup'");
    }
    EXPECT_THROW(makeHandObjectPairs(model, isHandSegmentBody, "palm", p), InputError);
}

// Every object shape makes a pair with every hand geometry; a mesh's polytope is built once
// and shared by all its pairs.
TEST(HandObjectPairs, ObjectsOfEveryShapeMakePairsWithTheHand) {
    const struct {
        model::Geometry::Type type;
        ContactShape::Type shape;
    } cases[] = {{model::Geometry::Type::Cylinder, ContactShape::Type::Cylinder},
                 {model::Geometry::Type::Ellipsoid, ContactShape::Type::Ellipsoid},
                 {model::Geometry::Type::Mesh, ContactShape::Type::ConvexMesh},
                 {model::Geometry::Type::Capsule, ContactShape::Type::Capsule}};
    for (const auto& c : cases) {
        model::ModelDescription description = makeHandWithBall();
        model::Geometry& geometry = description.updBody("ball")->geometry[0];
        geometry.type = c.type;
        geometry.semiAxes = {0.03, 0.02, 0.01};
        model::TriangleMesh tetrahedron;
        tetrahedron.vertices = {{0, 0, 0}, {0.02, 0, 0}, {0, 0.02, 0}, {0, 0, 0.02}};
        tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
        geometry.mesh = std::make_shared<model::TriangleMesh>(tetrahedron);
        const system::MultibodyModel model(description);
        const std::vector<ContactPair> pairs = makeHandObjectPairs(model, isHandSegmentBody, "ball", {});
        ASSERT_EQ(pairs.size(), 3u);  // two palm boxes and the finger capsule
        for (const ContactPair& pair : pairs) {
            EXPECT_EQ(pair.b.shape.type, c.shape);
            EXPECT_EQ(pair.b.shape.polytope, pairs[0].b.shape.polytope);
        }
    }
}

TEST(HandObjectPairs, UnloadedMeshGeometryIsRejectedNamingBodyAndGeometry) {
    model::ModelDescription description = makeHandWithBall();
    model::Geometry& geometry = description.updBody("index_proximal")->geometry[0];
    geometry.type = model::Geometry::Type::Mesh;
    geometry.meshFile = "phalanx.stl";
    const system::MultibodyModel model(description);
    try {
        makeHandObjectPairs(model, isHandSegmentBody, "ball", {});
        FAIL() << "mesh without triangles accepted";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()),
                  "body 'index_proximal' geometry 'index_capsule': mesh 'phalanx.stl' has no "
                  "loaded triangles; contact needs the mesh read from its file");
    }
}

TEST(HandObjectPairs, AnthropometricHandAgainstAnAddedBall) {
    system::MultibodyModel arm(model::buildBodyModel(model::BuildOptions{}));
    const model::Body ball = model::buildBallModel().bodies.front();
    const SimTK::MobilizedBody::Free ballMobod(
        arm.updMatter().updGround(),
        SimTK::Body::Rigid(
            SimTK::MassProperties(ball.mass, SimTK::Vec3(0), SimTK::UnitInertia::sphere(0.045))));
    const std::vector<ContactPair> pairs =
        makeHandObjectPairs(arm, isHandSegmentBody, ballMobod, ball, ContactParameters{});
    std::size_t handGeometry = 0;
    for (const model::Body& body : arm.getDescription().bodies) {
        if (body.segment == "hand" && !body.isVirtual()) handGeometry += body.geometry.size();
    }
    EXPECT_EQ(pairs.size(), handGeometry);
    EXPECT_GE(pairs.size(), 17u);  // 15 phalanx capsules (thumb metacarpal included), 2 palm boxes
    for (const ContactPair& pair : pairs) {
        EXPECT_EQ(pair.b.body.getMobilizedBodyIndex(), ballMobod.getMobilizedBodyIndex());
    }
}

}  // namespace
}  // namespace graspsim::contact
