#include "graspsim/opensim/osim_model.h"

#include "graspsim/error.h"

#include <tinyxml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace graspsim::opensim {

namespace {

using model::Body;
using model::Geometry;
using model::Joint;
using model::ModelDescription;
using model::Transform;
using model::Vec3;

constexpr double kPi = 3.14159265358979323846;

// 17 significant digits: the text reads back to the same double.
std::string formatNumber(double value) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.17g", value == 0 ? 0.0 : value);  // no "-0"
    return buffer;
}

std::string formatNumbers(std::initializer_list<double> values) {
    std::string text;
    for (double v : values) text += (text.empty() ? "" : " ") + formatNumber(v);
    return text;
}

std::string formatVec3(const Vec3& v) { return formatNumbers({v[0], v[1], v[2]}); }

TiXmlElement* appendElement(TiXmlElement& parent, const char* tag, const std::string& name = {}) {
    auto* element = new TiXmlElement(tag);
    if (!name.empty()) element->SetAttribute("name", name);
    parent.LinkEndChild(element);
    return element;
}

void appendText(TiXmlElement& parent, const char* tag, const std::string& text) {
    appendElement(parent, tag)->LinkEndChild(new TiXmlText(text));
}

// A rotation turning unit vector `from` onto unit vector `to` (Rodrigues about their cross product).
Transform calcAlignment(const Vec3& from, const Vec3& to) {
    const Vec3 c{from[1] * to[2] - from[2] * to[1], from[2] * to[0] - from[0] * to[2], from[0] * to[1] - from[1] * to[0]};
    const double s = std::sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
    const double d = from[0] * to[0] + from[1] * to[1] + from[2] * to[2];
    if (s < 1e-15) {
        if (d > 0) return Transform::identity();
        // Opposite: half a turn about any axis perpendicular to `from`.
        const Vec3 perpendicular = std::abs(from[0]) < 0.9 ? Vec3{0, -from[2], from[1]} : Vec3{-from[2], 0, from[0]};
        const double n = std::sqrt(perpendicular[0] * perpendicular[0] + perpendicular[1] * perpendicular[1] +
                                   perpendicular[2] * perpendicular[2]);
        return Transform::axisAngle({perpendicular[0] / n, perpendicular[1] / n, perpendicular[2] / n}, kPi);
    }
    return Transform::axisAngle({c[0] / s, c[1] / s, c[2] / s}, std::atan2(s, d));
}

void appendOffset(TiXmlElement& frame, const std::string& parentPath, const Transform& X) {
    appendText(frame, "socket_parent", parentPath);
    appendText(frame, "translation", formatVec3(X.p));
    const auto angles = calcBodyXyzAngles(X.R);
    appendText(frame, "orientation", formatNumbers({angles[0], angles[1], angles[2]}));
}

TiXmlElement* appendOffsetFrame(TiXmlElement& list, const std::string& name, const std::string& parentPath,
                                const Transform& X) {
    TiXmlElement* frame = appendElement(list, "PhysicalOffsetFrame", name);
    appendOffset(*frame, parentPath, X);
    return frame;
}

std::string getBodyPath(const std::string& body) { return body == "ground" ? "/ground" : "/bodyset/" + body; }

// One displayed shape in frame F (OpenSim geometry, attached to F).
void appendShape(TiXmlElement& geometryList, const std::string& name, const Geometry& g) {
    switch (g.type) {
        case Geometry::Type::Sphere:
            appendText(*appendElement(geometryList, "Sphere", name), "radius", formatNumber(g.radius));
            return;
        case Geometry::Type::Box:
            appendText(*appendElement(geometryList, "Brick", name), "half_lengths", formatVec3(g.halfLengths));
            return;
        case Geometry::Type::Cylinder:
        case Geometry::Type::Capsule: {
            TiXmlElement* cylinder = appendElement(geometryList, "Cylinder", name);
            appendText(*cylinder, "radius", formatNumber(g.radius));
            appendText(*cylinder, "half_height", formatNumber(g.length / 2));
            return;
        }
        case Geometry::Type::Mesh: {
            TiXmlElement* mesh = appendElement(geometryList, "Mesh", name);
            // OpenSim's Geometry scales by scale_factors (default 1 1 1), written only when it differs.
            if (g.meshScale != Vec3{1, 1, 1}) appendText(*mesh, "scale_factors", formatVec3(g.meshScale));
            appendText(*mesh, "mesh_file", g.meshFile);
            return;
        }
        case Geometry::Type::Ellipsoid:
            appendText(*appendElement(geometryList, "Ellipsoid", name), "radii", formatVec3(g.semiAxes));
            return;
    }
}

// The offset frames carrying a geometry's shapes: one, or three for a capsule (cylinder and caps).
void appendGeometry(TiXmlElement& components, const Body& body, const Geometry& g, std::size_t index) {
    const std::string name = g.name.empty() ? "geometry_" + std::to_string(index) : g.name;
    const std::string bodyPath = getBodyPath(body.name);
    const bool alongZ = g.type == Geometry::Type::Cylinder || g.type == Geometry::Type::Capsule;
    const Transform X_BF = alongZ ? g.X_BG * Transform::axisAngle({1, 0, 0}, kPi / 2) : g.X_BG;
    TiXmlElement* frame = appendOffsetFrame(components, name + "_frame", bodyPath, X_BF);
    appendShape(*appendElement(*frame, "attached_geometry"), name, g);
    if (g.type != Geometry::Type::Capsule) return;
    Geometry cap = g;
    cap.type = Geometry::Type::Sphere;
    for (const auto& [suffix, z] : {std::pair<const char*, double>{"_cap_pos", g.length / 2}, {"_cap_neg", -g.length / 2}}) {
        const Transform X_BC = g.X_BG * Transform::translation({0, 0, z});
        TiXmlElement* capFrame = appendOffsetFrame(components, name + suffix + "_frame", bodyPath, X_BC);
        appendShape(*appendElement(*capFrame, "attached_geometry"), name + suffix, cap);
    }
}

void appendBody(TiXmlElement& objects, const Body& body) {
    TiXmlElement* element = appendElement(objects, "Body", body.name);
    if (!body.geometry.empty()) {
        TiXmlElement* components = appendElement(*element, "components");
        for (std::size_t i = 0; i < body.geometry.size(); ++i) appendGeometry(*components, body, body.geometry[i], i);
    }
    appendText(*element, "mass", formatNumber(body.mass));
    appendText(*element, "mass_center", formatVec3(body.p_BCm));
    const model::Inertia& I = body.inertia;
    appendText(*element, "inertia", formatNumbers({I.xx, I.yy, I.zz, I.xy, I.xz, I.yz}));
}

const char* getOpenSimJointType(Joint::Type type) {
    switch (type) {
        case Joint::Type::Revolute:
        case Joint::Type::Continuous: return "PinJoint";
        case Joint::Type::Prismatic: return "SliderJoint";
        case Joint::Type::Fixed: break;
    }
    return "WeldJoint";
}

void appendCoordinate(TiXmlElement& joint, const Joint& j) {
    const bool limited = j.hasLimits();
    const double lower = limited ? j.lower : -2 * kPi;
    const double upper = limited ? j.upper : 2 * kPi;
    TiXmlElement* coordinate = appendElement(*appendElement(joint, "coordinates"), "Coordinate", j.name);
    appendText(*coordinate, "default_value", formatNumber(std::clamp(0.0, lower, upper)));
    appendText(*coordinate, "default_speed_value", "0");
    appendText(*coordinate, "range", formatNumbers({lower, upper}));
    appendText(*coordinate, "clamped", limited ? "true" : "false");
    appendText(*coordinate, "locked", "false");
}

void appendJoint(TiXmlElement& objects, const Joint& j) {
    TiXmlElement* element = appendElement(objects, getOpenSimJointType(j.type), j.name);
    const std::string parentFrame = j.parent + "_offset";
    const std::string childFrame = j.child + "_offset";
    appendText(*element, "socket_parent_frame", parentFrame);
    appendText(*element, "socket_child_frame", childFrame);
    if (j.type != Joint::Type::Fixed) appendCoordinate(*element, j);
    // The joint's own axis (z for a pin, x for a slider) turned onto graspsim's axis.
    const Vec3 jointAxis = j.type == Joint::Type::Prismatic ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
    const Transform R_JA = j.type == Joint::Type::Fixed ? Transform::identity() : calcAlignment(jointAxis, j.axis);
    TiXmlElement* frames = appendElement(*element, "frames");
    appendOffsetFrame(*frames, parentFrame, getBodyPath(j.parent), j.X_PJ * R_JA);
    appendOffsetFrame(*frames, childFrame, getBodyPath(j.child), R_JA);
}

void appendModelContents(TiXmlElement& model, const ModelDescription& m) {
    appendText(model, "credits", "Written by graspsim from its model description \"" + m.name + "\".");
    appendText(model, "length_units", "meters");
    appendText(model, "force_units", "N");
    appendText(model, "gravity", formatNumbers({0, -9.81, 0}));
    appendElement(model, "Ground", "ground");
    TiXmlElement* bodies = appendElement(*appendElement(model, "BodySet", "bodyset"), "objects");
    for (const Body& body : m.bodies) appendBody(*bodies, body);
    TiXmlElement* joints = appendElement(*appendElement(model, "JointSet", "jointset"), "objects");
    Joint weld;
    weld.name = "ground_" + m.bodies.front().name;
    weld.type = Joint::Type::Fixed;
    weld.parent = "ground";
    weld.child = m.bodies.front().name;
    weld.X_PJ = m.X_GR;
    appendJoint(*joints, weld);
    for (const Joint& joint : m.joints) appendJoint(*joints, joint);
}

}  // namespace

std::array<double, 3> calcBodyXyzAngles(const std::array<double, 9>& R) {
    // Rx(a) Ry(b) Rz(c): R02 = sin b, R12 = -sin a cos b, R22 = cos a cos b, R01 = -cos b sin c, R00 = cos b cos c.
    const double b = std::atan2(R[2], std::hypot(R[0], R[1]));
    if (std::hypot(R[0], R[1]) < 1e-12) return {0.0, b, std::atan2(R[3], R[4])};  // Ry(b) Rz(c): R10 = sin c, R11 = cos c
    return {std::atan2(-R[5], R[8]), b, std::atan2(-R[1], R[0])};
}

std::string writeOsim(const ModelDescription& model) {
    const std::string source = "model \"" + model.name + "\"";
    model.validate(source);
    if (model.findBody("ground")) {
        throw InputError(source + ": body name \"ground\" is not accepted in an OpenSim model; OpenSim reserves it for the ground frame");
    }
    TiXmlDocument document;
    document.LinkEndChild(new TiXmlDeclaration("1.0", "UTF-8", ""));
    document.LinkEndChild(new TiXmlComment(
        " Written by graspsim: an OpenSim 4 model of the arm and hand (bodies, joints, geometry; no muscles). "
        "Coordinates are named after graspsim's joints. "));
    auto* root = new TiXmlElement("OpenSimDocument");
    root->SetAttribute("Version", "40000");
    document.LinkEndChild(root);
    appendModelContents(*appendElement(*root, "Model", model.name), model);
    TiXmlPrinter printer;
    printer.SetIndent("  ");
    document.Accept(&printer);
    return printer.Str();
}

}  // namespace graspsim::opensim
