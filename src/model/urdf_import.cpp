#include "graspsim/model/urdf_import.h"

#include "urdf_capsule.h"
#include "urdf_extensions.h"
#include "urdf_inertial.h"
#include "urdf_number.h"
#include "urdf_rotation.h"
#include "urdf_source.h"
#include "urdf_text.h"
#include "urdf_tree_check.h"
#include "urdfdom_parse.h"

#include "graspsim/error.h"

#include <tinyxml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace graspsim::model {

namespace {

void parseXml(const std::string& xml, const UrdfSource& source, TiXmlDocument& document) {
    checkUrdfText(xml, source);  // before TinyXML, which reads past a truncated UTF-8 sequence
    document.Parse(xml.c_str());
    if (document.Error()) {
        source.fail(document.ErrorRow(), "malformed XML at line " + std::to_string(document.ErrorRow()) + ", column " +
                                             std::to_string(document.ErrorCol()) + ": " + document.ErrorDesc());
    }
}

const TiXmlElement& findRobot(const TiXmlDocument& document, const UrdfSource& source) {
    const TiXmlElement* robot = document.FirstChildElement("robot");
    if (!robot) {
        const TiXmlElement* root = document.RootElement();
        source.reject(root ? root->Row() : 0, "root element", root ? "<" + root->ValueStr() + ">" : "(none)",
                      "a URDF file's root element is <robot>");
    }
    if (!robot->Attribute("name")) source.reject(robot->Row(), "<robot> name", "(missing)", "a URDF robot needs a name");
    return *robot;
}

Transform convertPose(const urdf::Pose& pose) {
    Transform X;
    X.R = calcRotationFromQuaternion(pose.rotation.x, pose.rotation.y, pose.rotation.z, pose.rotation.w);
    X.p = {pose.position.x, pose.position.y, pose.position.z};
    return X;
}

Geometry convertCollision(const urdf::Collision& collision, std::size_t index) {
    Geometry g;
    g.name = collision.name.empty() ? "collision_" + std::to_string(index) : collision.name;
    g.X_BG = convertPose(collision.origin);
    const urdf::Geometry& shape = *collision.geometry;
    if (shape.type == urdf::Geometry::SPHERE) {
        g.type = Geometry::Type::Sphere;
        g.radius = static_cast<const urdf::Sphere&>(shape).radius;
    } else if (shape.type == urdf::Geometry::BOX) {
        const urdf::Vector3& size = static_cast<const urdf::Box&>(shape).dim;
        g.type = Geometry::Type::Box;
        g.halfLengths = {size.x / 2, size.y / 2, size.z / 2};
    } else if (shape.type == urdf::Geometry::CYLINDER) {
        g.type = Geometry::Type::Cylinder;
        g.radius = static_cast<const urdf::Cylinder&>(shape).radius;
        g.length = static_cast<const urdf::Cylinder&>(shape).length;
    } else {
        const urdf::Mesh& mesh = static_cast<const urdf::Mesh&>(shape);
        g.type = Geometry::Type::Mesh;
        g.meshFile = mesh.filename;
        g.meshScale = {mesh.scale.x, mesh.scale.y, mesh.scale.z};
    }
    return g;
}

// Names must be unique within a body; foreign files repeat them (or leave them out) freely.
void makeNamesUnique(std::vector<Geometry>& geometry) {
    std::set<std::string> used;
    for (Geometry& g : geometry) {
        std::string name = g.name;
        for (int k = 1; used.count(name); ++k) name = g.name + "_" + std::to_string(k);
        g.name = name;
        used.insert(name);
    }
}

Body convertLink(const TiXmlElement& element, const urdf::Link& link, const UrdfSource& source) {
    Body body;
    body.name = link.name;
    if (link.inertial) setBodyMassProperties(*link.inertial, element.Row(), source, body);
    std::vector<Geometry> geometry;
    for (std::size_t i = 0; i < link.collision_array.size(); ++i) {
        geometry.push_back(convertCollision(*link.collision_array[i], i));
    }
    body.geometry = mergeCapsuleTriplets(geometry, link.name, element.Row(), source);
    makeNamesUnique(body.geometry);
    return body;
}

Joint::Type convertJointType(int type) {
    switch (type) {
        case urdf::Joint::REVOLUTE: return Joint::Type::Revolute;
        case urdf::Joint::CONTINUOUS: return Joint::Type::Continuous;
        case urdf::Joint::PRISMATIC: return Joint::Type::Prismatic;
        default: return Joint::Type::Fixed;  // checkUrdfTree has already rejected the other types
    }
}

Vec3 convertAxis(const urdf::Vector3& a, const std::string& field, int line, const UrdfSource& source) {
    const double norm = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    if (!(norm > 0) || !std::isfinite(norm)) {
        source.reject(line, field, formatUrdfTriple({a.x, a.y, a.z}), "a finite, non-zero direction (it is normalized)");
    }
    return {a.x / norm, a.y / norm, a.z / norm};
}

Joint convertJoint(const TiXmlElement& element, const urdf::Joint& urdfJoint, const UrdfSource& source) {
    const std::string field = "joint " + quoted(urdfJoint.name);
    Joint joint;
    joint.name = urdfJoint.name;
    joint.type = convertJointType(urdfJoint.type);
    joint.parent = urdfJoint.parent_link_name;
    joint.child = urdfJoint.child_link_name;
    joint.X_PJ = convertPose(urdfJoint.parent_to_joint_origin_transform);
    if (joint.type == Joint::Type::Fixed) return joint;  // URDF ignores axis, limits and dynamics here
    joint.axis = convertAxis(urdfJoint.axis, field + " <axis xyz>", element.Row(), source);
    if (joint.hasLimits()) {
        joint.lower = urdfJoint.limits->lower;
        joint.upper = urdfJoint.limits->upper;
        if (!(joint.lower <= joint.upper) || !std::isfinite(joint.lower) || !std::isfinite(joint.upper)) {
            source.reject(element.Row(), field + " <limit>",
                          "lower=" + formatUrdfNumber(joint.lower) + " upper=" + formatUrdfNumber(joint.upper),
                          "finite limits with lower <= upper (rad or m)");
        }
    }
    if (urdfJoint.dynamics) {
        joint.damping = urdfJoint.dynamics->damping;
        if (!(joint.damping >= 0) || !std::isfinite(joint.damping)) {
            source.reject(element.Row(), field + " <dynamics damping>", formatUrdfNumber(joint.damping),
                          "a finite damping >= 0 (N m s/rad or N s/m)");
        }
    }
    return joint;
}

// File order, except that a body never precedes its parent: one pass in file order emits
// each body whose parent is out, repeated until all are out (a single pass for tree-ordered files).
std::vector<Body> orderParentsFirst(std::vector<Body> bodies, const std::vector<Joint>& joints) {
    std::vector<Body> ordered;
    std::set<std::string> emitted;
    while (!bodies.empty()) {
        for (auto it = bodies.begin(); it != bodies.end();) {
            const auto parentJoint = std::find_if(joints.begin(), joints.end(), [&](const Joint& j) { return j.child == it->name; });
            if (parentJoint != joints.end() && !emitted.count(parentJoint->parent)) {
                ++it;
                continue;
            }
            emitted.insert(it->name);
            ordered.push_back(std::move(*it));
            it = bodies.erase(it);
        }
    }
    return ordered;
}

// ROS's convention for a robot bolted to the ground: a massless "world" root and one fixed joint.
void foldWorldLink(ModelDescription& model) {
    const Body& root = model.bodies.front();
    const Inertia& I = root.inertia;
    const bool bare = root.mass == 0 && root.geometry.empty() && root.p_BCm == Vec3{0, 0, 0} && I.xx == 0 && I.yy == 0 &&
                      I.zz == 0 && I.xy == 0 && I.xz == 0 && I.yz == 0;
    if (root.name != "world" || !bare) return;
    const auto isWorldJoint = [](const Joint& j) { return j.parent == "world"; };
    const auto joint = std::find_if(model.joints.begin(), model.joints.end(), isWorldJoint);
    if (std::count_if(model.joints.begin(), model.joints.end(), isWorldJoint) != 1 || joint->type != Joint::Type::Fixed) return;
    model.X_GR = joint->X_PJ;
    model.joints.erase(joint);
    model.bodies.erase(model.bodies.begin());  // its only child, the new root, is next in parent-first order
}

}  // namespace

ModelDescription readUrdf(const std::string& xml, const std::string& sourceName) {
    const UrdfSource source{sourceName};
    TiXmlDocument document;
    parseXml(xml, source, document);
    const TiXmlElement& robot = findRobot(document, source);
    checkUrdfTree(robot, source);
    const UrdfdomParse parsed = parseWithUrdfdom(xml);
    if (!parsed.isAccepted()) {
        source.fail(0, "urdfdom rejected the file: " + (parsed.errors.empty() ? "(no reason given)" : parsed.errors));
    }
    ModelDescription model;
    model.name = parsed.model->getName();
    for (const TiXmlElement* e = robot.FirstChildElement("link"); e; e = e->NextSiblingElement("link")) {
        model.bodies.push_back(convertLink(*e, *parsed.model->getLink(e->Attribute("name")), source));
    }
    for (const TiXmlElement* e = robot.FirstChildElement("joint"); e; e = e->NextSiblingElement("joint")) {
        model.joints.push_back(convertJoint(*e, *parsed.model->getJoint(e->Attribute("name")), source));
    }
    model.bodies = orderParentsFirst(std::move(model.bodies), model.joints);
    foldWorldLink(model);
    applyGraspsimExtensions(robot, source, model);
    model.validate(source.name);
    return model;
}

ModelDescription importUrdf(const std::string& path) {
    std::error_code error;
    if (std::filesystem::is_directory(path, error)) {
        throw InputError(path + ": URDF file = a directory is not accepted; accepted: a readable URDF file");
    }
    std::ifstream in(path, std::ios::binary);
    if (!in) throw InputError(path + ": URDF file cannot be opened; accepted: an existing, readable URDF file");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw InputError(path + ": URDF file could not be read to the end; accepted: a readable URDF file");
    return readUrdf(text.str(), path);
}

}  // namespace graspsim::model
