// URDF import: a hand-written foreign gripper against hand-computed oracles, and every kind of
// bad input giving one InputError line that names the file and the offending field and value,
// with nothing printed by urdfdom.

#include "graspsim/model/body_model.h"
#include "graspsim/model/urdf_export.h"
#include "graspsim/model/urdf_import.h"

#include "graspsim/error.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace graspsim::model {
namespace {

constexpr double kTolerance = 1e-12;

std::string getFixturePath(const std::string& name) { return std::string(GRASPSIM_TEST_DATA_DIR) + "/" + name; }

ModelDescription importQuietly(const std::string& path) {
    testing::internal::CaptureStderr();
    ModelDescription model = importUrdf(path);
    EXPECT_EQ("", testing::internal::GetCapturedStderr());
    return model;
}

void expectRotationNear(const std::array<double, 9>& expected, const std::array<double, 9>& actual, const std::string& what) {
    for (int k = 0; k < 9; ++k) EXPECT_NEAR(expected[k], actual[k], kTolerance) << what << " R[" << k << "]";
}

void expectInertiaNear(const Inertia& expected, const Inertia& actual, const std::string& what) {
    EXPECT_NEAR(expected.xx, actual.xx, kTolerance) << what;
    EXPECT_NEAR(expected.yy, actual.yy, kTolerance) << what;
    EXPECT_NEAR(expected.zz, actual.zz, kTolerance) << what;
    EXPECT_NEAR(expected.xy, actual.xy, kTolerance) << what;
    EXPECT_NEAR(expected.xz, actual.xz, kTolerance) << what;
    EXPECT_NEAR(expected.yz, actual.yz, kTolerance) << what;
}

TEST(UrdfImportForeign, CountsBodiesJointsAndDegreesOfFreedom) {
    const ModelDescription model = importQuietly(getFixturePath("foreign_gripper.urdf"));
    EXPECT_EQ("test_gripper", model.name);
    EXPECT_EQ(8u, model.bodies.size());  // 9 links less the folded "world"
    EXPECT_EQ(7u, model.joints.size());  // 8 joints less the folded world_mount
    // wrist_roll 1 + four finger revolutes 4 + thumb_slide 1; camera_joint is fixed.
    EXPECT_EQ(6, model.getDofCount());
    EXPECT_TRUE(model.endEffectors.empty());
}

TEST(UrdfImportForeign, BodiesComeRootFirstWithParentsBeforeChildren) {
    const ModelDescription model = importQuietly(getFixturePath("foreign_gripper.urdf"));
    EXPECT_EQ("base_link", model.bodies.front().name);
    for (std::size_t k = 1; k < model.bodies.size(); ++k) {
        const Joint* joint = model.findParentJoint(model.bodies[k].name);
        ASSERT_NE(nullptr, joint) << model.bodies[k].name;
        const auto parent = std::find_if(model.bodies.begin(), model.bodies.end(), [&](const Body& b) { return b.name == joint->parent; });
        EXPECT_LT(parent - model.bodies.begin(), static_cast<std::ptrdiff_t>(k)) << model.bodies[k].name;
    }
}

TEST(UrdfImportForeign, WorldLinkBecomesTheGroundPose) {
    const ModelDescription model = importQuietly(getFixturePath("foreign_gripper.urdf"));
    EXPECT_EQ(nullptr, model.findBody("world"));
    EXPECT_EQ(nullptr, model.findJoint("world_mount"));
    expectRotationNear({0, -1, 0, 1, 0, 0, 0, 0, 1}, model.X_GR.R, "X_GR: yaw of 90 degrees");
    EXPECT_NEAR(0.5, model.X_GR.p[2], kTolerance);
}

TEST(UrdfImportForeign, InertiaIsRotatedFromTheInertialFrameIntoTheLinkFrame) {
    const ModelDescription model = importQuietly(getFixturePath("foreign_gripper.urdf"));
    // left_proximal: diag(2e-5, 1e-5, 2.5e-5) in a frame yawed 30 degrees; with c = cos 30, s = sin 30,
    // I_B = Rz I Rz^T has xx = c^2 a + s^2 b, yy = s^2 a + c^2 b, xy = c s (a - b), zz unchanged.
    const Body& proximal = *model.findBody("left_proximal");
    EXPECT_DOUBLE_EQ(0.03, proximal.mass);
    EXPECT_EQ((Vec3{0.001, 0, 0.02}), proximal.p_BCm);
    expectInertiaNear({1.75e-5, 1.25e-5, 2.5e-5, std::sqrt(3.0) / 4 * 1e-5, 0, 0}, proximal.inertia, "left_proximal");
    // left_distal: diag(3e-6, 2e-6, 4e-6) in a frame rolled 90 degrees about x: y and z swap.
    expectInertiaNear({3e-6, 4e-6, 2e-6, 0, 0, 0}, model.findBody("left_distal")->inertia, "left_distal");
    // right_distal has no rotation: taken as written.
    expectInertiaNear({3e-6, 4e-6, 2e-6, 0, 0, 0}, model.findBody("right_distal")->inertia, "right_distal");
}

TEST(UrdfImportForeign, CollisionsBecomeGeometryAndVisualsAreIgnored) {
    const ModelDescription model = importQuietly(getFixturePath("foreign_gripper.urdf"));
    const Body& base = *model.findBody("base_link");
    ASSERT_EQ(2u, base.geometry.size());
    EXPECT_EQ("collision_0", base.geometry[0].name);  // unnamed in the file
    EXPECT_EQ(Geometry::Type::Box, base.geometry[0].type);
    EXPECT_EQ((Vec3{0.04, 0.03, 0.03}), base.geometry[0].halfLengths);
    EXPECT_EQ((Vec3{0, 0, 0.03}), base.geometry[0].X_BG.p);
    EXPECT_EQ("base_flange", base.geometry[1].name);
    EXPECT_EQ(Geometry::Type::Cylinder, base.geometry[1].type);
    EXPECT_EQ(0.035, base.geometry[1].radius);
    EXPECT_EQ(0.01, base.geometry[1].length);

    const Body& palm = *model.findBody("palm_link");
    ASSERT_EQ(1u, palm.geometry.size());
    EXPECT_EQ(Geometry::Type::Mesh, palm.geometry[0].type);
    EXPECT_EQ("package://test_gripper_description/meshes/palm_collision.stl", palm.geometry[0].meshFile);

    const Body& camera = *model.findBody("camera_link");
    EXPECT_TRUE(camera.isVirtual());  // no <inertial>
    EXPECT_TRUE(camera.geometry.empty());  // its only shape is a <visual>
}

TEST(UrdfImportForeign, JointsKeepTypesFramesAxesLimitsAndDamping) {
    const ModelDescription model = importQuietly(getFixturePath("foreign_gripper.urdf"));
    const Joint& wrist = *model.findJoint("wrist_roll");
    EXPECT_EQ(Joint::Type::Continuous, wrist.type);
    EXPECT_EQ(0.1, wrist.damping);

    const Joint& distal = *model.findJoint("left_distal_joint");
    EXPECT_EQ(Joint::Type::Revolute, distal.type);
    EXPECT_EQ((Vec3{0, 1, 0}), distal.axis);  // "0 2 0" normalized
    EXPECT_EQ(0.0, distal.lower);
    EXPECT_EQ(1.5, distal.upper);

    const Joint& right = *model.findJoint("right_proximal_joint");
    expectRotationNear({-1, 0, 0, 0, -1, 0, 0, 0, 1}, right.X_PJ.R, "right_proximal_joint: yaw of 180 degrees");

    const Joint& thumb = *model.findJoint("thumb_slide_joint");
    EXPECT_EQ(Joint::Type::Prismatic, thumb.type);
    EXPECT_EQ(-0.01, thumb.lower);
    EXPECT_EQ(0.025, thumb.upper);
    EXPECT_EQ(2.0, thumb.damping);
    EXPECT_EQ(0.0, thumb.stiffness);
    expectRotationNear({1, 0, 0, 0, 0, 1, 0, -1, 0}, thumb.X_PJ.R, "thumb_slide_joint: roll of -90 degrees");
    EXPECT_EQ((Vec3{0, 0.03, 0.02}), thumb.X_PJ.p);

    EXPECT_EQ(Joint::Type::Fixed, model.findJoint("camera_joint")->type);
}

// ---- bad input -------------------------------------------------------------------------------

const std::string kInertial =
    "<inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>";

std::string makeLink(const std::string& name, const std::string& inner = kInertial) {
    return "<link name=\"" + name + "\">" + inner + "</link>\n";
}

std::string makeJoint(const std::string& name, const std::string& parent, const std::string& child,
                      const std::string& type = "revolute",
                      const std::string& inner = "<axis xyz=\"0 0 1\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>") {
    return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent + "\"/><child link=\"" + child +
           "\"/>" + inner + "</joint>\n";
}

std::string makeRobot(const std::string& contents) {
    return "<?xml version=\"1.0\"?>\n<robot name=\"bad\" xmlns:graspsim=\"https://graspsim.invalid/urdf-extensions\">\n" +
           contents + "</robot>\n";
}

// The message of the InputError readUrdf throws, checking that nothing reached stderr.
std::string getImportError(const std::string& xml, const std::string& source) {
    testing::internal::CaptureStderr();
    std::string message = "(no InputError)";
    try {
        readUrdf(xml, source);
    } catch (const InputError& e) {
        message = e.what();
    }
    EXPECT_EQ("", testing::internal::GetCapturedStderr()) << source;
    EXPECT_EQ(std::string::npos, message.find('\n')) << "one line: " << message;
    EXPECT_EQ(0u, message.rfind(source, 0)) << "starts with the source: " << message;
    return message;
}

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string::npos, (text).find(part)) << "in: " << (text)

TEST(UrdfImportErrors, ValidBaseModelReads) {
    const ModelDescription model = readUrdf(makeRobot(makeLink("a") + makeLink("b") + makeJoint("j", "a", "b")), "ok.urdf");
    EXPECT_EQ(2u, model.bodies.size());
}

TEST(UrdfImportErrors, MalformedXmlNamesLineAndColumn) {
    const std::string message = getImportError(makeRobot(makeLink("a") + "<link name=\"b\">\n<inertial>\n</link>\n"), "malformed.urdf");
    EXPECT_CONTAINS(message, "malformed.urdf:");
    EXPECT_CONTAINS(message, "malformed XML at line");
    EXPECT_CONTAINS(message, "column");
}

// TinyXML reads past the end of its buffer after a truncated UTF-8 sequence (the URDF fuzzer's
// finding): the import refuses such bytes before any parser sees them, naming line and byte.
TEST(UrdfImportErrors, TruncatedUtf8AtTheEndIsRefusedBeforeParsing) {
    const std::string robot = makeRobot(makeLink("a"));
    const std::string message = getImportError(robot + "\xdc", "truncated.urdf");
    EXPECT_CONTAINS(message, "truncated.urdf:5: byte " + std::to_string(robot.size()) + " = 0xdc is not accepted");
    EXPECT_CONTAINS(message, "UTF-8");
}

TEST(UrdfImportErrors, InvalidUtf8AndNulBytesAreRefused) {
    const std::string link = makeLink("a");
    for (const std::string bad : {std::string("\xc0\xaf"), std::string("\xed\xa0\x80"), std::string("\xff"),
                                  std::string("\x80"), std::string(1, '\0')}) {
        const std::string message = getImportError(makeRobot("<!-- " + bad + " -->\n" + link), "bad_bytes.urdf");
        EXPECT_CONTAINS(message, "bad_bytes.urdf:3: byte ");
    }
}

TEST(UrdfImportErrors, WellFormedUtf8IsRead) {
    // Two-, three- and four-byte characters in a comment: "Müller, 手, 🖐".
    const std::string xml = makeRobot("<!-- M\xc3\xbcller, \xe6\x89\x8b, \xf0\x9f\x96\x90 -->\n" + makeLink("a"));
    EXPECT_EQ(1u, readUrdf(xml, "utf8.urdf").bodies.size());
}

TEST(UrdfImportErrors, NotARobot) {
    EXPECT_CONTAINS(getImportError("<model name=\"x\"/>", "not_robot.urdf"), "<model>");
}

TEST(UrdfImportErrors, JointReferencingAMissingLink) {
    const std::string message = getImportError(makeRobot(makeLink("a") + makeLink("b") + makeJoint("j", "a", "c")), "missing.urdf");
    EXPECT_CONTAINS(message, "missing.urdf:");
    EXPECT_CONTAINS(message, "joint 'j' child link = 'c'");
}

TEST(UrdfImportErrors, LinkWithTwoParents) {
    const std::string message = getImportError(
        makeRobot(makeLink("a") + makeLink("b") + makeLink("c") + makeJoint("j1", "a", "b") + makeJoint("j2", "c", "b")),
        "two_parents.urdf");
    EXPECT_CONTAINS(message, "link 'b' parent joints");
    EXPECT_CONTAINS(message, "'j1'");
    EXPECT_CONTAINS(message, "'j2'");
}

TEST(UrdfImportErrors, CycleBesideTheRoot) {
    // urdfdom accepts this: r is a unique root; b and c are each other's parent.
    const std::string message = getImportError(
        makeRobot(makeLink("r") + makeLink("b") + makeLink("c") + makeJoint("jb", "c", "b") + makeJoint("jc", "b", "c")),
        "cycle.urdf");
    EXPECT_CONTAINS(message, "cycle");
    EXPECT_CONTAINS(message, "'b'");
    EXPECT_CONTAINS(message, "'c'");
}

TEST(UrdfImportErrors, TwoRoots) {
    const std::string message = getImportError(makeRobot(makeLink("a") + makeLink("b")), "roots.urdf");
    EXPECT_CONTAINS(message, "root links");
    EXPECT_CONTAINS(message, "'a'");
    EXPECT_CONTAINS(message, "'b'");
}

TEST(UrdfImportErrors, InertiaBreakingTheTriangleInequality) {
    const std::string inertial =
        "<inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"3\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>";
    const std::string message = getImportError(makeRobot(makeLink("a", inertial)), "triangle.urdf");
    EXPECT_CONTAINS(message, "link 'a' <inertial> <inertia>");
    EXPECT_CONTAINS(message, "izz=3");
    EXPECT_CONTAINS(message, "triangle inequality");
}

TEST(UrdfImportErrors, TriangleViolationHiddenByARotatedInertiaFrame) {
    // Principal moments (1, 1, 3) rotated 45 degrees about x: the diagonal (1, 2, 2) looks fine.
    const std::string inertial =
        "<inertial><mass value=\"1\"/><inertia ixx=\"1\" iyy=\"2\" izz=\"2\" ixy=\"0\" ixz=\"0\" iyz=\"1\"/></inertial>";
    EXPECT_CONTAINS(getImportError(makeRobot(makeLink("a", inertial)), "hidden.urdf"), "triangle inequality");
}

TEST(UrdfImportErrors, NegativeMomentOfInertia) {
    const std::string inertial =
        "<inertial><mass value=\"1\"/><inertia ixx=\"-1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>";
    const std::string message = getImportError(makeRobot(makeLink("a", inertial)), "negative_ixx.urdf");
    EXPECT_CONTAINS(message, "ixx=-1");
    EXPECT_CONTAINS(message, "positive definite");
}

TEST(UrdfImportErrors, NegativeMass) {
    const std::string inertial =
        "<inertial><mass value=\"-0.5\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>";
    const std::string message = getImportError(makeRobot(makeLink("a", inertial)), "negative_mass.urdf");
    EXPECT_CONTAINS(message, "link 'a' <inertial> <mass value> = -0.5");
}

TEST(UrdfImportErrors, NanMassIsReportedFromUrdfdomWithoutPrinting) {
    const std::string inertial =
        "<inertial><mass value=\"nan\"/><inertia ixx=\"1\" iyy=\"1\" izz=\"1\" ixy=\"0\" ixz=\"0\" iyz=\"0\"/></inertial>";
    const std::string message = getImportError(makeRobot(makeLink("a", inertial)), "nan_mass.urdf");
    EXPECT_CONTAINS(message, "urdfdom rejected the file");
    EXPECT_CONTAINS(message, "mass [nan]");
}

TEST(UrdfImportErrors, LowerLimitAboveUpper) {
    const std::string joint =
        makeJoint("j", "a", "b", "revolute", "<axis xyz=\"0 0 1\"/><limit lower=\"1\" upper=\"-1\" effort=\"1\" velocity=\"1\"/>");
    const std::string message = getImportError(makeRobot(makeLink("a") + makeLink("b") + joint), "limits.urdf");
    EXPECT_CONTAINS(message, "joint 'j' <limit> = lower=1 upper=-1");
}

TEST(UrdfImportErrors, FloatingAndPlanarJoints) {
    for (const std::string type : {"floating", "planar"}) {
        const std::string message =
            getImportError(makeRobot(makeLink("a") + makeLink("b") + makeJoint("free", "a", "b", type, "")), type + ".urdf");
        EXPECT_CONTAINS(message, "joint 'free' type = '" + type + "'");
        EXPECT_CONTAINS(message, "revolute, continuous, prismatic, fixed");
    }
}

TEST(UrdfImportErrors, ZeroAxis) {
    const std::string joint =
        makeJoint("j", "a", "b", "revolute", "<axis xyz=\"0 0 0\"/><limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"1\"/>");
    const std::string message = getImportError(makeRobot(makeLink("a") + makeLink("b") + joint), "axis.urdf");
    EXPECT_CONTAINS(message, "joint 'j' <axis xyz> = 0 0 0");
}

std::string makeCapsuleLink(const std::string& capPosRadius, const std::string& capNegXyz) {
    return makeLink("a", kInertial +
                             "<collision name=\"c__capsule_cylinder\"><geometry><cylinder radius=\"0.01\" length=\"0.04\"/></geometry></collision>"
                             "<collision name=\"c__capsule_cap_pos\"><origin xyz=\"0 0 0.02\"/><geometry><sphere radius=\"" +
                             capPosRadius +
                             "\"/></geometry></collision>"
                             "<collision name=\"c__capsule_cap_neg\"><origin xyz=\"" +
                             capNegXyz + "\"/><geometry><sphere radius=\"0.01\"/></geometry></collision>");
}

TEST(UrdfImportErrors, CapsuleTripletReadsAsOneCapsule) {
    const ModelDescription model = readUrdf(makeRobot(makeCapsuleLink("0.01", "0 0 -0.02")), "capsule.urdf");
    const Body& a = *model.findBody("a");
    ASSERT_EQ(1u, a.geometry.size());
    EXPECT_EQ("c", a.geometry[0].name);
    EXPECT_EQ(Geometry::Type::Capsule, a.geometry[0].type);
    EXPECT_EQ(0.01, a.geometry[0].radius);
    EXPECT_EQ(0.04, a.geometry[0].length);
}

TEST(UrdfImportErrors, CapsuleTripletWithMismatchedRadii) {
    const std::string message = getImportError(makeRobot(makeCapsuleLink("0.012", "0 0 -0.02")), "capsule_radii.urdf");
    EXPECT_CONTAINS(message, "link 'a' capsule 'c' collision 'c__capsule_cap_pos' radius = 0.012");
}

TEST(UrdfImportErrors, CapsuleCapOffTheCylinderEnd) {
    const std::string message = getImportError(makeRobot(makeCapsuleLink("0.01", "0 0 -0.03")), "capsule_cap.urdf");
    EXPECT_CONTAINS(message, "'c__capsule_cap_neg' origin xyz = 0 0 -0.03");
}

TEST(UrdfImportErrors, IncompleteCapsuleTriplet) {
    const std::string link = makeLink("a", kInertial +
                                               "<collision name=\"c__capsule_cylinder\"><geometry><cylinder radius=\"0.01\" "
                                               "length=\"0.04\"/></geometry></collision>");
    EXPECT_CONTAINS(getImportError(makeRobot(link), "capsule_incomplete.urdf"), "'c__capsule_cap_pos' = (missing)");
}

TEST(UrdfImportErrors, ExtensionNamingAnUnknownJoint) {
    const std::string xml = makeRobot(makeLink("a") + makeLink("b") + makeJoint("j", "a", "b") +
                                      "<graspsim:joint name=\"k\" stiffness=\"1\"/>\n");
    EXPECT_CONTAINS(getImportError(xml, "ext_joint.urdf"), "<graspsim:joint> name = 'k'");
}

TEST(UrdfImportErrors, ExtensionWithAMisspelledAttribute) {
    const std::string xml = makeRobot(makeLink("a") + makeLink("b") + makeJoint("j", "a", "b") +
                                      "<graspsim:joint name=\"j\" stifness=\"1\"/>\n");
    EXPECT_CONTAINS(getImportError(xml, "ext_attribute.urdf"), "'stifness'");
}

TEST(UrdfImportErrors, ExtensionWithNegativeStiffness) {
    const std::string xml = makeRobot(makeLink("a") + makeLink("b") + makeJoint("j", "a", "b") +
                                      "<graspsim:joint name=\"j\" stiffness=\"-2\"/>\n");
    EXPECT_CONTAINS(getImportError(xml, "ext_stiffness.urdf"), "stiffness = '-2'");
}

TEST(UrdfImportErrors, ExtensionWithAnUnknownRole) {
    const std::string xml = makeRobot(makeLink("a") + makeLink("b") + makeJoint("j", "a", "b") +
                                      "<graspsim:link name=\"b\" segment=\"hand\" role=\"thumb\"/>\n");
    EXPECT_CONTAINS(getImportError(xml, "ext_role.urdf"), "role = 'thumb'");
}

TEST(UrdfImportNames, BodyRolesSurviveTheRoundTrip) {
    const ModelDescription built = buildBodyModel(BuildOptions{});
    const ModelDescription read = readUrdf(writeUrdf(built), "roles.urdf");
    int palms = 0, digits = 0;
    for (const Body& b : built.bodies) {
        EXPECT_EQ(toString(b.role), toString(read.findBody(b.name)->role)) << b.name;
        palms += b.role == BodyRole::Palm && !b.isVirtual();
        digits += b.role == BodyRole::Digit && !b.isVirtual();
    }
    EXPECT_EQ(palms, 1);
    EXPECT_EQ(digits, 15);  // three phalanges on each of five digits
}

TEST(UrdfImportNames, RepeatedCollisionNamesAreMadeUnique) {
    const std::string sphere = "<geometry><sphere radius=\"0.01\"/></geometry>";
    const std::string link = makeLink("a", kInertial + "<collision name=\"pad\">" + sphere + "</collision><collision name=\"pad\">" +
                                               sphere + "</collision><collision>" + sphere + "</collision>");
    const ModelDescription model = readUrdf(makeRobot(link), "names.urdf");
    const Body& a = *model.findBody("a");
    ASSERT_EQ(3u, a.geometry.size());
    EXPECT_EQ("pad", a.geometry[0].name);
    EXPECT_EQ("pad_1", a.geometry[1].name);
    EXPECT_EQ("collision_2", a.geometry[2].name);
}

TEST(UrdfImportNames, ExtensionsAreFoundUnderAnyPrefixBoundToTheNamespace) {
    const std::string xml = "<robot name=\"r\" xmlns:gs=\"https://graspsim.invalid/urdf-extensions\">" + makeLink("a") +
                            makeLink("b") + makeJoint("j", "a", "b") +
                            "<gs:joint name=\"j\" stiffness=\"0.25\" rest_angle=\"0.1\"/><gs:link name=\"b\" segment=\"hand\"/>"
                            "<gs:end_effector name=\"tip\" link=\"b\" xyz=\"0 0 0.02\"/></robot>";
    const ModelDescription model = readUrdf(xml, "prefix.urdf");
    EXPECT_EQ(0.25, model.findJoint("j")->stiffness);
    EXPECT_EQ(0.1, model.findJoint("j")->restAngle);
    EXPECT_EQ("hand", model.findBody("b")->segment);
    ASSERT_NE(nullptr, model.findEndEffector("tip"));
    EXPECT_EQ((Vec3{0, 0, 0.02}), model.findEndEffector("tip")->p_BE);
}

TEST(UrdfImportErrors, UnreadableFileNamesThePath) {
    const std::string path = getFixturePath("no_such_file.urdf");
    try {
        importUrdf(path);
        FAIL() << "expected InputError";
    } catch (const InputError& e) {
        EXPECT_CONTAINS(std::string(e.what()), path);
    }
}

}  // namespace
}  // namespace graspsim::model
