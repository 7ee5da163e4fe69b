#include "graspsim/contact/anchor_friction.h"

#include <cmath>

namespace graspsim::contact {

double calcAnchorStiffness(const ContactParameters& contact, const AnchorFrictionParameters& anchor,
                           double radius, double depth) {
    return anchor.stiffnessRatio * 2 * contact.effectiveStiffness * std::sqrt(radius * depth);
}

double calcAnchorFrictionLimit(const ContactParameters& contact, double sliding, double slipSpeed) {
    return contact.staticFriction - sliding * (contact.staticFriction - contact.dynamicFriction) +
           contact.viscousFriction * slipSpeed;
}

AnchorFriction calcAnchorFriction(const ContactParameters& contact, const AnchorFrictionParameters& anchor,
                                  const AnchorContact& pair, const AnchorState& state) {
    const SimTK::Vec3& n = pair.n_G.asVec3();
    const double zNormal = SimTK::dot(state.deflection_G, n);
    const SimTK::Vec3 zTangent = state.deflection_G - zNormal * n;
    const SimTK::Vec3& v = pair.slipVelocity_G;
    const double damping = 2 * std::sqrt(pair.stiffness * anchor.dampingMass);
    const SimTK::Vec3 trial = -pair.stiffness * zTangent - damping * v;
    const double limit = calcAnchorFrictionLimit(contact, state.sliding, v.norm()) * pair.normalForce;

    AnchorFriction friction;
    const double trialNorm = trial.norm();
    friction.force_G = trialNorm > limit ? (limit / trialNorm) * trial : trial;
    // The anchor slides only by what the spring alone holds beyond the limit (ExponentialSpringForce
    // moves its spring zero the same way), so a damper peak does not drag it.
    const double springForce = pair.stiffness * zTangent.norm();
    const double excess = springForce > limit ? 1 - limit / springForce : 0;
    const double tau = anchor.relaxationTime;
    friction.rate.deflection_G = v - (excess / tau) * zTangent - (zNormal / tau) * n;
    friction.rate.sliding = ((excess > 0 ? 1.0 : 0.0) - state.sliding) / tau;
    return friction;
}

AnchorState calcAnchorRelaxationRate(const AnchorFrictionParameters& anchor, const AnchorState& state) {
    return {-state.deflection_G / anchor.relaxationTime, -state.sliding / anchor.relaxationTime};
}

}  // namespace graspsim::contact
