#include "body_mobilizer.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

#include "graspsim/error.h"

namespace graspsim::system {

namespace {

SimTK::Body makeBody(const model::Body& body) {
    // Virtual bodies are constitutively massless so that nothing can give them mass later;
    // Simbody accepts them when a massive body follows in the chain.
    if (body.isVirtual()) return SimTK::Body::Massless();
    return SimTK::Body::Rigid(calcMassPropertiesAboutOrigin(body));
}

}  // namespace

SimTK::MassProperties calcMassPropertiesAboutOrigin(const model::Body& body) {
    const model::Inertia& I = body.inertia;
    // Both the description and SimTK::Inertia list products as the off-diagonal elements of
    // the inertia matrix (URDF convention), so they carry over unchanged.
    const SimTK::Inertia I_Bcm_B(I.xx, I.yy, I.zz, I.xy, I.xz, I.yz);
    const SimTK::Vec3 p_BCm = toSimTKVec3(body.p_BCm);
    // The shift depends on p only through its outer products, so the direction from the mass
    // centre to the origin (-p_BCm) and p_BCm give the same result.
    const SimTK::Inertia I_Bo_B = I_Bcm_B.shiftFromMassCenter(-p_BCm, body.mass);
    return SimTK::MassProperties(body.mass, p_BCm, I_Bo_B);
}

void checkMassPropertiesForSimbody(const model::Body& body, const std::string& what) {
    if (body.isVirtual()) return;
    // Plain matrices, not SimTK::Inertia, whose own checks would throw a trace before ours speaks.
    const model::Inertia& I = body.inertia;
    const SimTK::Mat33 I_Bcm_given(I.xx, I.xy, I.xz, I.xy, I.yy, I.yz, I.xz, I.yz, I.zz);
    const SimTK::Vec3 p = toSimTKVec3(body.p_BCm);
    const double m = body.mass;
    const SimTK::Mat33 pointMass = m * (p.normSqr() * SimTK::Mat33(1) - p * ~p);
    // What Simbody will hold (I_Bo) and the central inertia it recovers from that.
    const SimTK::Mat33 I_Bcm = (I_Bcm_given + pointMass) - pointMass;
    const SimTK::Vec3 d(I_Bcm(0, 0), I_Bcm(1, 1), I_Bcm(2, 2));
    // Simbody's slop for its inertia checks is sqrt(eps) max(trace, 1); we keep half of it as a
    // margin, and ask the rounding of the shift (a few eps m|p|^2) to stay below the other half,
    // so that our arithmetic and Simbody's cannot land on different sides of its bound.
    const double slop = 0.5 * std::sqrt(SimTK::Eps) * std::max(d.sum(), 1.0);
    const double shift = m * p.normSqr();
    const bool recoverable = 8 * SimTK::Eps * shift < slop;
    const bool valid = d[0] >= 0 && d[1] >= 0 && d[2] >= 0 && d[0] + d[1] + slop >= d[2] &&
                       d[0] + d[2] + slop >= d[1] && d[1] + d[2] + slop >= d[0] &&
                       d[0] + slop >= std::abs(2 * I_Bcm(1, 2)) && d[1] + slop >= std::abs(2 * I_Bcm(0, 2)) &&
                       d[2] + slop >= std::abs(2 * I_Bcm(0, 1));
    if (recoverable && valid) return;
    std::ostringstream message;
    message << what << " mass " << m << " kg with its mass centre at (" << p[0] << ", " << p[1] << ", " << p[2]
            << ") m from the link origin is not accepted: ";
    if (!recoverable) {
        message << "m |p|^2 = " << shift << " kg m^2 swamps the central inertia (trace "
                << body.inertia.xx + body.inertia.yy + body.inertia.zz
                << " kg m^2) in double precision; accepted: m |p|^2 below " << slop / (8 * SimTK::Eps)
                << " kg m^2 (put the link origin nearer the mass centre)";
    } else {
        message << "the central inertia Simbody recovers, diagonal (" << d[0] << ", " << d[1] << ", " << d[2]
                << ") kg m^2, breaks its rules; accepted: diagonals >= 0 obeying the triangle inequality within "
                << slop << " kg m^2";
    }
    throw InputError(message.str());
}

SimTK::Rotation calcAxisAlignedRotation(const model::Vec3& axis_J,
                                        SimTK::CoordinateAxis mobilizerAxis) {
    return SimTK::Rotation(SimTK::UnitVec3(toSimTKVec3(axis_J)), mobilizerAxis);
}

SimTK::MobilizedBody addRootMobilizedBody(SimTK::SimbodyMatterSubsystem& matter,
                                          const model::Body& root, const model::Transform& X_GR) {
    return SimTK::MobilizedBody::Weld(matter.updGround(), toSimTKTransform(X_GR, "X_GR"),
                                      makeBody(root), SimTK::Transform());
}

SimTK::MobilizedBody addJointMobilizedBody(SimTK::MobilizedBody& parent, const model::Joint& joint,
                                           const model::Body& child) {
    const SimTK::Transform X_PJ = toSimTKTransform(joint.X_PJ, "joint '" + joint.name + "' X_PJ");
    const SimTK::Body body = makeBody(child);
    using Type = model::Joint::Type;
    if (joint.type == Type::Fixed) {
        return SimTK::MobilizedBody::Weld(parent, X_PJ, body, SimTK::Transform());
    }
    // A pin turns its M frame about F's z and a slider moves it along F's x. Placing F at
    // X_PJ * R_JF and M at R_BM = R_JF makes B coincide with J at q = 0 and turn about the
    // joint axis: X_PB = X_PJ * R_JF * X_FM(q) * ~R_JF.
    if (joint.type == Type::Prismatic) {
        const SimTK::Rotation R_JF = calcAxisAlignedRotation(joint.axis, SimTK::XAxis);
        return SimTK::MobilizedBody::Slider(parent, X_PJ * SimTK::Transform(R_JF), body,
                                            SimTK::Transform(R_JF));
    }
    const SimTK::Rotation R_JF = calcAxisAlignedRotation(joint.axis, SimTK::ZAxis);
    return SimTK::MobilizedBody::Pin(parent, X_PJ * SimTK::Transform(R_JF), body,
                                     SimTK::Transform(R_JF));
}

}  // namespace graspsim::system
