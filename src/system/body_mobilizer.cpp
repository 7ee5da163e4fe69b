#include "body_mobilizer.h"

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
