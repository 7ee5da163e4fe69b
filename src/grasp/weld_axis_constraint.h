#pragma once
// Private to graspsim_grasp: one axis of grasp::LimitedWeld as a Simbody nonholonomic constraint.
//
// Velocity level, one equation: the component along M's axis k of the velocity of M relative to
// body H (angular velocity for k = 0-2; for k = 3-5 the velocity of M's origin relative to H's
// material point coincident with it) is zero. A velocity-level equation has no reference pose,
// so enabling it at any pose causes no jump, and an axis that has slid sticks again wherever
// it is. The price is that the pose is held only as well as the integrator keeps the velocity
// error at zero (no position-level restoring term), which CPodes' projection does to its
// constraint tolerance.

#include <simbody/Simbody.h>

#include <functional>

namespace graspsim::grasp {

class WeldAxisConstraint : public SimTK::Constraint::Custom::Implementation {
public:
    // Pose X_OM of frame M on bodyO in a state (the weld keeps it in a state variable).
    using FrameOnO = std::function<const SimTK::Transform&(const SimTK::State&)>;

    // `axis` 0-2: rotation about M's x, y, z; 3-5: translation along them. M is findX_OM(state) on bodyO.
    WeldAxisConstraint(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& bodyH,
                       const SimTK::MobilizedBody& bodyO, FrameOnO findX_OM, int axis);

    Implementation* clone() const override { return new WeldAxisConstraint(*this); }

    void calcVelocityErrors(const SimTK::State& state,
                            const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& allV_AB,
                            const SimTK::Array_<SimTK::Real, SimTK::ConstrainedUIndex>& constrainedU,
                            SimTK::Array_<SimTK::Real>& verr) const override;
    void calcVelocityDotErrors(const SimTK::State& state,
                               const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& allA_AB,
                               const SimTK::Array_<SimTK::Real, SimTK::ConstrainedUIndex>& constrainedUDot,
                               SimTK::Array_<SimTK::Real>& vaerr) const override;
    void addInVelocityConstraintForces(const SimTK::State& state, const SimTK::Array_<SimTK::Real>& multipliers,
                                       SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& bodyForcesInA,
                                       SimTK::Array_<SimTK::Real, SimTK::ConstrainedUIndex>& mobilityForces) const override;

private:
    SimTK::UnitVec3 findAxis_A(const SimTK::State& state) const;  // m_k in the ancestor frame A
    SimTK::Vec3 findP_OM_A(const SimTK::State& state) const;      // O's origin to M's origin, in A

    SimTK::ConstrainedBodyIndex bodyH_;
    SimTK::ConstrainedBodyIndex bodyO_;
    FrameOnO findX_OM_;
    int axis_;
};

}  // namespace graspsim::grasp
