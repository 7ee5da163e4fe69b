#include "graspsim/model/urdf_export.h"

#include "urdf_capsule.h"
#include "urdf_extensions.h"
#include "urdf_number.h"
#include "urdf_rotation.h"
#include "urdf_source.h"
#include "urdfdom_parse.h"

#include "graspsim/error.h"

#include <tinyxml.h>

namespace graspsim::model {

namespace {

const char* const kWorldLink = "world";

const char* const kHeaderComment =
    "\n  Written by graspsim. Every number is the shortest decimal text of its double, so it reads back exactly."
    "\n  Collisions named <name>__capsule_cylinder, <name>__capsule_cap_pos and <name>__capsule_cap_neg"
    "\n  are the three parts of one capsule, which URDF lacks; other URDF readers see their union, the capsule."
    "\n  graspsim:* elements hold anatomical segments, joint springs and end-effectors; other readers skip them."
    "\n";

std::string getWorldJointName(const ModelDescription& model) { return "world_to_" + model.bodies.front().name; }

TiXmlElement* appendElement(TiXmlElement& parent, const char* tag) {
    auto* element = new TiXmlElement(tag);
    parent.LinkEndChild(element);
    return element;
}

void appendOrigin(TiXmlElement& parent, const Transform& X) {
    TiXmlElement* origin = appendElement(parent, "origin");
    origin->SetAttribute("xyz", formatUrdfTriple(X.p));
    origin->SetAttribute("rpy", formatUrdfTriple(calcRpyFromRotation(X.R)));
}

void appendShape(TiXmlElement& parent, const Geometry& g) {
    TiXmlElement* geometry = appendElement(parent, "geometry");
    switch (g.type) {
        case Geometry::Type::Sphere:
            appendElement(*geometry, "sphere")->SetAttribute("radius", formatUrdfNumber(g.radius));
            break;
        case Geometry::Type::Box:
            appendElement(*geometry, "box")->SetAttribute(
                "size", formatUrdfTriple({2 * g.halfLengths[0], 2 * g.halfLengths[1], 2 * g.halfLengths[2]}));
            break;
        case Geometry::Type::Cylinder: {
            TiXmlElement* cylinder = appendElement(*geometry, "cylinder");
            cylinder->SetAttribute("radius", formatUrdfNumber(g.radius));
            cylinder->SetAttribute("length", formatUrdfNumber(g.length));
            break;
        }
        case Geometry::Type::Mesh: {
            TiXmlElement* mesh = appendElement(*geometry, "mesh");
            mesh->SetAttribute("filename", g.meshFile);
            // URDF's default scale is 1; writing it only when it differs keeps older files' bytes.
            if (g.meshScale != Vec3{1, 1, 1}) mesh->SetAttribute("scale", formatUrdfTriple(g.meshScale));
            break;
        }
        case Geometry::Type::Capsule:
            break;  // appendGeometry splits capsules first
        case Geometry::Type::Ellipsoid:
            throw InputError("geometry '" + g.name + "' (ellipsoid, semi-axes " + formatUrdfTriple(g.semiAxes) +
                             " m): URDF has no ellipsoid element and graspsim writes none; export a sphere, box, "
                             "cylinder, capsule or mesh (e.g. a tessellated ellipsoid)");
    }
}

// Each shape twice: <collision> for physics, an identical <visual> so viewers draw the model.
void appendGeometry(TiXmlElement& link, const Geometry& g) {
    if (g.type == Geometry::Type::Capsule) {
        for (const Geometry& part : splitCapsule(g)) appendGeometry(link, part);
        return;
    }
    for (const char* tag : {"collision", "visual"}) {
        TiXmlElement* element = appendElement(link, tag);
        if (!g.name.empty()) element->SetAttribute("name", g.name);
        appendOrigin(*element, g.X_BG);
        appendShape(*element, g);
    }
}

void appendInertial(TiXmlElement& link, const Body& body) {
    const Inertia& I = body.inertia;
    const bool empty = body.mass == 0 && body.p_BCm == Vec3{0, 0, 0} && I.xx == 0 && I.yy == 0 && I.zz == 0 &&
                       I.xy == 0 && I.xz == 0 && I.yz == 0;
    if (empty) return;  // a virtual body: URDF's link without <inertial>
    TiXmlElement* inertial = appendElement(link, "inertial");
    appendOrigin(*inertial, Transform::translation(body.p_BCm));
    appendElement(*inertial, "mass")->SetAttribute("value", formatUrdfNumber(body.mass));
    TiXmlElement* inertia = appendElement(*inertial, "inertia");
    const std::pair<const char*, double> moments[] = {{"ixx", I.xx}, {"ixy", I.xy}, {"ixz", I.xz},
                                                      {"iyy", I.yy}, {"iyz", I.yz}, {"izz", I.zz}};
    for (const auto& [name, value] : moments) inertia->SetAttribute(name, formatUrdfNumber(value));
}

void appendLink(TiXmlElement& robot, const Body& body) {
    TiXmlElement* link = appendElement(robot, "link");
    link->SetAttribute("name", body.name);
    appendInertial(*link, body);
    for (const Geometry& g : body.geometry) appendGeometry(*link, g);
}

const char* getUrdfJointType(Joint::Type type) {
    switch (type) {
        case Joint::Type::Revolute: return "revolute";
        case Joint::Type::Continuous: return "continuous";
        case Joint::Type::Prismatic: return "prismatic";
        case Joint::Type::Fixed: break;
    }
    return "fixed";
}

void appendJoint(TiXmlElement& robot, const Joint& joint) {
    TiXmlElement* element = appendElement(robot, "joint");
    element->SetAttribute("name", joint.name);
    element->SetAttribute("type", getUrdfJointType(joint.type));
    appendOrigin(*element, joint.X_PJ);
    appendElement(*element, "parent")->SetAttribute("link", joint.parent);
    appendElement(*element, "child")->SetAttribute("link", joint.child);
    if (joint.type == Joint::Type::Fixed) return;
    appendElement(*element, "axis")->SetAttribute("xyz", formatUrdfTriple(joint.axis));
    if (joint.hasLimits()) {
        TiXmlElement* limit = appendElement(*element, "limit");
        limit->SetAttribute("lower", formatUrdfNumber(joint.lower));
        limit->SetAttribute("upper", formatUrdfNumber(joint.upper));
        limit->SetAttribute("effort", "0");
        limit->SetAttribute("velocity", "0");
    }
    if (joint.damping != 0) appendElement(*element, "dynamics")->SetAttribute("damping", formatUrdfNumber(joint.damping));
}

bool isIdentity(const Transform& X) {
    const Transform I = Transform::identity();
    return X.R == I.R && X.p == I.p;
}

// The encoding reserves two kinds of names; a model using them could not be read back as written.
void checkReservedNames(const ModelDescription& model, const UrdfSource& source) {
    for (const Body& body : model.bodies) {
        for (const Geometry& g : body.geometry) {
            if (hasCapsuleSuffix(g.name)) {
                source.reject(0, "body " + quoted(body.name) + " geometry name", quoted(g.name),
                              "names ending in __capsule_cylinder, __capsule_cap_pos or __capsule_cap_neg are reserved");
            }
        }
    }
    if (isIdentity(model.X_GR)) return;
    if (model.findBody(kWorldLink)) {
        source.reject(0, "body name", quoted(kWorldLink), "with a non-identity X_GR the name is reserved for the ground link");
    }
    if (model.findJoint(getWorldJointName(model))) {
        source.reject(0, "joint name", quoted(getWorldJointName(model)),
                      "with a non-identity X_GR the name is reserved for the ground joint");
    }
}

void appendRobotContents(TiXmlElement& robot, const ModelDescription& model) {
    const bool grounded = !isIdentity(model.X_GR);
    if (grounded) {
        Body world;
        world.name = kWorldLink;
        appendLink(robot, world);
    }
    for (const Body& body : model.bodies) appendLink(robot, body);
    if (grounded) {
        Joint weld;
        weld.name = getWorldJointName(model);
        weld.type = Joint::Type::Fixed;
        weld.parent = kWorldLink;
        weld.child = model.bodies.front().name;
        weld.X_PJ = model.X_GR;
        appendJoint(robot, weld);
    }
    for (const Joint& joint : model.joints) appendJoint(robot, joint);
    appendGraspsimExtensions(model, robot);
}

}  // namespace

std::string writeUrdf(const ModelDescription& model) {
    const UrdfSource source{"model " + quoted(model.name)};
    model.validate(source.name);
    checkReservedNames(model, source);
    TiXmlDocument document;
    document.LinkEndChild(new TiXmlDeclaration("1.0", "utf-8", ""));
    document.LinkEndChild(new TiXmlComment(kHeaderComment));
    auto* robot = new TiXmlElement("robot");
    document.LinkEndChild(robot);
    robot->SetAttribute("name", model.name);
    robot->SetAttribute(std::string("xmlns:") + kGraspsimPrefix, kGraspsimNamespaceUri);
    appendRobotContents(*robot, model);
    TiXmlPrinter printer;
    printer.SetIndent("  ");
    document.Accept(&printer);
    const std::string text = printer.Str();
    const UrdfdomParse check = parseWithUrdfdom(text);
    if (!check.isAccepted()) {
        throw Error("writeUrdf: urdfdom rejects the URDF written for " + source.name + " (a graspsim bug): " + check.errors);
    }
    return text;
}

}  // namespace graspsim::model
