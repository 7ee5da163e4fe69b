#include "graspsim/model/model_description.h"

#include "simbody_mass_properties.h"

#include "graspsim/error.h"
#include "graspsim/model/geometry_inertia.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <sstream>

namespace graspsim::model {

Transform Transform::translation(const Vec3& p) {
    Transform X;
    X.p = p;
    return X;
}

Transform Transform::axisAngle(const Vec3& axis, double angle, const Vec3& p) {
    const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    const double x = axis[0] / n, y = axis[1] / n, z = axis[2] / n;
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    Transform X;
    X.R = {t * x * x + c,     t * x * y - s * z, t * x * z + s * y,
           t * x * y + s * z, t * y * y + c,     t * y * z - s * x,
           t * x * z - s * y, t * y * z + s * x, t * z * z + c};
    X.p = p;
    return X;
}

Vec3 Transform::xformFrameVecToBase(const Vec3& v) const {
    return {R[0] * v[0] + R[1] * v[1] + R[2] * v[2],
            R[3] * v[0] + R[4] * v[1] + R[5] * v[2],
            R[6] * v[0] + R[7] * v[1] + R[8] * v[2]};
}

Vec3 Transform::shiftFrameStationToBase(const Vec3& p_BQ) const {
    const Vec3 v = xformFrameVecToBase(p_BQ);
    return {p[0] + v[0], p[1] + v[1], p[2] + v[2]};
}

Transform Transform::operator*(const Transform& X_BC) const {
    Transform X_AC;
    for (int i = 0; i < 3; ++i) {
        for (int j = 0; j < 3; ++j) {
            double sum = 0;
            for (int k = 0; k < 3; ++k) sum += R[3 * i + k] * X_BC.R[3 * k + j];
            X_AC.R[3 * i + j] = sum;
        }
    }
    X_AC.p = shiftFrameStationToBase(X_BC.p);
    return X_AC;
}

namespace {

template <class T>
T* findByName(std::vector<T>& items, const std::string& name) {
    auto it = std::find_if(items.begin(), items.end(), [&](const T& item) { return item.name == name; });
    return it == items.end() ? nullptr : &*it;
}

std::string describe(double value) {
    std::ostringstream out;
    out << value;
    return out.str();
}

[[noreturn]] void fail(const std::string& source, const std::string& field, const std::string& value,
                       const std::string& accepted) {
    throw InputError(source + ": " + field + " = " + value + " is not accepted; " + accepted);
}

void validateInertia(const std::string& source, const Body& body) {
    const Inertia& I = body.inertia;
    const std::string field = "link '" + body.name + "' inertia";
    const double values[] = {I.xx, I.yy, I.zz, I.xy, I.xz, I.yz};
    for (double v : values) {
        if (!std::isfinite(v)) fail(source, field, describe(v), "inertia components must be finite");
    }
    if (body.isVirtual()) return;
    const std::array<double, 3> moments = calcPrincipalMoments(I);
    const std::string shown = "[" + describe(I.xx) + " " + describe(I.yy) + " " + describe(I.zz) + " " +
                              describe(I.xy) + " " + describe(I.xz) + " " + describe(I.yz) + "]";
    if (!(moments[0] > 0)) {
        fail(source, field, shown, "the central inertia of a body with mass must be positive definite");
    }
    // A rigid body's principal moments obey the triangle inequality (largest <= sum of the others).
    const double slack = kInertiaTriangleTolerance * (moments[0] + moments[1] + moments[2]);
    if (moments[0] + moments[1] < moments[2] - slack) {
        fail(source, field, shown, "principal moments must satisfy the triangle inequality (largest <= sum of the others)");
    }
}

void validateBody(const std::string& source, const Body& body) {
    if (body.name.empty()) fail(source, "link name", "''", "every link needs a non-empty name");
    if (!std::isfinite(body.mass) || body.mass < 0) {
        fail(source, "link '" + body.name + "' mass", describe(body.mass), "mass must be finite and >= 0 kg");
    }
    for (double c : body.p_BCm) {
        if (!std::isfinite(c)) fail(source, "link '" + body.name + "' centre of mass", describe(c), "must be finite");
    }
    validateInertia(source, body);
    checkMassPropertiesForSimbody(source, body);
    for (const Geometry& g : body.geometry) {
        const std::string field = "link '" + body.name + "' geometry '" + g.name + "'";
        const bool needsRadius = g.type == Geometry::Type::Sphere || g.type == Geometry::Type::Capsule ||
                                 g.type == Geometry::Type::Cylinder;
        if (needsRadius && !(g.radius > 0)) fail(source, field + " radius", describe(g.radius), "must be > 0 m");
        const bool needsLength = g.type == Geometry::Type::Capsule || g.type == Geometry::Type::Cylinder;
        if (needsLength && !(g.length >= 0)) fail(source, field + " length", describe(g.length), "must be >= 0 m");
        if (g.type == Geometry::Type::Box) {
            for (double h : g.halfLengths) {
                if (!(h > 0)) fail(source, field + " size", describe(2 * h), "box sizes must be > 0 m");
            }
        }
        if (g.type == Geometry::Type::Ellipsoid) {
            for (double a : g.semiAxes) {
                if (!(a > 0 && std::isfinite(a))) fail(source, field + " semi_axes", describe(a), "must be > 0 m");
            }
        }
    }
}

void validateJoint(const std::string& source, const Joint& joint) {
    const std::string field = "joint '" + joint.name + "'";
    if (joint.type != Joint::Type::Fixed) {
        const double n = std::sqrt(joint.axis[0] * joint.axis[0] + joint.axis[1] * joint.axis[1] +
                                   joint.axis[2] * joint.axis[2]);
        if (!(std::abs(n - 1) < 1e-9)) fail(source, field + " axis length", describe(n), "axis must be a unit vector");
    }
    if (joint.hasLimits() && !(joint.lower <= joint.upper)) {
        fail(source, field + " limits", "[" + describe(joint.lower) + ", " + describe(joint.upper) + "]",
             "lower must not exceed upper");
    }
    if (!(joint.stiffness >= 0)) fail(source, field + " stiffness", describe(joint.stiffness), "must be >= 0");
    if (!(joint.damping >= 0)) fail(source, field + " damping", describe(joint.damping), "must be >= 0");
}

// Walks from the root through the joints; every body must be reached exactly once.
void validateTree(const std::string& source, const ModelDescription& m) {
    std::map<std::string, std::string> parentOf;
    for (const Joint& j : m.joints) {
        if (!m.findBody(j.parent)) fail(source, "joint '" + j.name + "' parent", "'" + j.parent + "'", "no link has that name");
        if (!m.findBody(j.child)) fail(source, "joint '" + j.name + "' child", "'" + j.child + "'", "no link has that name");
        if (!parentOf.emplace(j.child, j.parent).second) {
            fail(source, "link '" + j.child + "' parent joints", "2 or more", "each link has at most one parent joint");
        }
    }
    if (parentOf.count(m.bodies.front().name)) {
        fail(source, "root link '" + m.bodies.front().name + "'", "has a parent joint", "the first link must be the root");
    }
    for (const Body& b : m.bodies) {
        std::set<std::string> seen;
        std::string at = b.name;
        while (parentOf.count(at)) {
            if (!seen.insert(at).second) fail(source, "link '" + b.name + "' ancestry", "a cycle", "joints must form a tree");
            at = parentOf.at(at);
        }
        if (at != m.bodies.front().name) {
            fail(source, "link '" + b.name + "'", "not connected to root '" + m.bodies.front().name + "'",
                 "every link must hang from the one root");
        }
    }
}

// A movable joint that carries only massless links has nothing resisting its motion: its
// articulated-body inertia is zero, and Simbody silently gives NaN accelerations. Needs a valid tree.
void validateMassOutboard(const std::string& source, const ModelDescription& m) {
    std::set<std::string> carriesMass;  // links with mass at or beyond them
    for (const Body& b : m.bodies) {
        if (!b.isVirtual()) carriesMass.insert(b.name);
    }
    for (bool grew = true; grew;) {  // from the leaves toward the root
        grew = false;
        for (const Joint& j : m.joints) grew = (carriesMass.count(j.child) && carriesMass.insert(j.parent).second) || grew;
    }
    for (const Joint& j : m.joints) {
        if (j.getDofCount() > 0 && !carriesMass.count(j.child)) {
            fail(source, "joint '" + j.name + "' outboard mass", "0 kg (it moves only massless links)",
                 "a movable joint needs a link with mass > 0 at or beyond its child");
        }
    }
}

void validateUniqueNames(const std::string& source, const ModelDescription& m) {
    std::set<std::string> names;
    for (const Body& b : m.bodies) {
        if (!names.insert(b.name).second) fail(source, "link name", "'" + b.name + "'", "link names must be unique");
    }
    names.clear();
    for (const Joint& j : m.joints) {
        if (!names.insert(j.name).second) fail(source, "joint name", "'" + j.name + "'", "joint names must be unique");
    }
    for (const EndEffector& e : m.endEffectors) {
        if (!m.findBody(e.body)) fail(source, "end effector '" + e.name + "' link", "'" + e.body + "'", "no link has that name");
    }
}

}  // namespace

const Body* ModelDescription::findBody(const std::string& n) const {
    return findByName(const_cast<std::vector<Body>&>(bodies), n);
}
Body* ModelDescription::updBody(const std::string& n) { return findByName(bodies, n); }
const Body& ModelDescription::findPalm() const {
    const Body* palm = nullptr;
    for (const Body& b : bodies) {
        if (b.role != BodyRole::Palm || b.isVirtual()) continue;
        if (palm != nullptr) {
            throw InputError("model '" + name + "': two palms ('" + palm->name + "', '" + b.name + "'); a grasp needs one hand");
        }
        palm = &b;
    }
    if (palm == nullptr) throw InputError("model '" + name + "': no body has the palm role; a grasp needs a hand");
    return *palm;
}
const Joint* ModelDescription::findJoint(const std::string& n) const {
    return findByName(const_cast<std::vector<Joint>&>(joints), n);
}
Joint* ModelDescription::updJoint(const std::string& n) { return findByName(joints, n); }
const EndEffector* ModelDescription::findEndEffector(const std::string& n) const {
    return findByName(const_cast<std::vector<EndEffector>&>(endEffectors), n);
}

const Joint* ModelDescription::findParentJoint(const std::string& body) const {
    auto it = std::find_if(joints.begin(), joints.end(), [&](const Joint& j) { return j.child == body; });
    return it == joints.end() ? nullptr : &*it;
}

int ModelDescription::getDofCount() const {
    int dof = 0;
    for (const Joint& j : joints) dof += j.getDofCount();
    return dof;
}

double ModelDescription::calcTotalMass() const {
    double total = 0;
    for (const Body& b : bodies) total += b.mass;
    return total;
}

std::vector<std::pair<std::string, double>> ModelDescription::calcSegmentMasses() const {
    std::vector<std::pair<std::string, double>> masses;
    for (const Body& b : bodies) {
        const std::string key = b.segment.empty() ? b.name : b.segment;
        auto it = std::find_if(masses.begin(), masses.end(), [&](const auto& e) { return e.first == key; });
        if (it == masses.end()) {
            masses.emplace_back(key, b.mass);
        } else {
            it->second += b.mass;
        }
    }
    return masses;
}

void ModelDescription::validate(const std::string& source) const {
    if (bodies.empty()) fail(source, "links", "none", "a model needs at least one link");
    validateUniqueNames(source, *this);
    for (const Body& b : bodies) validateBody(source, b);
    for (const Joint& j : joints) validateJoint(source, j);
    validateTree(source, *this);
    validateMassOutboard(source, *this);
}

std::string toString(BodyRole role) {
    switch (role) {
        case BodyRole::Other: return "other";
        case BodyRole::Palm: return "palm";
        case BodyRole::Digit: return "digit";
    }
    return "other";
}

std::string toString(Geometry::Type type) {
    switch (type) {
        case Geometry::Type::Sphere: return "sphere";
        case Geometry::Type::Box: return "box";
        case Geometry::Type::Capsule: return "capsule";
        case Geometry::Type::Cylinder: return "cylinder";
        case Geometry::Type::Mesh: return "mesh";
        case Geometry::Type::Ellipsoid: return "ellipsoid";
    }
    return "unknown";
}

}  // namespace graspsim::model
