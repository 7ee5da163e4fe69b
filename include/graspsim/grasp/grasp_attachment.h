#pragma once
/// @file
/// The interface of the approximation's friction-limited attachments (thesis section 4.2, eq.
/// 4.1-4.3): what the grasp switch, the engaged-grasp tracker and the cost table need of the
/// element that holds the object in place of the finger-object contacts, whichever realizes it:
///  - LimitedBushing: compliant, one 6-DOF element between the palm H and the object O;
///  - LimitedWeld: rigid (constraints that give way at their limits), palm H to object O;
///  - MultiAttachment: one friction-limited bushing per fingertip.
/// Every attachment engages at the current pose with no force jump beyond what its own file
/// comment states, holds while the load on each axis stays below that axis's limit, slides at the
/// limit (carrying exactly the limit, Coulomb friction per axis), and lets go without changing a
/// velocity (tests/grasp/grasp_attachment_test.cpp checks the three against closed forms).

#include "graspsim/integration/force_jacobian.h"
#include "graspsim/simbody.h"

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace graspsim::grasp {

/// One of the six axes of an attachment, in SpatialVec order (rotation first).
enum class BushingAxis { RotationX = 0, RotationY, RotationZ, TranslationX, TranslationY, TranslationZ };

/// Index of `axis` in a Vec6 of per-axis values (0-2 rotation, 3-5 translation).
constexpr int toIndex(BushingAxis axis) { return static_cast<int>(axis); }

/// One finger's load at attachment, from its contacts (eq. 4.1-4.3 per finger).
struct FingerLoad {
    bool atContact = false;        ///< place S_i at contact_G / normal_G (else at the AttachmentSite)
    SimTK::Vec3 contact_G{0, 0, 0};  ///< centroid of the finger's contact points, in Ground (m)
    SimTK::Vec3 normal_G{0, 0, 1};   ///< object's outward normal there, in Ground (unit)
    SimTK::Vec3 tangentHint_G{0, 0, 0};  ///< S_i's x direction (tangent part), in Ground, as AttachmentSite's
    SimTK::Vec3 force_G{0, 0, 0};  ///< total contact force of the finger on the object, in Ground (N)
    double normalForce = 0;        ///< F_perp_i = sum f . n over the finger's contacts (N), >= 0
    double armRadius = 0;          ///< r_i: mean distance of its contact points from their centroid (m)
};

/// What an attachment is engaged with. Palm attachments (bushing, weld) read the frames, limits,
/// locks and bounds; the multi-attachment reads the per-finger loads, `mu` and the bound.
struct AttachmentEngagement {
    SimTK::Transform X_HF;  ///< pose of F on the palm H (m); coincides with M at engagement
    SimTK::Transform X_OM;  ///< pose of M on the object O (m)
    /// Per-axis limits L, rotation first (N m for 0-2, N for 3-5): mu r F_perp and mu F_perp. With
    /// `lowerLimits` set, the upper side L+ (the force on the object along the axis stays <= L+).
    SimTK::Vec6 limits{0};
    /// The lower sides L- (force on the object >= -L-), for two-sided limits; unset: symmetric,
    /// L- = L+ = limits. Only the bushing takes two-sided limits (the weld refuses them).
    std::optional<SimTK::Vec6> lowerLimits;
    std::array<bool, 6> lockedAxes{};  ///< per axis, true: locked (limit infinite)
    /// Farthest contact point from M's origin (m): the lever through which the element's rotation
    /// moves a fingertip (for the compliant element's stiffness).
    double leverArm = 0;
    /// How far the element's elastic deflection under loads up to its limits may move a
    /// fingertip into the object (m); compliant elements are stiffened to keep within it.
    double penetrationBound = 0;
    /// Per axis, a stiffness (N m/rad for 0-2, N/m for 3-5) in place of the penetration bound's,
    /// where set and positive (NaN: the bound's). Only the bushing takes it.
    std::optional<SimTK::Vec6> stiffness;
    /// A coupled stiffness (6 x 6, rotation first, along M's axes; symmetric positive definite) in
    /// place of the per-axis one: the grasp's whole compliance model (bushing_give.h). Only the
    /// bushing takes it.
    std::optional<SimTK::Mat66> stiffnessMatrix;
    /// The generalized force on the object along M's axes (N m, N) that the element carries at
    /// engagement, clamped to its limits: its anchor is set back by preload / K, so that the
    /// element takes over the contacts' wrench without the object first sagging into its spring.
    /// Unset: none (the anchor at the current pose). Only the bushing takes it.
    std::optional<SimTK::Vec6> preload;
    std::vector<FingerLoad> fingers;  ///< per part, in part order (multi-attachment)
    double mu = 0;                    ///< friction coefficient of the per-finger limits (multi-attachment)
};

/// The state of an attachment that is one palm-object constraint (bushing or weld), for reports.
/// Axes k in SpatialVec order: 0-2 rotation about the constraint frame M's x, y, z, 3-5
/// translation along them.
struct SingleConstraintState {
    SimTK::Transform X_OM;      ///< pose of the constraint frame M on the object O (m)
    SimTK::Vec6 limits{0};      ///< effective limits, upper side (N m for 0-2, N for 3-5); +Infinity on locked axes
    SimTK::Vec6 reaction{0};    ///< generalized reaction on the object along M's axes (N m, N)
    SimTK::SpatialVec wrench_G; ///< the same as a spatial force on the object (moment about M's origin, N m; force, N), in Ground
    /// Lower sides of two-sided limits (the reaction stays >= -lowerLimits); equal to `limits`
    /// for symmetric ones.
    SimTK::Vec6 lowerLimits{0};
};

/// The friction-limited attachment of the grasp approximation (see the file comment).
class GraspAttachment {
public:
    virtual ~GraspAttachment() = default;

    /// Whether the attachment holds the object (any part of it) in `state`. Any stage.
    virtual bool isEngaged(const SimTK::State& state) const = 0;
    /// Engages at the current pose with `engagement`'s frames and limits. An Instance-stage change
    /// (do it in an event handler); needs Stage::Position beforehand and leaves `state` realized
    /// to at least Stage::Position.
    virtual void engage(SimTK::State& state, const AttachmentEngagement& engagement) const = 0;
    /// Lets go of the object: nothing acts afterwards and no velocity changes. Instance-stage.
    virtual void release(SimTK::State& state) const = 0;
    /// The stage findReactionOnObject() needs (Velocity for a force element, Acceleration for
    /// constraints, whose reactions are Lagrange multipliers).
    virtual SimTK::Stage getReactionStage() const = 0;
    /// The attachment's spatial force on the object, its moment about O's origin (N m) and force
    /// (N), expressed in Ground; zero when released. Needs getReactionStage().
    virtual SimTK::SpatialVec findReactionOnObject(const SimTK::State& state) const = 0;
    /// Whether `axis` slides (carries its limit while moving) in `state`, for the multi-attachment
    /// in any attached part (each along its own site axes). Needs Stage::Velocity.
    virtual bool isSliding(const SimTK::State& state, BushingAxis axis) const = 0;
    /// The fraction of an axis's limit at which the axis begins to slide: 1 for a hard limit (the
    /// default), 1 - w for the bushing's slip-onset band (LimitedBushing::getSlipOnsetWidth()).
    virtual double getSlipOnsetFraction() const { return 1.0; }
    /// Frame, limits and reaction while engaged, for an attachment that is one palm-object
    /// constraint; nullopt while released and for attachments of several parts (the default).
    /// Needs getReactionStage().
    virtual std::optional<SingleConstraintState> findSingleConstraintState(const SimTK::State& state) const {
        (void)state;
        return std::nullopt;
    }
    /// The attachment's force Jacobians for the linearly implicit stepper
    /// (integration/force_jacobian.h), for an attachment built between the palm `bodyH` and the
    /// object `bodyO`; nullptr (the default) when it has none to give: a constraint (its forces
    /// are not functions of the motion) or an attachment whose Jacobian is not built, which the
    /// stepper then treats explicitly. The result refers to this attachment and must not outlive it.
    virtual std::unique_ptr<integration::ForceJacobianContributor> makeForceJacobian(
        const SimTK::SimbodyMatterSubsystem& matter, const SimTK::MobilizedBody& bodyH, const SimTK::MobilizedBody& bodyO) const {
        (void)matter, (void)bodyH, (void)bodyO;
        return nullptr;
    }

protected:
    GraspAttachment() = default;
    GraspAttachment(const GraspAttachment&) = default;
    GraspAttachment& operator=(const GraspAttachment&) = default;
};

/// A spatial force W_M with its moment about the point M (p_OM in O, m), moved to O's origin:
/// the moment gains p_OM x F (all expressed in Ground; R_GO turns p_OM into Ground).
SimTK::SpatialVec shiftToObjectOrigin(const SimTK::SpatialVec& W_M, const SimTK::Rotation& R_GO,
                                      const SimTK::Vec3& p_OM);

}  // namespace graspsim::grasp
