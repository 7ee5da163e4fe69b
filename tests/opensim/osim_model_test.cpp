// OpenSim export: the .osim, read back with a plain XML parser and its joint frames composed as
// OpenSim composes them (PinJoint about z, SliderJoint along x, frame-fixed x-y-z orientations),
// puts every body where Simbody puts graspsim's model (1e-9 m), at many joint angles; masses,
// centres of mass, inertias, ranges and geometry are the description's.

#include "graspsim/opensim/osim_model.h"

#include "graspsim/error.h"
#include "graspsim/model/body_model.h"
#include "graspsim/model/object_model.h"
#include "graspsim/system/multibody_model.h"

#include <gtest/gtest.h>
#include <simbody/Simbody.h>
#include <tinyxml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace graspsim::opensim {
namespace {

constexpr double kTolerance = 1e-9;
constexpr double kPi = 3.14159265358979323846;

std::vector<double> parseNumbers(const TiXmlElement& parent, const char* tag) {
    const TiXmlElement* element = parent.FirstChildElement(tag);
    EXPECT_NE(element, nullptr) << "missing <" << tag << "> in <" << parent.Value() << ">";
    std::vector<double> values;
    if (!element || !element->GetText()) return values;
    std::istringstream in(element->GetText());
    for (double v; in >> v;) values.push_back(v);
    return values;
}

std::string getText(const TiXmlElement& parent, const char* tag) {
    const TiXmlElement* element = parent.FirstChildElement(tag);
    return element && element->GetText() ? element->GetText() : "";
}

// An OpenSim PhysicalOffsetFrame: its parent's path and X_PF, orientation a frame-fixed x-y-z sequence.
struct OffsetFrame {
    std::string parentBody;
    SimTK::Transform X_PF;
};

OffsetFrame parseOffsetFrame(const TiXmlElement& frame) {
    std::string path = getText(frame, "socket_parent");
    const std::vector<double> p = parseNumbers(frame, "translation"), a = parseNumbers(frame, "orientation");
    const SimTK::Rotation R(SimTK::BodyRotationSequence, a.at(0), SimTK::XAxis, a.at(1), SimTK::YAxis, a.at(2), SimTK::ZAxis);
    const std::string prefix = "/bodyset/";
    return {path.rfind(prefix, 0) == 0 ? path.substr(prefix.size()) : path.substr(1), SimTK::Transform(R, SimTK::Vec3(p[0], p[1], p[2]))};
}

struct OsimJoint {
    std::string type, name;
    OffsetFrame parent, child;  // child.parentBody is the child body
    std::vector<double> range;
    double defaultValue = 0;
    std::string clamped;
};

struct OsimDocument {
    TiXmlDocument xml;
    const TiXmlElement* model = nullptr;
    std::vector<OsimJoint> joints;
    std::map<std::string, const TiXmlElement*> bodies;
};

OffsetFrame findFrame(const TiXmlElement& joint, const std::string& name) {
    for (const TiXmlElement* f = joint.FirstChildElement("frames")->FirstChildElement(); f; f = f->NextSiblingElement()) {
        if (f->Attribute("name") == name) return parseOffsetFrame(*f);
    }
    ADD_FAILURE() << "joint " << joint.Attribute("name") << " has no frame " << name;
    return {};
}

OsimJoint parseJoint(const TiXmlElement& element) {
    OsimJoint joint{element.Value(), element.Attribute("name"), findFrame(element, getText(element, "socket_parent_frame")),
                    findFrame(element, getText(element, "socket_child_frame")), {}, 0, ""};
    if (const TiXmlElement* coordinates = element.FirstChildElement("coordinates")) {
        const TiXmlElement& c = *coordinates->FirstChildElement("Coordinate");
        EXPECT_EQ(std::string(c.Attribute("name")), joint.name);
        joint.range = parseNumbers(c, "range");
        joint.defaultValue = parseNumbers(c, "default_value").at(0);
        joint.clamped = getText(c, "clamped");
    }
    return joint;
}

void parseOsim(const std::string& text, OsimDocument& doc) {
    doc.xml.Parse(text.c_str());
    ASSERT_FALSE(doc.xml.Error()) << doc.xml.ErrorDesc();
    const TiXmlElement* root = doc.xml.RootElement();
    ASSERT_EQ(std::string(root->Value()), "OpenSimDocument");
    ASSERT_EQ(std::string(root->Attribute("Version")), "40000");
    doc.model = root->FirstChildElement("Model");
    ASSERT_NE(doc.model, nullptr);
    for (const TiXmlElement* b = doc.model->FirstChildElement("BodySet")->FirstChildElement("objects")->FirstChildElement("Body"); b;
         b = b->NextSiblingElement("Body")) {
        doc.bodies[b->Attribute("name")] = b;
    }
    for (const TiXmlElement* j = doc.model->FirstChildElement("JointSet")->FirstChildElement("objects")->FirstChildElement(); j;
         j = j->NextSiblingElement()) {
        doc.joints.push_back(parseJoint(*j));
    }
}

// The joint's own motion X_FM(q): OpenSim's PinJoint turns about z, its SliderJoint slides along x.
SimTK::Transform calcMobilizerTransform(const std::string& type, double q) {
    if (type == "PinJoint") return SimTK::Transform(SimTK::Rotation(q, SimTK::ZAxis));
    if (type == "SliderJoint") return SimTK::Transform(SimTK::Vec3(q, 0, 0));
    EXPECT_EQ(type, "WeldJoint");
    return SimTK::Transform();
}

// Every body's pose in ground, composing X_GC = X_GP X_PF X_FM(q) X_CM^-1 from the root outward.
std::map<std::string, SimTK::Transform> composePoses(const std::vector<OsimJoint>& joints, const std::map<std::string, double>& q) {
    std::map<std::string, SimTK::Transform> X_G{{"ground", SimTK::Transform()}};
    for (std::size_t resolved = 0, pass = 0; resolved < joints.size() && pass <= joints.size(); ++pass) {
        for (const OsimJoint& j : joints) {
            if (X_G.count(j.child.parentBody) || !X_G.count(j.parent.parentBody)) continue;
            const double angle = q.count(j.name) ? q.at(j.name) : 0.0;
            X_G[j.child.parentBody] = X_G[j.parent.parentBody] * j.parent.X_PF * calcMobilizerTransform(j.type, angle) * ~j.child.X_PF;
            ++resolved;
        }
    }
    return X_G;
}

double calcRotationError(const SimTK::Rotation& A, const SimTK::Rotation& B) {
    const SimTK::Mat33 difference = A.asMat33() - B.asMat33();
    double largest = 0;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 3; ++c) largest = std::max(largest, std::abs(difference(r, c)));
    }
    return largest;
}

// Poses of the .osim against Simbody's for `model` at `count` random joint-angle sets in range.
void expectSamePoses(const model::ModelDescription& model, int count) {
    OsimDocument doc;
    parseOsim(writeOsim(model), doc);
    system::MultibodyModel multibody(model);
    SimTK::State state = multibody.realizeTopology();
    std::mt19937 random(19);
    for (int set = 0; set < count; ++set) {
        std::map<std::string, double> q;
        for (const OsimJoint& j : doc.joints) {
            if (j.range.empty()) continue;
            q[j.name] = std::uniform_real_distribution<double>(j.range[0], j.range[1])(random);
            multibody.setJointPosition(state, j.name, q[j.name]);
        }
        multibody.getSystem().realize(state, SimTK::Stage::Position);
        const auto X_G = composePoses(doc.joints, q);
        for (const model::Body& body : model.bodies) {
            ASSERT_TRUE(X_G.count(body.name)) << body.name << " not reached from ground";
            const SimTK::Transform& X_GB = multibody.getMobilizedBody(body.name).getBodyTransform(state);
            EXPECT_LT((X_G.at(body.name).p() - X_GB.p()).norm(), kTolerance) << body.name << " in set " << set;
            EXPECT_LT(calcRotationError(X_G.at(body.name).R(), X_GB.R()), kTolerance) << body.name << " in set " << set;
        }
    }
}

model::ModelDescription buildArm() {
    model::BuildOptions options;
    options.subject = anthropometry::getReferenceSubject(anthropometry::Sex::Male);
    return model::buildBodyModel(options);
}

TEST(OsimModel, EveryBodyOfTheArmIsWhereSimbodyPutsIt) { expectSamePoses(buildArm(), 20); }

// Axes along and against every direction, a slider, a welded body and a root pose at pitch pi/2
// (gimbal lock of the x-y-z angles).
model::ModelDescription buildOddModel() {
    model::ModelDescription m;
    m.name = "odd";
    m.X_GR = model::Transform::axisAngle({0, 1, 0}, kPi / 2, {0.1, 0.2, 0.3});
    const model::Vec3 axes[] = {{0, 0, -1}, {1, 0, 0}, {0, -1, 0}, {0.6, 0, 0.8}, {0, 0, 1}};
    for (int i = 0; i <= 6; ++i) {
        model::Body b;
        b.name = "b" + std::to_string(i);
        b.mass = 0.5 + i;
        b.p_BCm = {0.01 * i, -0.02, 0.03};
        b.inertia = {0.02, 0.03, 0.04, 0.001, -0.002, 0.003};
        m.bodies.push_back(b);
        if (i == 0) continue;
        model::Joint j;
        j.name = "j" + std::to_string(i);
        j.parent = "b" + std::to_string(i - 1);
        j.child = b.name;
        j.X_PJ = model::Transform::axisAngle({0.48, 0.6, 0.64}, 0.3 * i, {0.05, -0.1 * i, 0.02});
        j.type = i == 5 ? model::Joint::Type::Prismatic : i == 6 ? model::Joint::Type::Fixed : model::Joint::Type::Revolute;
        j.axis = i == 6 ? model::Vec3{0, 0, 1} : axes[i - 1];
        j.lower = j.type == model::Joint::Type::Prismatic ? -0.05 : -2.5;
        j.upper = j.type == model::Joint::Type::Prismatic ? 0.04 : 2.0;
        m.joints.push_back(j);
    }
    return m;
}

TEST(OsimModel, AnyAxisSlidersWeldsAndGimbalLockComposeExactly) { expectSamePoses(buildOddModel(), 20); }

TEST(OsimModel, BodiesAndCoordinatesCarryTheDescriptionsValues) {
    const model::ModelDescription arm = buildArm();
    OsimDocument doc;
    parseOsim(writeOsim(arm), doc);
    ASSERT_EQ(doc.bodies.size(), arm.bodies.size());
    for (const model::Body& body : arm.bodies) {
        const TiXmlElement& b = *doc.bodies.at(body.name);
        EXPECT_EQ(parseNumbers(b, "mass").at(0), body.mass) << body.name;  // 17 digits: exact
        EXPECT_EQ(parseNumbers(b, "mass_center"), std::vector<double>(body.p_BCm.begin(), body.p_BCm.end())) << body.name;
        const model::Inertia& I = body.inertia;
        EXPECT_EQ(parseNumbers(b, "inertia"), (std::vector<double>{I.xx, I.yy, I.zz, I.xy, I.xz, I.yz})) << body.name;
    }
    ASSERT_EQ(doc.joints.size(), arm.joints.size() + 1);  // and the root's weld to ground
    EXPECT_EQ(doc.joints.front().type, "WeldJoint");
    for (const model::Joint& joint : arm.joints) {
        const auto j = std::find_if(doc.joints.begin(), doc.joints.end(), [&](const OsimJoint& o) { return o.name == joint.name; });
        ASSERT_NE(j, doc.joints.end()) << joint.name;
        EXPECT_EQ(j->type, "PinJoint") << joint.name;
        EXPECT_EQ(j->range, (std::vector<double>{joint.lower, joint.upper})) << joint.name;
        EXPECT_EQ(j->defaultValue, std::clamp(0.0, joint.lower, joint.upper)) << joint.name;
        EXPECT_EQ(j->clamped, "true");
    }
}

TEST(OsimModel, ShapesSitWhereTheDescriptionPutsThem) {
    const model::ModelDescription arm = buildArm();
    OsimDocument doc;
    parseOsim(writeOsim(arm), doc);
    int capsules = 0;
    for (const model::Body& body : arm.bodies) {
        std::map<std::string, OffsetFrame> frames;
        if (const TiXmlElement* components = doc.bodies.at(body.name)->FirstChildElement("components")) {
            for (const TiXmlElement* f = components->FirstChildElement("PhysicalOffsetFrame"); f; f = f->NextSiblingElement()) {
                frames[f->Attribute("name")] = parseOffsetFrame(*f);
                EXPECT_EQ(frames[f->Attribute("name")].parentBody, body.name);
            }
        }
        for (const model::Geometry& g : body.geometry) {
            ASSERT_TRUE(frames.count(g.name + "_frame")) << body.name << " " << g.name;
            const SimTK::Transform& X_BF = frames.at(g.name + "_frame").X_PF;
            const SimTK::Vec3 p_BG(g.X_BG.p[0], g.X_BG.p[1], g.X_BG.p[2]);
            EXPECT_LT((X_BF.p() - p_BG).norm(), kTolerance);
            if (g.type != model::Geometry::Type::Capsule) continue;
            ++capsules;
            // OpenSim's cylinder lies along its frame's y; graspsim's capsule along G's z.
            const SimTK::Vec3 z_BG = SimTK::Vec3(g.X_BG.R[2], g.X_BG.R[5], g.X_BG.R[8]);
            EXPECT_LT((X_BF.R().y() - z_BG).norm(), kTolerance) << g.name;
            EXPECT_LT((frames.at(g.name + "_cap_pos_frame").X_PF.p() - (p_BG + g.length / 2 * z_BG)).norm(), kTolerance);
            EXPECT_LT((frames.at(g.name + "_cap_neg_frame").X_PF.p() - (p_BG - g.length / 2 * z_BG)).norm(), kTolerance);
        }
    }
    EXPECT_GT(capsules, 10);  // the finger segments
}

// Each object shape becomes its OpenSim geometry: the text names the element and its sizes.
TEST(OsimModel, ObjectShapesBecomeOpenSimGeometry) {
    model::TriangleMesh tetrahedron;
    tetrahedron.vertices = {{0, 0, 0}, {0.03, 0, 0}, {0, 0.03, 0}, {0, 0, 0.03}};
    tetrahedron.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    const std::pair<model::ModelDescription, std::vector<std::string>> cases[] = {
        {model::buildCylinderModel(0.3, 0.02, 0.1), {"<Cylinder name=\"cylinder_shape\">", "<half_height>0.05"}},
        {model::buildCapsuleModel(0.2, 0.015, 0.05), {"<Cylinder name=\"capsule_shape\">", "<Sphere name=\"capsule_shape_cap_pos\">"}},
        {model::buildEllipsoidModel(0.1, {0.05, 0.04, 0.03}), {"<Ellipsoid name=\"ellipsoid_shape\">", "<radii>0.05"}},
        {model::buildMeshModel(0.1, tetrahedron, "meshes/tetrahedron.stl", {2, 2, 2}),
         {"<Mesh name=\"mesh_shape\">", "<mesh_file>meshes/tetrahedron.stl</mesh_file>", "<scale_factors>2 2 2</scale_factors>"}},
    };
    for (const auto& [object, expected] : cases) {
        const std::string text = writeOsim(object);
        for (const std::string& part : expected) EXPECT_NE(text.find(part), std::string::npos) << part << " not in\n" << text;
    }
}

TEST(OsimModel, OrientationAnglesRebuildTheRotation) {
    std::mt19937 random(7);
    std::uniform_real_distribution<double> angle(-kPi, kPi);
    for (int i = 0; i < 200; ++i) {
        const SimTK::Rotation R(SimTK::Quaternion(angle(random), angle(random), angle(random), angle(random)).normalize());
        const SimTK::Mat33 M = R.asMat33();
        std::array<double, 9> rowMajor;
        for (int r = 0; r < 3; ++r) for (int c = 0; c < 3; ++c) rowMajor[3 * r + c] = M(r, c);
        const auto a = calcBodyXyzAngles(rowMajor);
        const SimTK::Rotation back(SimTK::BodyRotationSequence, a[0], SimTK::XAxis, a[1], SimTK::YAxis, a[2], SimTK::ZAxis);
        EXPECT_LT(calcRotationError(R, back), 1e-14);
    }
}

TEST(OsimModel, RejectsABodyNamedGround) {
    model::ModelDescription m = buildOddModel();
    m.bodies[3].name = "ground";
    m.joints[2].child = "ground";
    m.joints[3].parent = "ground";
    try {
        writeOsim(m);
        FAIL() << "accepted a body named ground";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("\"ground\""), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace graspsim::opensim
