#pragma once
/// @file
/// The "bushing" realization of the thesis's friction-limited 6-DOF grasp constraint (thesis
/// section 4.2): a stiff 6-DOF spring-damper between the hand side H and the object O
/// whose force saturates at per-axis limits while its anchor slips (elasto-plastic friction).
///
/// Frames: F is fixed on body H (pose X_HF), M is fixed on body O (pose X_OM); both poses are
/// given to the constructor as defaults and can be moved per State (setFrames()). The element keeps
/// an ANCHOR frame A, fixed in F while it sticks: the pose of M in F at which the spring is
/// relaxed. A is stored as X_FA = X_FA0 * X_A0A, where X_FA0 (a discrete variable) is set by
/// resetAnchor() and the slip since then, X_A0A = (rotation vector z_r, position z_p in A0), is
/// six continuous state variables z integrated by whatever integrator runs the system.
///
/// Axes, in SpatialVec order (rotation first, as Simbody): k = 0,1,2 rotation about A's x,y,z;
/// k = 3,4,5 translation along A's x,y,z. At engagement A coincides with M, and it stays within
/// the elastic displacement (about L/K) of M afterwards, so the axes follow the object, as the
/// thesis's constraint axes do (its frame is at the object's centre of mass).
///
/// Per axis k, with e the displacement of M from A (e_r = rotation vector of R_AM (rad),
/// e_p = p_AM expressed in A (m)), r the velocity of M relative to F expressed in A (angular
/// rad/s, linear m/s of M's origin), and L_k the axis's limit (N m or N) on the side the elastic
/// force -K_k e_k points to (two-sided limits: f_k in [-L-_k, +L+_k]; L_k = L+_k for e_k < 0, else
/// L-_k; equal sides are the symmetric element):
///  - slip fraction  s_k = g(K_k |e_k| / L_k) if e_k r_k > 0 (loading), else 0; g is 0 below
///    1 - w, a C1 smoothstep to 1 at u = 1 (w = getSlipOnsetWidth()), and 1 + ((u - 1) / w)^2
///    above, so an overshoot past the limit is pulled back (see limited_bushing_law.h);
///  - anchor rate    (rate of A in F, in A)_k = s_k r_k;   elastic rate  edot_k = (1 - s_k) r_k;
///  - generalized force  f_k = clamp(-K_k e_k - D_k edot_k, -L-_k, +L+_k).
/// With a coupled stiffness (a symmetric positive definite 6 x 6 K, setStiffness(state, Mat66, ...))
/// K_k e_k reads (K e)_k throughout: the elastic load of axis k, which decides its slip fraction
/// (u = |(K e)_k| / L_k, loading (K e)_k r_k > 0) and its force clamp(-(K e)_k - D_k edot_k, ...);
/// D stays per axis.
/// O receives moment (f_0, f_1, f_2) and force (f_3, f_4, f_5), expressed in A, at M's origin;
/// H receives the opposite at the same point.
///
/// What this reproduces exactly: below (1 - w) L the element is a linear spring-damper (no creep,
/// so a held object stays put); while sliding the anchor follows M, edot = 0 and the force is
/// exactly +-L (Coulomb sliding friction at the limit); unloading from the limit is elastic
/// (stick). The regularization error is confined to |K e| in [(1 - w) L, L]: there the anchor
/// already creeps at fraction g of the loading rate (partial slip), so the last w of the
/// elastic range is softer than K. The hard elasto-plastic model (slide only at |K e| >= L) is
/// the limit w -> 0; w > 0 keeps zdot continuous in the state, which error-controlled
/// integrators (Runge-Kutta, CPodes' Newton iteration) need.
/// Approximations: e_r as a moment is exact to first order in |e_r| (small for a stiff
/// element); edot neglects the O(|e| |r|) transport terms of the anchor's own rotation.
/// The slip rotation |z_r| must stay below 2 pi (rotation-vector chart); call resetAnchor() (no
/// force jump when e = 0) or setAnchorDisplacement() from an event to re-base long rotations.
///
/// Stages: forces and zdot need Stage::Velocity and are produced at Stage::Dynamics. The enabled
/// flag is an Instance-stage discrete variable (like Force::disable()); limits, locks, stiffness,
/// damping and X_FA0
/// are Dynamics-stage discrete variables; anchor changes write z. Change them in an event
/// handler (the TimeStepper re-realizes and reinitializes the integrator after it) or before
/// Integrator::initialize().

#include "graspsim/grasp/grasp_attachment.h"
#include "graspsim/simbody.h"

namespace graspsim::grasp {

/// The friction-limited 6-DOF bushing (a Simbody Force::Custom handle; copies refer to the same
/// element, which belongs to the GeneralForceSubsystem). See the file comment for the law.
class LimitedBushing : public SimTK::Force::Custom, public GraspAttachment {
public:
    /// An empty handle.
    LimitedBushing() = default;

    /// Adds the element to `forces`, between frame F on `bodyH` (pose X_HF in H) and frame M on
    /// `bodyO` (pose X_OM in O). Defaults: enabled, every axis locked (limit infinite), anchor
    /// X_FA0 = identity (call resetAnchor() before use).
    /// @param stiffness K per axis: N m/rad (0-2) and N/m (3-5); each > 0 and finite.
    /// @param damping   D per axis: N m s/rad (0-2) and N s/m (3-5); each >= 0 and finite.
    /// @throws graspsim::InputError naming the axis and value for a bad stiffness or damping, or
    ///         if H and O are the same body.
    LimitedBushing(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& bodyH,
                   const SimTK::Transform& X_HF, const SimTK::MobilizedBody& bodyO,
                   const SimTK::Transform& X_OM, const SimTK::Vec6& stiffness,
                   const SimTK::Vec6& damping);

    /// Default K per axis (N m/rad, N/m), as given to the constructor; the one in force is
    /// getStiffness(state).
    const SimTK::Vec6& getStiffness() const;
    /// The body O the element holds.
    const SimTK::MobilizedBody& getObjectBody() const;
    /// Default D per axis (N m s/rad, N s/m), as given to the constructor; the one in force is
    /// getDamping(state).
    const SimTK::Vec6& getDamping() const;
    /// Width w of the slip-onset band, as a fraction of the limit (default 0.01).
    double getSlipOnsetWidth() const;
    /// Sets w in (0, 1]; a topology change (call before realizeTopology()).
    /// @throws graspsim::InputError for a value outside (0, 1].
    void setSlipOnsetWidth(double width);

    /// Whether the element applies force (and its anchor moves) in `state`.
    bool isEnabled(const SimTK::State& state) const;
    /// Switches the element on or off; invalidates Stage::Instance. A disabled element applies
    /// nothing and its anchor is frozen: call resetAnchor() when enabling it again. Use this,
    /// not Force::disable(), which would also skip the element's zdot computation.
    void setEnabled(SimTK::State& state, bool enabled) const;

    /// Per-axis force limits L (N m for 0-2, N for 3-5) in `state`, before locking: the upper side
    /// L+ (the force on O along the axis stays <= L+).
    const SimTK::Vec6& getLimits(const SimTK::State& state) const;
    /// The lower side L- (>= 0; the force on O stays >= -L-), before locking; getLimits() unless
    /// two-sided limits were set.
    const SimTK::Vec6& getLowerLimits(const SimTK::State& state) const;
    /// Sets L (each >= 0; +Infinity allowed); invalidates Stage::Dynamics. The thesis's values
    /// are mu F_perp on translation axes (eq. 4.1) and mu |r| F_perp on rotation axes (eq. 4.2).
    /// If `state` is realized to Stage::Position, the anchor is moved so that |K_k e_k| <= L_k on
    /// every axis (a lowered limit turns the excess elastic strain into slip at once, as an
    /// elasto-plastic material does); otherwise the anchor is left alone.
    /// @throws graspsim::InputError naming the axis for a negative or NaN limit.
    void setLimits(SimTK::State& state, const SimTK::Vec6& limits) const;
    /// Two-sided limits: the force on O along axis k stays in [-lower_k, +upper_k] (each >= 0;
    /// +Infinity allowed); the slip onset of a loaded axis is decided by the side it is loaded
    /// toward. Otherwise as setLimits(state, limits), which is setLimits(state, limits, limits).
    void setLimits(SimTK::State& state, const SimTK::Vec6& lower, const SimTK::Vec6& upper) const;
    /// K per axis in force in `state` (N m/rad for 0-2, N/m for 3-5); the constructor's until
    /// setStiffness() is called; the diagonal of a coupled stiffness.
    const SimTK::Vec6& getStiffness(const SimTK::State& state) const;
    /// D per axis in force in `state` (N m s/rad for 0-2, N s/m for 3-5).
    const SimTK::Vec6& getDamping(const SimTK::State& state) const;
    /// Sets K (each > 0, finite) and D (each >= 0, finite) in `state`, e.g. at engagement from the
    /// limits so that the elastic displacement at the limit, L_k / K_k, is bounded; invalidates
    /// Stage::Dynamics. The anchor keeps its pose; if `state` is realized to Stage::Position and
    /// a softer K would put |K_k e_k| over L_k, the anchor is moved as setLimits() does.
    /// @throws graspsim::InputError naming the axis for a bad stiffness or damping.
    void setStiffness(SimTK::State& state, const SimTK::Vec6& stiffness,
                      const SimTK::Vec6& damping) const;
    /// A coupled stiffness K (6 x 6, rotation first, in A's axes: N m/rad, N m/m = N/rad and N/m
    /// blocks), symmetric positive definite: the elastic load is K e (file comment); damping D
    /// per axis as above. The anchor rule of a softer stiffness reads K's diagonal.
    /// @throws graspsim::InputError for a non-finite, asymmetric or not positive definite K, or a
    ///         bad damping.
    void setStiffness(SimTK::State& state, const SimTK::Mat66& stiffness, const SimTK::Vec6& damping) const;
    /// The stiffness in force as a matrix (rotation first): the coupled K, or diag(getStiffness(state)).
    SimTK::Mat66 findStiffnessMatrix(const SimTK::State& state) const;
    /// Whether `axis` is locked (limit infinite regardless of getLimits()).
    bool isAxisLocked(const SimTK::State& state, BushingAxis axis) const;
    /// Locks (true) or relaxes (false, limited by getLimits()) `axis`; invalidates
    /// Stage::Dynamics. Relaxing follows the same anchor rule as setLimits().
    void setAxisLocked(SimTK::State& state, BushingAxis axis, bool locked) const;
    /// The limits in force: L_k (the upper side), or +Infinity for a locked axis.
    SimTK::Vec6 findEffectiveLimits(const SimTK::State& state) const;
    /// The lower sides in force: L-_k, or +Infinity for a locked axis.
    SimTK::Vec6 findEffectiveLowerLimits(const SimTK::State& state) const;

    /// Moves frame F to pose X_HF on H and frame M to X_OM on O (m; e.g. both at the point the
    /// element should act through); invalidates Stage::Instance. The anchor keeps its pose in F,
    /// so call resetAnchor() afterwards (the grasp switch does it on engagement).
    void setFrames(SimTK::State& state, const SimTK::Transform& X_HF,
                   const SimTK::Transform& X_OM) const;
    /// Pose X_HF of F on H in `state`. Any stage.
    const SimTK::Transform& getFrameOnH(const SimTK::State& state) const;
    /// Pose X_OM of M on O in `state`. Any stage.
    const SimTK::Transform& getFrameOnO(const SimTK::State& state) const;

    /// Sets the anchor to the current relative pose (X_FA0 := X_FM, z := 0), so the elastic
    /// displacement and the spring force are zero: engaging the element causes no jump (only
    /// the damping force, proportional to the current relative velocity, remains). Needs
    /// Stage::Position.
    void resetAnchor(SimTK::State& state) const;
    /// Sets the anchor so that the displacement of M from it is `e` (rotation vector, rad, and
    /// position, m, in A). Needs Stage::Position.
    void setAnchorDisplacement(SimTK::State& state, const SimTK::Vec6& e) const;

    /// Pose X_FA of the anchor in F. Needs Stage::Topology (reads state variables only).
    SimTK::Transform findAnchorTransform(const SimTK::State& state) const;
    /// Displacement e of M from the anchor (rad, m; in A). Needs Stage::Position.
    SimTK::Vec6 findDisplacement(const SimTK::State& state) const;
    /// Generalized force f on O (N m, N; in A), zero if disabled. Needs Stage::Velocity.
    SimTK::Vec6 findGeneralizedForce(const SimTK::State& state) const;
    /// Spatial force on O (moment about M's origin, N m; force, N), expressed in Ground.
    /// H receives the opposite at M's origin. Needs Stage::Velocity.
    SimTK::SpatialVec findWrench(const SimTK::State& state) const;
    /// Whether `axis`'s anchor is slipping: enabled, loading (e_k r_k > 0) and the slip
    /// fraction s_k >= 0.5. Needs Stage::Velocity.
    bool isSliding(const SimTK::State& state, BushingAxis axis) const override;
    double getSlipOnsetFraction() const override { return 1 - getSlipOnsetWidth(); }

    /// GraspAttachment: whether enabled.
    bool isEngaged(const SimTK::State& state) const override { return isEnabled(state); }
    /// GraspAttachment: moves F and M to `engagement`'s frames, enables the element with its
    /// anchor at the current pose (no spring force jump), stiffens it so that its elastic
    /// deflection at the limits moves no fingertip (at most engagement.leverArm from M) more
    /// than engagement.penetrationBound (calcStiffnessForBound with each axis's larger side, never below the constructor's
    /// stiffness; engagement.stiffness in its place on the axes it sets, engagement.stiffnessMatrix
    /// in its place altogether; damping critical with the stiffness's diagonal and the object's
    /// mass and central moments of inertia), then sets the limits (two-sided if
    /// engagement.lowerLimits is set) and locks. With engagement.preload, the anchor is then set
    /// back so that the spring carries it (clamped to the limits in force). Leaves `state`
    /// realized to Stage::Position.
    void engage(SimTK::State& state, const AttachmentEngagement& engagement) const override;
    /// GraspAttachment: disables the element.
    void release(SimTK::State& state) const override { setEnabled(state, false); }
    /// GraspAttachment: Stage::Velocity (a force of the state).
    SimTK::Stage getReactionStage() const override { return SimTK::Stage::Velocity; }
    /// GraspAttachment: a LimitedBushingJacobian (limited_bushing_jacobian.h, where it is defined).
    std::unique_ptr<integration::ForceJacobianContributor> makeForceJacobian(
        const SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& bodyH,
        const SimTK::MobilizedBody& bodyO) const override;
    /// GraspAttachment: findWrench() with its moment moved to O's origin. Needs Stage::Velocity.
    SimTK::SpatialVec findReactionOnObject(const SimTK::State& state) const override;
    /// GraspAttachment: getFrameOnO(), findEffectiveLimits(), findGeneralizedForce(), findWrench()
    /// and findEffectiveLowerLimits() while enabled. Needs Stage::Velocity.
    std::optional<SingleConstraintState> findSingleConstraintState(const SimTK::State& state) const override;
};

}  // namespace graspsim::grasp
