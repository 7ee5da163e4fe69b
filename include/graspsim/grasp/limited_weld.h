#pragma once
/// @file
/// The "weld" realization of the thesis's friction-limited 6-DOF grasp constraint (thesis
/// section 4.2, eq. 4.1-4.2): rigid. Each axis STICKS (a constraint holds it, with any
/// reaction up to its limit) or SLIDES (the constraint is off and the axis carries exactly its
/// limit, opposing the slip) - Coulomb friction per axis, with the limits as the thesis's
/// "limits on the Lagrange variables". The compliant alternative is LimitedBushing.
///
/// Frames and axes, as LimitedBushing: F is fixed on body H (pose X_HF), M on body O (pose
/// X_OM), constructor defaults that setFrames() moves per State. Axis k in SpatialVec order (rotation first): k = 0,1,2 rotation about M's x, y, z;
/// k = 3,4,5 translation of M's origin along M's x, y, z. The axes turn with the object (the
/// thesis puts its constraint frame at the object's centre of mass). Per axis, the slip rate
/// r_k is the component along M's axis k of the angular velocity of O relative to H (rad/s),
/// or of the velocity of M's origin relative to H's material point coincident with it (m/s).
///
/// Realization (design choice). Simbody 3.7 does not implement BoundedSpeedConstraint or
/// StateLimitedFriction, so the weld switches between two model elements per axis, as
/// Simbody's ExampleMotor-TorqueLimited-Constraint does, but with witness functions
/// (one SimTK::TriggeredEventHandler per axis) so the integrator localizes every switch:
///  - stuck:   a one-equation NONHOLONOMIC Constraint::Custom, r_k = 0 (velocity level: no
///             reference pose, so an axis that slid sticks again where it is, and enabling
///             causes no pose jump); the reaction on O along the axis is -lambda_k;
///  - sliding: the constraint is disabled and a Force::Custom applies f_k = -s_k L_k on O
///             (s_k = +-1, the slip direction; H takes the opposite at M's origin).
///  - stick -> slide when |lambda_k| reaches L_k (witness |lambda_k| - L_k rising through 0);
///    s_k = sign(lambda_k), so the force is continuous across the switch;
///  - slide -> stick when r_k crosses zero (witness -s_k r_k rising through 0): the constraint is
///    tried; if it would need |lambda_k| > L_k the axis keeps sliding the other way,
///    s_k = sign(lambda_k).
/// Axes are independent (a box-shaped friction limit, as the thesis's per-axis limits), and a
/// locked axis (or L = +Infinity) always sticks. Held pose: only as exact as the integrator
/// keeps r = 0 (CPodes projects the velocity constraints to its tolerance), so it may drift
/// slowly; there is no position-level restoring term.
///
/// Held by a lock: when O hangs from H on a Free mobilizer (O's parent is H), a weld with every
/// axis stuck does not use the six constraints: it locks O's mobilizer (MobilizedBody::lock at
/// the current pose, u = 0), the same rigid attachment with no Lagrange multipliers to solve for,
/// so the engaged system costs about what it would with O part of H. The lock's motion forces
/// (SimbodyMatterSubsystem::findMotionForces) are the reaction, which the witnesses compare
/// with the limits as they do the multipliers; when an axis must slide, the lock gives way to
/// the constraints (the five stuck axes) and the sliding force, and when every axis sticks
/// again it takes over again. While locked the pose is held exactly (no drift). Locking is
/// an Instance-stage change, as switching the constraints is.
///
/// Stages: enabling/disabling the weld and the per-axis stick/slide modes are Instance-stage
/// (they switch constraints on and off); limits and axis locks are Dynamics-stage. Change them in an
/// event handler (the TimeStepper re-realizes and reinitializes the integrator after it) or
/// before Integrator::initialize(). The weld needs a stepper that runs its handlers (SimTK::TimeStepper,
/// integration::SimbodyCpodesStepper, integration::CvodeIntegrator).
///
/// Lifetime: the constraints, the force and the handlers belong to the System; this object
/// holds handles and is referred to by its handlers, so it must outlive every run of the System
/// and is neither copyable nor movable.

#include "graspsim/grasp/limited_bushing.h"

#include "graspsim/simbody.h"

#include <array>

namespace graspsim::grasp {

/// One of the six axes of a LimitedWeld: the bushing's axes, same order and meaning.
using WeldAxis = BushingAxis;

/// The friction-limited weld (see the file comment).
class LimitedWeld : public GraspAttachment {
public:
    /// Adds the weld's elements to `system` (6 disabled constraints in `matter`, one force in
    /// `forces`, 6 event handlers in `system`). Defaults: disabled, every axis locked (limit
    /// +Infinity). Call before realizeTopology().
    /// @throws graspsim::InputError if H and O are the same body.
    LimitedWeld(SimTK::MultibodySystem& system, SimTK::SimbodyMatterSubsystem& matter,
                SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& bodyH,
                const SimTK::Transform& X_HF, const SimTK::MobilizedBody& bodyO,
                const SimTK::Transform& X_OM);
    LimitedWeld(const LimitedWeld&) = delete;
    LimitedWeld& operator=(const LimitedWeld&) = delete;

    /// Whether the weld acts in `state`.
    bool isEnabled(const SimTK::State& state) const;
    /// Enables the weld at the current relative pose (every axis starts stuck, then any axis
    /// whose reaction would exceed its limit starts sliding), or disables it (nothing acts, no
    /// velocity changes). Enabling removes the relative velocity of M in H, if any, by Simbody's
    /// velocity projection (System::projectU); at rest relative to H nothing moves. Records the
    /// relative pose for findEngagedTransform(). Needs Stage::Position; realizes `state` to
    /// Stage::Acceleration when enabling.
    void setEnabled(SimTK::State& state, bool enabled) const;

    /// Moves frame F to pose X_HF on H and frame M to X_OM on O (m); invalidates Stage::Instance.
    /// Call it while the weld is disabled, before setEnabled(true) (the engaged pose is recorded
    /// there, in the new frames).
    void setFrames(SimTK::State& state, const SimTK::Transform& X_HF, const SimTK::Transform& X_OM) const;
    /// Pose X_HF of F on H in `state`. Any stage.
    const SimTK::Transform& getFrameOnH(const SimTK::State& state) const;
    /// Pose X_OM of M on O in `state`. Any stage.
    const SimTK::Transform& getFrameOnO(const SimTK::State& state) const;

    /// Per-axis limits L (N m for 0-2, N for 3-5), before locking.
    const SimTK::Vec6& getLimits(const SimTK::State& state) const;
    /// Sets L (each >= 0, +Infinity allowed); invalidates Stage::Dynamics. If the weld is
    /// enabled and `state` is realized to Stage::Position, stuck axes now over their limit start
    /// sliding at once (realizes to Stage::Acceleration). The thesis's values: mu F_perp per
    /// translation axis (eq. 4.1), mu |r| F_perp per rotation axis (eq. 4.2).
    /// @throws graspsim::InputError naming the axis for a negative or NaN limit.
    void setLimits(SimTK::State& state, const SimTK::Vec6& limits) const;
    /// Whether `axis` is locked (always sticks, whatever its limit).
    bool isAxisLocked(const SimTK::State& state, WeldAxis axis) const;
    /// Locks (true) or relaxes (false, limited by getLimits()) `axis`; as setLimits() otherwise.
    void setAxisLocked(SimTK::State& state, WeldAxis axis, bool locked) const;
    /// The limits in force: L_k, or +Infinity for a locked axis.
    SimTK::Vec6 findEffectiveLimits(const SimTK::State& state) const;

    /// Whether every axis is stuck and O's mobilizer lock holds them (see the file comment); only
    /// when O's parent is H on a Free mobilizer. Any stage.
    bool isHeldByLock(const SimTK::State& state) const;
    /// Whether `axis` is sliding (enabled, its constraint off, carrying its limit).
    bool isSliding(const SimTK::State& state, WeldAxis axis) const override;
    /// Slip direction s_k of `axis`: +1 or -1 while sliding, 0 while stuck or disabled.
    int getSlideDirection(const SimTK::State& state, WeldAxis axis) const;
    /// Slip rates r (rad/s for 0-2, m/s for 3-5; along M's axes). Needs Stage::Velocity.
    SimTK::Vec6 findSlipVelocity(const SimTK::State& state) const;
    /// Generalized reaction f on O along M's axes (N m, N): -lambda_k on stuck axes, -s_k L_k
    /// on sliding ones, zero when disabled. Needs Stage::Acceleration (multipliers).
    SimTK::Vec6 findGeneralizedForce(const SimTK::State& state) const;
    /// Spatial force of the weld on O (moment about M's origin, N m; force, N), expressed in
    /// Ground; H receives the opposite at M's origin. Needs Stage::Acceleration.
    SimTK::SpatialVec findWrench(const SimTK::State& state) const;
    /// Pose X_FM of M in F when the weld was last enabled (identity before). Any stage.
    const SimTK::Transform& findEngagedTransform(const SimTK::State& state) const;
    /// Current pose X_FM of M in F. Needs Stage::Position.
    SimTK::Transform findTransform(const SimTK::State& state) const;

    /// GraspAttachment: whether enabled.
    bool isEngaged(const SimTK::State& state) const override { return isEnabled(state); }
    /// GraspAttachment: moves F and M to `engagement`'s frames, sets the limits and locks, then
    /// enables the weld (last, so that axes already over their limits start sliding at once).
    /// Leaves `state` realized to Stage::Position.
    /// @throws graspsim::InputError for two-sided limits (lowerLimits set and unequal to limits).
    void engage(SimTK::State& state, const AttachmentEngagement& engagement) const override;
    /// GraspAttachment: disables the weld.
    void release(SimTK::State& state) const override { setEnabled(state, false); }
    /// GraspAttachment: Stage::Acceleration (the reactions are Lagrange multipliers).
    SimTK::Stage getReactionStage() const override { return SimTK::Stage::Acceleration; }
    /// GraspAttachment: findWrench() with its moment moved to O's origin. Needs
    /// Stage::Acceleration.
    SimTK::SpatialVec findReactionOnObject(const SimTK::State& state) const override;
    /// GraspAttachment: getFrameOnO(), findEffectiveLimits(), findGeneralizedForce() and
    /// findWrench() while enabled. Needs Stage::Acceleration.
    std::optional<SingleConstraintState> findSingleConstraintState(const SimTK::State& state) const override;

    class AxisEvent;  // the per-axis witness handler (implementation detail)
    class Elements;   // the Simbody elements and state variables (implementation detail)

private:
    void handleAxisEvent(SimTK::State& state, int axis) const;
    void stick(SimTK::State& state, int axis) const;
    void slide(SimTK::State& state, int axis, int direction) const;
    void releaseOverloadedAxes(SimTK::State& state) const;
    void holdByLock(SimTK::State& state) const;
    void holdByConstraints(SimTK::State& state) const;
    double findMultiplier(const SimTK::State& state, int axis) const;

    const SimTK::MultibodySystem& system_;
    SimTK::MobilizedBody bodyO_;
    bool lockable_;  // O hangs from H on a Free mobilizer
    Elements* elements_ = nullptr;  // owned by the System (it is the Force::Custom's implementation)
    SimTK::Force::Custom force_;
    std::array<SimTK::Constraint::Custom, 6> constraints_;
};

}  // namespace graspsim::grasp
