#pragma once
/// @file
/// Linearly implicit Euler for the stiff joint impedance (springs, dampers, limit stops, PD
/// gains) of a fixed-step explicit stepper: Simbody's SemiExplicitEulerTimeStepper, which the
/// rigid contact model needs.
///
/// Why: a finger phalanx has an effective inertia m of a few 1e-7 kg m^2 and its joint a
/// damping c of about 0.1 N m s/rad (passive damper + PD), a time constant m / c of a few
/// microseconds. Explicit Euler is stable only for h < 2 m / c, so a grasp would need steps of
/// about 3e-6 s. Implicit Euler has no such limit.
///
/// What: with joint-space stiffness K and damping C (diagonal: the sum of every element's
/// -dtau/dq and -dtau/du on each listed joint, combined before the implicit factor), generalized
/// mass matrix M, the step's size h and the total generalized force F at the step's start
/// (applied forces of every other element, minus Coriolis and gyroscopic forces, plus the
/// constraint forces of the previous step, see below), linearly implicit Euler takes
///
///     (M + h C + h^2 K) du = h (F - h K u)                          (1)
///
/// i.e. the impedance forces are evaluated at the end of the step, linearized. The stepper
/// itself takes M du = h (F + X): this element supplies the correction X that makes both
/// agree, X = -h K u - (h C + h^2 K) w with (M + h C + h^2 K) w = F - h K u, nonzero on the
/// listed joints only. Without constraints the step is exactly (1), a first-order method that
/// is stable for any h on the linear impedance, and it converges to the continuous solution
/// as h -> 0 (tests/system/implicit_joint_impedance_test.cpp compares it with tiny explicit steps).
///
/// Constraints (rigid contacts): the stepper solves the constraint impulses with M, not with
/// M + h C + h^2 K. The element therefore puts the previous step's constraint forces into F
/// (setConstraintForces()); the stepper's own constraint force then corrects only their change
/// over the step. At steady state the result is the implicit step's exactly (the joints push on
/// a contact with their full spring force); while contact forces change, each step moves them
/// toward the implicit solution by a factor 1 - mu (mu in (0, 1], the generalized eigenvalues
/// of G (M + hD)^-1 G^T against G M^-1 G^T), monotonically, never overshooting.
///
/// With step size 0 (the default; continuous integrators) the element applies no force at
/// all: the model's physics is unchanged.
///
/// Stages: the correction is computed at Stage::Dynamics (needs Velocity); the step size is a
/// Stage::Dynamics discrete variable, the constraint forces are set by updateConstraintForces().
#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::system {

/// The linear impedance of one joint as the implicit step sees it.
struct JointImpedance {
    /// The joint's mobilizer: one mobility with qdot = u (Pin or Slider).
    SimTK::MobilizedBodyIndex mobod;
    double stiffness = 0;  ///< K = -dtau/dq of the joint's springs and PD (N m/rad or N/m), >= 0
    double damping = 0;    ///< C = -dtau/du of its dampers and PD (N m s/rad or N s/m), >= 0
    /// The joint's limit stop, or an empty handle. Past a limit its current linearization
    /// (stiffness k, damping k d x for a violation x, see SystemOptions) is added.
    SimTK::Force::MobilityLinearStop stop;
};

/// The correction force element (a Force::Custom handle; the element belongs to the subsystem).
class ImplicitJointImpedance : public SimTK::Force::Custom {
public:
    /// An empty handle.
    ImplicitJointImpedance() = default;

    /// Adds the element to `forces`. It reads the forces of every other element of `forces`.
    /// @throws graspsim::InputError for a negative or non-finite stiffness or damping (a
    ///         mobilizer with other than one mobility throws when the correction is computed).
    ImplicitJointImpedance(SimTK::GeneralForceSubsystem& forces, const SimTK::SimbodyMatterSubsystem& matter,
                           std::vector<JointImpedance> joints);

    /// The fixed step size h (s) of the stepper that advances `state`; 0 turns the element off.
    /// Invalidates Stage::Dynamics. @throws graspsim::InputError for h < 0 or non-finite.
    void setStepSize(SimTK::State& state, double h) const;
    double getStepSize(const SimTK::State& state) const;

    /// Stores the generalized constraint forces -G^T lambda of the step just taken, for the next
    /// step's F (see the file comment). Call it after each SemiExplicitEulerTimeStepper::stepTo()
    /// on the stepper's state, which then holds the step's multipliers lambda (N, N m) at
    /// Stage::Dynamics. The forces belong to the step that starts at the state's time: once this
    /// has been called, the element applies nothing in a state at any other time. The stepper's
    /// own end-of-step realization is such a state; if `state` is one (realized to Stage::Dynamics
    /// at a time other than the previous call's), this call completes it: it adds the correction
    /// to its mobility forces, with F taken from that realization (the same sum in another order
    /// than calcCorrection()'s, equal to rounding), so the next step evaluates no force element
    /// again. Otherwise it invalidates Stage::Dynamics.
    void updateConstraintForces(SimTK::State& state) const;

    /// The correction X (generalized forces, N m or N; one entry per mobility) at `state`
    /// (Stage::Velocity): what the element adds when realized to Stage::Dynamics.
    SimTK::Vector calcCorrection(const SimTK::State& state) const;

private:
    class Implementation;
    const Implementation& getImpl() const;
};

}  // namespace graspsim::system
