#include "weld_axis_constraint.h"

#include <utility>

namespace graspsim::grasp {

// Everything is measured in the constraint's ancestor frame A (Ground when one body hangs from
// Ground). The relative velocity of M with respect to H does not depend on the frame it is
// measured in, so neither do the equations.

WeldAxisConstraint::WeldAxisConstraint(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& bodyH,
                                       const SimTK::MobilizedBody& bodyO, FrameOnO findX_OM, int axis)
    : Implementation(matter, 0, 1, 0), findX_OM_(std::move(findX_OM)), axis_(axis) {
    bodyH_ = addConstrainedBody(bodyH);
    bodyO_ = addConstrainedBody(bodyO);
}

SimTK::UnitVec3 WeldAxisConstraint::findAxis_A(const SimTK::State& state) const {
    const SimTK::Rotation R_AM = getBodyRotationFromState(state, bodyO_) * findX_OM_(state).R();
    return R_AM.getAxisUnitVec(SimTK::CoordinateAxis(axis_ % 3));
}

SimTK::Vec3 WeldAxisConstraint::findP_OM_A(const SimTK::State& state) const {
    return getBodyRotationFromState(state, bodyO_) * findX_OM_(state).p();
}

void WeldAxisConstraint::calcVelocityErrors(const SimTK::State& state,
                                            const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& allV_AB,
                                            const SimTK::Array_<SimTK::Real, SimTK::ConstrainedUIndex>&,
                                            SimTK::Array_<SimTK::Real>& verr) const {
    const SimTK::Vec3 m = findAxis_A(state);
    const SimTK::SpatialVec& V_H = allV_AB[bodyH_];
    const SimTK::SpatialVec& V_O = allV_AB[bodyO_];
    if (axis_ < 3) {
        verr[0] = ~m * (V_O[0] - V_H[0]);
        return;
    }
    const SimTK::Vec3 p_OM = findP_OM_A(state);
    const SimTK::Vec3 p_HM = getBodyOriginLocationFromState(state, bodyO_) + p_OM -
                             getBodyOriginLocationFromState(state, bodyH_);
    const SimTK::Vec3 v_M = V_O[1] + V_O[0] % p_OM;  // M's origin moving with O
    const SimTK::Vec3 v_C = V_H[1] + V_H[0] % p_HM;  // H's point coincident with M's origin
    verr[0] = ~m * (v_M - v_C);
}

// Exactly the time derivative of calcVelocityErrors(): the axis m turns with O (mdot = w_O x m),
// and H's coincident point is a different material point at every instant, so its "acceleration"
// is a_H + b_H x p_HM + w_H x (v_M - v_H).
void WeldAxisConstraint::calcVelocityDotErrors(const SimTK::State& state,
                                               const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& allA_AB,
                                               const SimTK::Array_<SimTK::Real, SimTK::ConstrainedUIndex>&,
                                               SimTK::Array_<SimTK::Real>& vaerr) const {
    const SimTK::Vec3 m = findAxis_A(state);
    const SimTK::SpatialVec& V_H = getBodyVelocityFromState(state, bodyH_);
    const SimTK::SpatialVec& V_O = getBodyVelocityFromState(state, bodyO_);
    const SimTK::SpatialVec& A_H = allA_AB[bodyH_];
    const SimTK::SpatialVec& A_O = allA_AB[bodyO_];
    const SimTK::Vec3 mDot = V_O[0] % m;
    if (axis_ < 3) {
        vaerr[0] = ~mDot * (V_O[0] - V_H[0]) + ~m * (A_O[0] - A_H[0]);
        return;
    }
    const SimTK::Vec3 p_OM = findP_OM_A(state);
    const SimTK::Vec3 p_HM = getBodyOriginLocationFromState(state, bodyO_) + p_OM -
                             getBodyOriginLocationFromState(state, bodyH_);
    const SimTK::Vec3 v_M = V_O[1] + V_O[0] % p_OM;
    const SimTK::Vec3 v_C = V_H[1] + V_H[0] % p_HM;
    const SimTK::Vec3 a_M = A_O[1] + A_O[0] % p_OM + V_O[0] % (V_O[0] % p_OM);
    const SimTK::Vec3 a_C = A_H[1] + A_H[0] % p_HM + V_H[0] % (v_M - V_H[1]);
    vaerr[0] = ~mDot * (v_M - v_C) + ~m * (a_M - a_C);
}

// The transpose of the velocity-error Jacobian: multiplier lambda gives O a torque (or a force
// at M's origin) lambda m and H the opposite (at the same point). Simbody applies -lambda times
// these, so the reaction on O along m is -lambda.
void WeldAxisConstraint::addInVelocityConstraintForces(
    const SimTK::State& state, const SimTK::Array_<SimTK::Real>& multipliers,
    SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& bodyForcesInA,
    SimTK::Array_<SimTK::Real, SimTK::ConstrainedUIndex>&) const {
    const SimTK::Vec3 f = multipliers[0] * SimTK::Vec3(findAxis_A(state));
    if (axis_ < 3) {
        addInBodyTorque(state, bodyO_, f, bodyForcesInA);
        addInBodyTorque(state, bodyH_, -f, bodyForcesInA);
        return;
    }
    const SimTK::Vec3 p_GM = getBodyOriginLocationFromState(state, bodyO_) + findP_OM_A(state);
    const SimTK::Transform& X_AH = getBodyTransformFromState(state, bodyH_);
    addInStationForce(state, bodyO_, findX_OM_(state).p(), f, bodyForcesInA);
    addInStationForce(state, bodyH_, ~X_AH * p_GM, -f, bodyForcesInA);
}

}  // namespace graspsim::grasp
