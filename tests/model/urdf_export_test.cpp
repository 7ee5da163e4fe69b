// URDF export: the written text reads back to the same description (every number to 1e-9,
// most of them bit for bit), urdfdom accepts it, and foreign readers see real shapes.

#include "graspsim/model/object_model.h"
#include "graspsim/model/urdf_export.h"
#include "graspsim/model/urdf_import.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>
#include <urdf_parser/urdf_parser.h>

#include <cmath>
#include <string>
#include <tuple>

namespace graspsim::model {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTolerance = 1e-9;

const Vec3 kX{1, 0, 0}, kY{0, 1, 0}, kZ{0, 0, 1};

// R = Rz(yaw) Ry(pitch) Rx(roll), built from axis-angle rotations, not from the code under test.
Transform makePose(double roll, double pitch, double yaw, const Vec3& p) {
    Transform X = Transform::axisAngle(kZ, yaw) * Transform::axisAngle(kY, pitch) * Transform::axisAngle(kX, roll);
    X.p = p;
    return X;
}

Geometry makeGeometry(Geometry::Type type, const std::string& name, const Transform& X_BG) {
    Geometry g;
    g.type = type;
    g.name = name;
    g.X_BG = X_BG;
    return g;
}

Body makeBody(const std::string& name, double mass, const Vec3& p_BCm, const Inertia& inertia) {
    Body b;
    b.name = name;
    b.segment = "hand";
    b.mass = mass;
    b.p_BCm = p_BCm;
    b.inertia = inertia;
    return b;
}

Joint makeJoint(const std::string& name, Joint::Type type, const std::string& parent, const std::string& child,
                const Transform& X_PJ) {
    Joint j;
    j.name = name;
    j.type = type;
    j.parent = parent;
    j.child = child;
    j.X_PJ = X_PJ;
    return j;
}

std::vector<Body> makeBodies() {
    Body palm = makeBody("palm", 0.2512345678901234, {0.01234567890123, -0.002, 0.0456789},
                         {3.1e-4, 2.7e-4, 1.9e-4, 1.2e-5, -7e-6, 3.3e-6});
    Geometry box = makeGeometry(Geometry::Type::Box, "palm_box", makePose(0, 0.1, 0, {0, 0, 0.04}));
    box.halfLengths = {0.04, 0.01, 0.045};
    Geometry pad = makeGeometry(Geometry::Type::Sphere, "palm_pad", Transform::translation({0.01, -0.012, 0.07}));
    pad.radius = 0.012;
    palm.geometry = {box, pad};

    Body mcpVirtual = makeBody("index_mcp_virtual", 0, {0, 0, 0}, {});
    Body proximal = makeBody("index_proximal", 0.0123456789012345, {0.0011, 0.0152, -0.0003},
                             {2.1e-6, 9.0e-7, 2.0e-6, 1.1e-7, -2.0e-8, 4.0e-8});
    Geometry capsule = makeGeometry(Geometry::Type::Capsule, "index_proximal_capsule", makePose(-kPi / 2, 0.2, 0.1, {0, 0.015, 0}));
    capsule.radius = 0.009;
    capsule.length = 0.03;
    proximal.geometry = {capsule};

    Body distal = makeBody("index_distal", 0.007, {0, 0.01, 0}, {6.0e-7, 3.0e-7, 6.0e-7, 0, 0, 0});
    Geometry tip = makeGeometry(Geometry::Type::Sphere, "index_tip_sphere", Transform::translation({0, 0.018, 0}));
    tip.radius = 0.0075;
    distal.geometry = {tip};

    Body slider = makeBody("thumb_slider", 0.05, {0.001, 0, 0.002}, {1e-5, 1.2e-5, 8e-6, -1e-7, 2e-7, 0});
    slider.segment = "";
    Geometry cylinder = makeGeometry(Geometry::Type::Cylinder, "thumb_cylinder", makePose(0.3, -0.4, 2.5, {0.002, 0, 0.01}));
    cylinder.radius = 0.008;
    cylinder.length = 0.02;
    Geometry mesh = makeGeometry(Geometry::Type::Mesh, "thumb_mesh", makePose(0, 0, kPi, {0, 0, 0}));
    mesh.meshFile = "package://graspsim/meshes/thumb.stl";
    slider.geometry = {cylinder, mesh};

    Body sensor = makeBody("sensor_mount", 0.001, {0, 0, 0}, {1e-8, 1e-8, 1e-8, 0, 0, 0});
    sensor.segment = "";
    return {palm, mcpVirtual, proximal, distal, slider, sensor};
}

std::vector<Joint> makeJoints() {
    Joint abduction = makeJoint("index_mcp_abd", Joint::Type::Revolute, "palm", "index_mcp_virtual",
                                makePose(0.3, kPi / 2, -0.4, {0.03, 0.002, 0.09}));  // gimbal lock: pitch exactly pi/2
    abduction.axis = {1.0 / 3, 2.0 / 3, 2.0 / 3};
    abduction.lower = -0.35;
    abduction.upper = 0.35;
    abduction.stiffness = 0.25;
    abduction.damping = 0.05;
    abduction.restAngle = 0.1;

    Joint flexion = makeJoint("index_mcp_flex", Joint::Type::Revolute, "index_mcp_virtual", "index_proximal",
                              makePose(-1.1, -kPi / 2, 0.7, {0, 0, 0}));  // pitch -pi/2
    flexion.lower = -0.2;
    flexion.upper = kPi / 2;
    flexion.stiffness = 0.25;
    flexion.damping = 0.05;

    Joint pip = makeJoint("index_pip", Joint::Type::Continuous, "index_proximal", "index_distal",
                          makePose(0.9, kPi / 2 - 1e-7, 1.3, {0, 0.03, 0}));  // near gimbal lock, outside its branch
    pip.axis = kX;
    pip.damping = 0.02;

    Joint slide = makeJoint("thumb_slide", Joint::Type::Prismatic, "palm", "thumb_slider", makePose(2.9, 0.5, -2.8, {-0.02, 0.01, 0.03}));
    slide.axis = kX;
    slide.lower = -0.01;
    slide.upper = 0.02;
    slide.stiffness = 50;
    slide.damping = 0.5;
    slide.restAngle = 0.005;

    Joint weld = makeJoint("sensor_weld", Joint::Type::Fixed, "palm", "sensor_mount", makePose(0.1, 0.2, 0.3, {0, -0.01, 0.02}));
    return {abduction, flexion, pip, slide, weld};
}

ModelDescription makeTestModel() {
    ModelDescription model;
    model.name = "roundtrip_hand";
    model.X_GR = Transform::axisAngle({1, 2, 3}, 0.7, {0.1, -0.2, 0.95});
    model.bodies = makeBodies();
    model.joints = makeJoints();
    model.endEffectors = {{"index_tip", "index_distal", {0, 0.0123456789, 0.001}}, {"palm_centre", "palm", {0.01, 0, 0.05}}};
    return model;
}

void expectVecNear(const Vec3& expected, const Vec3& actual, const std::string& what) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(expected[k], actual[k], kTolerance) << what << " [" << k << "]";
}

void expectTransformNear(const Transform& expected, const Transform& actual, const std::string& what) {
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(expected.R[k], actual.R[k], kTolerance) << what << " R[" << k << "]";
    expectVecNear(expected.p, actual.p, what + " p");
}

void expectGeometryNear(const Geometry& expected, const Geometry& actual, const std::string& what) {
    EXPECT_EQ(expected.name, actual.name) << what;
    EXPECT_EQ(expected.type, actual.type) << what;
    expectTransformNear(expected.X_BG, actual.X_BG, what + " X_BG");
    EXPECT_NEAR(expected.radius, actual.radius, kTolerance) << what;
    EXPECT_NEAR(expected.length, actual.length, kTolerance) << what;
    expectVecNear(expected.halfLengths, actual.halfLengths, what + " halfLengths");
    EXPECT_EQ(expected.meshFile, actual.meshFile) << what;
    expectVecNear(expected.meshScale, actual.meshScale, what + " meshScale");
}

void expectBodyNear(const Body& expected, const Body& actual) {
    const std::string what = "body " + expected.name;
    EXPECT_EQ(expected.name, actual.name);
    EXPECT_EQ(expected.segment, actual.segment) << what;
    EXPECT_NEAR(expected.mass, actual.mass, kTolerance) << what;
    expectVecNear(expected.p_BCm, actual.p_BCm, what + " p_BCm");
    const Inertia &I = expected.inertia, &J = actual.inertia;
    const double e[] = {I.xx, I.yy, I.zz, I.xy, I.xz, I.yz}, a[] = {J.xx, J.yy, J.zz, J.xy, J.xz, J.yz};
    for (int k = 0; k < 6; ++k) EXPECT_NEAR(e[k], a[k], kTolerance) << what << " inertia component " << k;
    ASSERT_EQ(expected.geometry.size(), actual.geometry.size()) << what;
    for (std::size_t k = 0; k < expected.geometry.size(); ++k) {
        expectGeometryNear(expected.geometry[k], actual.geometry[k], what + " geometry " + expected.geometry[k].name);
    }
}

void expectJointNear(const Joint& expected, const Joint& actual) {
    const std::string what = "joint " + expected.name;
    EXPECT_EQ(expected.name, actual.name);
    EXPECT_EQ(expected.type, actual.type) << what;
    EXPECT_EQ(expected.parent, actual.parent) << what;
    EXPECT_EQ(expected.child, actual.child) << what;
    expectTransformNear(expected.X_PJ, actual.X_PJ, what + " X_PJ");
    expectVecNear(expected.axis, actual.axis, what + " axis");
    for (const auto& [e, a, field] : {std::tuple{expected.lower, actual.lower, "lower"}, {expected.upper, actual.upper, "upper"},
                                      {expected.stiffness, actual.stiffness, "stiffness"},
                                      {expected.damping, actual.damping, "damping"},
                                      {expected.restAngle, actual.restAngle, "restAngle"}}) {
        EXPECT_NEAR(e, a, kTolerance) << what << " " << field;
    }
}

void expectModelNear(const ModelDescription& expected, const ModelDescription& actual) {
    EXPECT_EQ(expected.name, actual.name);
    expectTransformNear(expected.X_GR, actual.X_GR, "X_GR");
    ASSERT_EQ(expected.bodies.size(), actual.bodies.size());
    for (std::size_t k = 0; k < expected.bodies.size(); ++k) expectBodyNear(expected.bodies[k], actual.bodies[k]);
    ASSERT_EQ(expected.joints.size(), actual.joints.size());
    for (std::size_t k = 0; k < expected.joints.size(); ++k) expectJointNear(expected.joints[k], actual.joints[k]);
    ASSERT_EQ(expected.endEffectors.size(), actual.endEffectors.size());
    for (std::size_t k = 0; k < expected.endEffectors.size(); ++k) {
        EXPECT_EQ(expected.endEffectors[k].name, actual.endEffectors[k].name);
        EXPECT_EQ(expected.endEffectors[k].body, actual.endEffectors[k].body);
        expectVecNear(expected.endEffectors[k].p_BE, actual.endEffectors[k].p_BE, expected.endEffectors[k].name);
    }
}

TEST(UrdfExport, RoundTripReproducesEveryField) {
    const ModelDescription expected = makeTestModel();
    expectModelNear(expected, readUrdf(writeUrdf(expected), "roundtrip.urdf"));
}

TEST(UrdfExport, RotationsSurviveGimbalLockToRoundOff) {
    // Near pitch = +-pi/2 the textbook roll = atan2(r21, r22), yaw = atan2(r10, r00) take angles
    // from numbers of size cos(pitch), so the absolute round-off every composed rotation carries
    // (here from turning about a skew axis and back) becomes angle error / cos(pitch).
    // The rotation must come back to round-off.
    ModelDescription model = makeTestModel();
    const Transform turn = Transform::axisAngle({0.3, -0.5, 0.8}, 1.234), unturn = Transform::axisAngle({0.3, -0.5, 0.8}, -1.234);
    const double pitches[] = {kPi / 2, -kPi / 2, kPi / 2 - 1e-7, -kPi / 2 + 1e-9, kPi / 2 - 1e-13, 0.3};
    for (double pitch : pitches) {
        model.joints.front().X_PJ = turn * unturn * makePose(2.9, pitch, -1.7, {0.03, 0.002, 0.09});
        const ModelDescription back = readUrdf(writeUrdf(model), "gimbal.urdf");
        const Transform& expected = model.joints.front().X_PJ;
        const Transform& actual = back.joints.front().X_PJ;
        for (int k = 0; k < 9; ++k) EXPECT_NEAR(expected.R[k], actual.R[k], 1e-14) << "pitch " << pitch << " R[" << k << "]";
    }
}

TEST(UrdfExport, NumbersWithoutRotationReadBackBitForBit) {
    // urdfdom's own exporter writes 6 significant digits: 0.0123456789012345 would become 0.0123457.
    const ModelDescription expected = makeTestModel();
    const std::string text = writeUrdf(expected);
    EXPECT_NE(text.find("\"0.0123456789012345\""), std::string::npos);
    const ModelDescription actual = readUrdf(text, "roundtrip.urdf");
    const Body& proximal = *actual.findBody("index_proximal");
    EXPECT_EQ(0.0123456789012345, proximal.mass);
    EXPECT_EQ(expected.findBody("index_proximal")->inertia.xy, proximal.inertia.xy);
    EXPECT_EQ(expected.findBody("palm")->p_BCm, actual.findBody("palm")->p_BCm);
    EXPECT_EQ(kPi / 2, actual.findJoint("index_mcp_flex")->upper);
}

TEST(UrdfExport, RepeatedRoundTripsDoNotDrift) {
    const ModelDescription expected = makeTestModel();
    ModelDescription model = expected;
    for (int k = 0; k < 5; ++k) model = readUrdf(writeUrdf(model), "round_" + std::to_string(k) + ".urdf");
    expectModelNear(expected, model);
}

TEST(UrdfExport, UrdfdomReadsTheTextAndSeesTheCapsuleAsCylinderAndTwoSpheres) {
    const ModelDescription model = makeTestModel();
    const urdf::ModelInterfaceSharedPtr parsed = urdf::parseURDF(writeUrdf(model));
    ASSERT_TRUE(parsed);
    EXPECT_EQ("world", parsed->getRoot()->name);  // X_GR is not identity
    EXPECT_EQ(model.bodies.size() + 1, parsed->links_.size());
    EXPECT_EQ(model.joints.size() + 1, parsed->joints_.size());

    const urdf::LinkConstSharedPtr link = parsed->getLink("index_proximal");
    ASSERT_TRUE(link);
    ASSERT_EQ(3u, link->collision_array.size());
    const Geometry& capsule = model.findBody("index_proximal")->geometry.front();
    int cylinders = 0, spheres = 0;
    for (const urdf::CollisionSharedPtr& c : link->collision_array) {
        if (c->geometry->type == urdf::Geometry::CYLINDER) {
            ++cylinders;
            EXPECT_EQ(capsule.radius, std::static_pointer_cast<urdf::Cylinder>(c->geometry)->radius);
            EXPECT_EQ(capsule.length, std::static_pointer_cast<urdf::Cylinder>(c->geometry)->length);
        } else if (c->geometry->type == urdf::Geometry::SPHERE) {
            ++spheres;
            EXPECT_EQ(capsule.radius, std::static_pointer_cast<urdf::Sphere>(c->geometry)->radius);
            // Each cap is centred on a cylinder end: length/2 from the capsule centre.
            const urdf::Vector3& p = c->origin.position;
            const Vec3& centre = capsule.X_BG.p;
            EXPECT_NEAR(capsule.length / 2, std::hypot(p.x - centre[0], p.y - centre[1], p.z - centre[2]), 1e-12);
        }
    }
    EXPECT_EQ(1, cylinders);
    EXPECT_EQ(2, spheres);
    EXPECT_EQ(3u, link->visual_array.size());  // viewers draw the same shapes
}

TEST(UrdfExport, IdentityGroundPoseWritesNoWorldLink) {
    ModelDescription model = makeTestModel();
    model.X_GR = Transform::identity();
    const std::string text = writeUrdf(model);
    const urdf::ModelInterfaceSharedPtr parsed = urdf::parseURDF(text);
    ASSERT_TRUE(parsed);
    EXPECT_EQ("palm", parsed->getRoot()->name);
    EXPECT_EQ(std::string::npos, text.find("\"world\""));
    const ModelDescription back = readUrdf(text, "identity.urdf");
    expectTransformNear(Transform::identity(), back.X_GR, "X_GR");
}

TEST(UrdfExport, VirtualBodyHasNoInertialAndStaysMassless) {
    const std::string text = writeUrdf(makeTestModel());
    const urdf::ModelInterfaceSharedPtr parsed = urdf::parseURDF(text);
    ASSERT_TRUE(parsed);
    EXPECT_FALSE(parsed->getLink("index_mcp_virtual")->inertial);
    EXPECT_TRUE(readUrdf(text, "virtual.urdf").findBody("index_mcp_virtual")->isVirtual());
}

TEST(UrdfExport, ReservedCapsuleSuffixInAGeometryNameIsRejected) {
    ModelDescription model = makeTestModel();
    model.bodies.front().geometry.front().name = "palm__capsule_cylinder";
    try {
        writeUrdf(model);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("'palm__capsule_cylinder'"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("roundtrip_hand"), std::string::npos) << e.what();
    }
}

TEST(UrdfExport, BodyNamedWorldClashesWithTheGroundLink) {
    ModelDescription model = makeTestModel();
    model.bodies.back().name = "world";
    model.joints.back().child = "world";
    EXPECT_THROW(writeUrdf(model), InputError);
}

TEST(UrdfExport, ObjectShapesRoundTrip) {
    // A box mesh with a corner at its file's origin: the geometry frame sits at minus its centroid.
    TriangleMesh box;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j)
            for (int k = 0; k < 2; ++k) box.vertices.push_back({0.04 * i, 0.06 * j, 0.02 * k});
    const int quads[6][4] = {{0, 1, 3, 2}, {4, 6, 7, 5}, {0, 4, 5, 1}, {2, 3, 7, 6}, {0, 2, 6, 4}, {1, 5, 7, 3}};
    for (const auto& q : quads) {
        box.triangles.push_back({q[0], q[1], q[2]});
        box.triangles.push_back({q[0], q[2], q[3]});
    }
    const ModelDescription objects[] = {buildCylinderModel(0.3, 0.02, 0.1), buildCapsuleModel(0.2, 0.015, 0.05),
                                        buildMeshModel(0.1, box, "meshes/box.stl", {0.5, 1, 2})};
    for (const ModelDescription& object : objects) {
        SCOPED_TRACE(object.name);
        const std::string text = writeUrdf(object);
        expectModelNear(object, readUrdf(text, "object.urdf"));
    }
    const std::string meshText = writeUrdf(objects[2]);
    EXPECT_NE(meshText.find("<mesh filename=\"meshes/box.stl\" scale=\"0.5 1 2\""), std::string::npos) << meshText;
    EXPECT_NE(meshText.find("<origin xyz=\"-0.02 -0.03 -0.01"), std::string::npos) << meshText;  // -centroid
}

TEST(UrdfExport, EllipsoidIsRefusedInOneLine) {
    try {
        writeUrdf(buildEllipsoidModel(0.1, {0.05, 0.04, 0.03}));
        FAIL() << "an ellipsoid was written";
    } catch (const InputError& e) {
        const std::string message = e.what();
        EXPECT_EQ(message.find('\n'), std::string::npos) << message;
        EXPECT_NE(message.find("'ellipsoid_shape'"), std::string::npos) << message;
        EXPECT_NE(message.find("0.05 0.04 0.03"), std::string::npos) << message;
        EXPECT_NE(message.find("URDF has no ellipsoid"), std::string::npos) << message;
    }
}

TEST(UrdfExport, InvalidModelIsRejectedBeforeWriting) {
    ModelDescription model = makeTestModel();
    model.joints.front().lower = 1;
    model.joints.front().upper = -1;
    EXPECT_THROW(writeUrdf(model), InputError);
}

}  // namespace
}  // namespace graspsim::model
