#pragma once
// Hand-built model descriptions with closed-form dynamics, shared by the system-layer tests.
// They are written out field by field, independently of the anthropometric builders, so that a
// test's oracle depends only on the numbers here.

#include <array>
#include <cmath>
#include <string>

#include "graspsim/model/model_description.h"

namespace graspsim::system::test {

/// Row-major rotation by `angle` (rad) about unit `axis`, by Rodrigues' formula
/// R = I cos(a) + sin(a) [axis]x + (1 - cos(a)) axis axis^T.
inline std::array<double, 9> rotationAboutAxis(const model::Vec3& axis, double angle) {
    const double c = std::cos(angle), s = std::sin(angle), t = 1 - c;
    const double x = axis[0], y = axis[1], z = axis[2];
    return {t * x * x + c,     t * x * y - s * z, t * x * z + s * y,
            t * x * y + s * z, t * y * y + c,     t * y * z - s * x,
            t * x * z - s * y, t * y * z + s * x, t * z * z + c};
}

/// A massive body with diagonal central inertia (kg, m, kg m^2).
inline model::Body makeBody(const std::string& name, double mass, const model::Vec3& p_BCm,
                            const model::Vec3& centralMoments) {
    model::Body body;
    body.name = name;
    body.mass = mass;
    body.p_BCm = p_BCm;
    body.inertia.xx = centralMoments[0];
    body.inertia.yy = centralMoments[1];
    body.inertia.zz = centralMoments[2];
    return body;
}

/// A massless virtual body of a multi-DOF joint chain.
inline model::Body makeVirtualBody(const std::string& name) {
    model::Body body;
    body.name = name;
    return body;
}

/// A joint of `type` from parent to child about (or along) `axis`, joint frame at X_PJ.
inline model::Joint makeJoint(const std::string& name, model::Joint::Type type,
                              const std::string& parent, const std::string& child,
                              const model::Vec3& axis, const model::Transform& X_PJ = {}) {
    model::Joint joint;
    joint.name = name;
    joint.type = type;
    joint.parent = parent;
    joint.child = child;
    joint.axis = axis;
    joint.X_PJ = X_PJ;
    return joint;
}

/// Parameters of the planar pendulum: a bob of mass m whose centre of mass hangs a distance l
/// below the pivot (along the rod body's -y at q = 0), with central moment Ic about the pin z.
struct PendulumParameters {
    double mass = 2.0;         ///< kg
    double length = 0.5;       ///< m, pivot to centre of mass
    double centralIzz = 0.01;  ///< kg m^2
    /// Moment of inertia about the pivot, I_O = Ic + m l^2 (kg m^2).
    double calcPivotInertia() const { return centralIzz + mass * length * length; }
};

/// A 1 kg "base" root welded at ground's origin and a "rod" hanging from it on joint "pivot"
/// about z (gravity along -y swings it in the x-y plane). The joint is Continuous (no limits,
/// no spring, no damper); tests change what they need. End-effector "tip" sits at the centre
/// of mass.
inline model::ModelDescription makePendulum(const PendulumParameters& p = {}) {
    model::ModelDescription m;
    m.name = "pendulum";
    m.bodies.push_back(makeBody("base", 1.0, {0, 0, 0}, {0.01, 0.01, 0.01}));
    m.bodies.push_back(
        makeBody("rod", p.mass, {0, -p.length, 0}, {p.centralIzz, p.centralIzz, p.centralIzz}));
    m.joints.push_back(
        makeJoint("pivot", model::Joint::Type::Continuous, "base", "rod", {0, 0, 1}));
    m.endEffectors.push_back({"tip", "rod", {0, -p.length, 0}});
    return m;
}

/// A shoulder-like chain: root "thorax", then pins about z ("flexion"), x ("abduction") and
/// y ("rotation") through massless bodies "shoulder_1" and "shoulder_2" to "upper_arm", whose
/// centre of mass is off all three axes.
inline model::ModelDescription makeShoulderChain() {
    model::ModelDescription m;
    m.name = "shoulder";
    m.bodies.push_back(makeBody("thorax", 20.0, {0, 0, 0}, {0.5, 0.4, 0.3}));
    m.bodies.push_back(makeVirtualBody("shoulder_1"));
    m.bodies.push_back(makeVirtualBody("shoulder_2"));
    m.bodies.push_back(makeBody("upper_arm", 2.0, {0.02, -0.15, 0.01}, {0.012, 0.003, 0.011}));
    model::Transform X_TS;  // shoulder joint centre in the thorax
    X_TS.p = {0.0, 0.4, 0.18};
    using Type = model::Joint::Type;
    m.joints.push_back(
        makeJoint("flexion", Type::Continuous, "thorax", "shoulder_1", {0, 0, 1}, X_TS));
    m.joints.push_back(
        makeJoint("abduction", Type::Continuous, "shoulder_1", "shoulder_2", {1, 0, 0}));
    m.joints.push_back(
        makeJoint("rotation", Type::Continuous, "shoulder_2", "upper_arm", {0, 1, 0}));
    return m;
}

}  // namespace graspsim::system::test
