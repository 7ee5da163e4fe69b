#pragma once
/// @file
/// The bilateral Simbody constraint underneath one rigid contact (rigid_contact.h): one
/// holonomic equation along the contact normal and two nonholonomic equations along the contact
/// plane, with the contact frame taken from our exact shape geometry (rigid_contact_geometry.h)
/// at the current pose. RigidContact switches it on and off and lets Simbody's
/// SemiExplicitEulerTimeStepper impose the unilateral and Coulomb conditions on its multipliers.
///
/// Equations, with bodies A and B (constrained bodies 0 and 1), everything measured and
/// expressed in the constraint's ancestor frame, and the contact geometry (point P, unit normal
/// n from A toward B, gap s) of the current pose:
///  - perr = s, the exact signed gap between the two surfaces (m);
///  - pverr = n . (v_B(P) - v_A(P)) (m/s), v_X(P) the velocity of body X's material point at P;
///  - verr = [tx . (v_B(P) - v_A(P)), ty . (v_B(P) - v_A(P))] (m/s), slip in the contact plane,
///    (tx, ty, n) right-handed with tx = n.perp();
///  - forces: multipliers lambda = (lambda_n, lambda_x, lambda_y) act as lambda_n n + lambda_x tx
///    + lambda_y ty on B at P and its negative on A at P (Simbody applies -G^T lambda, so
///    lambda_n <= 0 pushes the bodies apart, see SimTK::UnilateralContact).
/// pverr is the exact time derivative of perr (the normal rotates perpendicular to the gap).
/// The acceleration-level errors (paerr, vaerr) treat P as a material point of B and n, tx, ty as
/// fixed in A over the instant, like Simbody's own contact constraints; they omit the surface
/// curvature terms. SemiExplicitEulerTimeStepper works at velocity level and never uses them.
#include "graspsim/simbody.h"

#include "graspsim/contact/contact_shape.h"
#include "graspsim/contact/rigid_contact_geometry.h"

namespace graspsim::contact {

/// Constraint::Custom implementation of one point contact between two shapes on two bodies
/// (1 holonomic + 2 nonholonomic equations; see the file comment). Wrap it in a
/// SimTK::Constraint::Custom, which takes ownership.
class RigidContactConstraint : public SimTK::Constraint::Custom::Implementation {
public:
    /// @param shapeA, X_BS_A  shape on bodyA and its pose in bodyA's frame (m)
    /// @param shapeB, X_BS_B  shape on bodyB and its pose in bodyB's frame (m)
    /// @param searchMargin    first margin for the gap search (m), see findRigidContactGeometry()
    /// @throws graspsim::InputError if the pair is unsupported or both bodies are the same.
    RigidContactConstraint(SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& bodyA,
                           const ContactShape& shapeA, const SimTK::Transform& X_BS_A,
                           const SimTK::MobilizedBody& bodyB, const ContactShape& shapeB,
                           const SimTK::Transform& X_BS_B, double searchMargin);

    Implementation* clone() const override { return new RigidContactConstraint(*this); }

    /// The contact geometry in frame F, given the poses of the two bodies' frames in F.
    RigidContactGeometry findGeometry(const SimTK::Transform& X_FA,
                                      const SimTK::Transform& X_FB) const;

    /// Allocates the lazy cache entries of the pose (Stage::Position) and velocity terms.
    void realizeTopology(SimTK::State& state) const override;

    void calcPositionErrors(
        const SimTK::State& state,
        const SimTK::Array_<SimTK::Transform, SimTK::ConstrainedBodyIndex>& X_AB,
        const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& constrainedQ,
        SimTK::Array_<SimTK::Real>& perr) const override;
    void calcPositionDotErrors(
        const SimTK::State& state,
        const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& V_AB,
        const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& constrainedQDot,
        SimTK::Array_<SimTK::Real>& pverr) const override;
    void calcPositionDotDotErrors(
        const SimTK::State& state,
        const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& A_AB,
        const SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& constrainedQDotDot,
        SimTK::Array_<SimTK::Real>& paerr) const override;
    void addInPositionConstraintForces(
        const SimTK::State& state, const SimTK::Array_<SimTK::Real>& multipliers,
        SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& bodyForcesInA,
        SimTK::Array_<SimTK::Real, SimTK::ConstrainedQIndex>& qForces) const override;
    void calcVelocityErrors(
        const SimTK::State& state,
        const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& V_AB,
        const SimTK::Array_<SimTK::Real, SimTK::ConstrainedUIndex>& constrainedU,
        SimTK::Array_<SimTK::Real>& verr) const override;
    void calcVelocityDotErrors(
        const SimTK::State& state,
        const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& A_AB,
        const SimTK::Array_<SimTK::Real, SimTK::ConstrainedUIndex>& constrainedUDot,
        SimTK::Array_<SimTK::Real>& vaerr) const override;
    void addInVelocityConstraintForces(
        const SimTK::State& state, const SimTK::Array_<SimTK::Real>& multipliers,
        SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& bodyForcesInA,
        SimTK::Array_<SimTK::Real, SimTK::ConstrainedUIndex>& mobilityForces) const override;

private:
    /// What every equation needs at one pose, in the ancestor frame A.
    struct PoseTerms {
        RigidContactGeometry geometry;
        SimTK::Vec3 tx, ty;  ///< friction directions (tx = n.perp(), ty = n x tx)
        SimTK::Vec3 r_A, r_B;  ///< P's station on bodies A and B from their origins, expressed in A (m)
    };
    /// The velocity terms of a_B(P) - a_A(P) - 2 w_A x (v_B(P) - v_A(P)), in A.
    struct VelocityTerms {
        SimTK::Vec3 centripetal_A, centripetal_B;  ///< w_X x (w_X x r_X) (m/s^2)
        SimTK::Vec3 coriolis;                      ///< 2 w_A x (v_B(P) - v_A(P)) (m/s^2)
    };

    /// PoseTerms at the pose in `state` (Stage::Position). Computed once per pose: the stepper's
    /// impulse solver evaluates every equation once per constraint row and call.
    const PoseTerms& findPoseTerms(const SimTK::State& state) const;
    /// VelocityTerms at the velocities in `state` (Stage::Velocity), once per velocity update.
    const VelocityTerms& findVelocityTerms(const SimTK::State& state) const;
    PoseTerms calcPoseTerms(const SimTK::State& state) const;
    VelocityTerms calcVelocityTerms(const SimTK::State& state) const;
    /// Relative velocity v_B(P) - v_A(P) of the two material points at P (ancestor frame).
    SimTK::Vec3 findSlipVelocity(const PoseTerms& pose,
                                 const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& V_AB) const;
    /// a_B(P) - a_A(P) - 2 w_A x (v_B(P) - v_A(P)) (ancestor frame), see the file comment.
    SimTK::Vec3 findRelativeAcceleration(
        const SimTK::State& state, const PoseTerms& pose,
        const SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& A_AB) const;
    /// Adds force f_A at P on B and -f_A on A (f_A in the ancestor frame).
    void addInContactForce(const PoseTerms& pose, const SimTK::Vec3& f,
                           SimTK::Array_<SimTK::SpatialVec, SimTK::ConstrainedBodyIndex>& bodyForcesInA) const;

    SimTK::ConstrainedBodyIndex m_bodyA, m_bodyB;
    ContactShape m_shapeA, m_shapeB;
    SimTK::Transform m_X_BS_A, m_X_BS_B;
    double m_searchMargin;
    mutable SimTK::CacheEntryIndex m_poseIndex, m_velocityIndex;  // allocated in realizeTopology()
    mutable const SimTK::SimbodyMatterSubsystem* m_matter = nullptr;  // set in realizeTopology()
};

}  // namespace graspsim::contact
