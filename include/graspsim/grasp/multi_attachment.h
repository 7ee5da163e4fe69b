#pragma once
/// @file
/// The `multi` attachment of the grasp approximation (the thesis's future work,
/// "a custom constraint that allows for more than two attachments"): one friction-limited element
/// spanning the object O and every fingertip, so each finger keeps its own joints and can leave
/// the object on its own.
///
/// Realization in Simbody: one LimitedBushing per finger (a "part"), between the finger's body H_i
/// and a site frame S_i on O, its z axis the object's outward surface normal (M = S_i in
/// limited_bushing.h; F_i coincides with S_i at attachment). S_i is placed at attachment where the
/// finger touches (the centroid of its contacts, their mean normal), so the part's forces act where
/// the contact forces did; the AttachmentSite (the goal point) is the default when no contact point
/// is given.
/// A part is a point contact made sticky:
///  - tangent translations x, y: friction-limited at mu F_perp_i (eq. 4.1 per finger, F_perp_i the
///    normal force of that finger's own contacts at attachment);
///  - normal translation z: locked (a stiff spring, the finger's squeeze), preloaded at attachment
///    so that it pushes exactly as the contact did: no force jump. The normal is bilateral here;
///    a finger that starts pulling (the contact would open) is detached by its owner
///    (simulation/multi_attachment_switch.h), which is what lets a finger leave the object;
///  - rotations: friction-limited at mu r_i F_perp_i (eq. 4.2 per finger, r_i the mean distance of
///    that finger's contact points from their centroid): 0 for a single point contact, which
///    transmits no moment, as the compliant contact it replaces. The grasp's resistance to rotation
///    then comes, as in full contact, from the tangent forces at spread fingertips.
/// So the limits of the merged element (mu F_perp, mu r F_perp) are shared out per finger, and the
/// grasp's translational friction capacity is the sum of the fingers'.
///
/// Parts are attached and detached one by one (LimitedBushing::setEnabled, an Instance-stage
/// change: do it in an event handler).

#include "graspsim/grasp/grasp_attachment.h"
#include "graspsim/grasp/limited_bushing.h"

#include "graspsim/simbody.h"

#include <vector>

namespace graspsim::grasp {

/// Where one finger holds the object.
struct AttachmentSite {
    SimTK::MobilizedBody finger;  ///< the finger's body H_i (its fingertip segment)
    SimTK::Vec3 p_OS;             ///< site origin on the object's surface, in O (m)
    SimTK::UnitVec3 n_O;          ///< outward surface normal at the site, in O
    /// Direction, in O, of S_i's x axis (projected on the tangent plane; ignored if parallel to
    /// n_O). The friction limits are per axis (a box, as the thesis's per-axis limits), so a load
    /// along x or y gets exactly mu F_perp_i, and one along a diagonal up to sqrt(2) times it:
    /// point x along the main expected load (e.g. gravity's tangent part).
    SimTK::Vec3 tangentHint_O{0, 0, 0};
};

/// The element (see the file comment). Copies refer to the same Simbody force elements.
class MultiAttachment : public GraspAttachment {
public:
    MultiAttachment() = default;
    /// Adds one disabled part per site to `forces`.
    /// @param stiffness, damping per axis of EVERY part (rotation N m/rad and N m s/rad, then
    ///        translation N/m and N s/m, in S_i), as LimitedBushing's.
    /// @throws graspsim::InputError for no site, a site on the object itself, or a bad stiffness
    ///         or damping.
    MultiAttachment(SimTK::GeneralForceSubsystem& forces, const SimTK::MobilizedBody& object,
                    const std::vector<AttachmentSite>& sites, const SimTK::Vec6& stiffness,
                    const SimTK::Vec6& damping);

    int getNumParts() const { return static_cast<int>(parts_.size()); }
    /// The bushing of part i (for inspection).
    const LimitedBushing& getPart(int i) const;
    /// Pose X_OS of site i's default (the AttachmentSite) in O; the one in use is
    /// getPart(i).getFrameOnO(state).
    const SimTK::Transform& getSiteTransform(int i) const;

    /// Disables every part; for the initial state (parts are created enabled, as any bushing).
    void detachAll(SimTK::State& state) const;
    /// Attaches part i with limits from `load` (friction coefficient `mu`) and its normal (and
    /// tangent, up to the limits) spring preloaded to `load.force_G`, with the stiffness part i
    /// has in `state` (getPart(i).setStiffness() before attaching changes it). Needs Stage::Position; leaves
    /// `state` realized to Stage::Position. @throws graspsim::InputError for i out of range.
    void attach(SimTK::State& state, int i, const FingerLoad& load, double mu) const;
    /// Detaches part i (it applies nothing until attached again).
    void detach(SimTK::State& state, int i) const;
    bool isAttached(const SimTK::State& state, int i) const;
    int countAttached(const SimTK::State& state) const;

    /// Normal force with which finger i presses on the object (N; > 0 pressing, <= 0 pulling),
    /// 0 if detached. Needs Stage::Velocity.
    double findPressingForce(const SimTK::State& state, int i) const;
    /// How far part i's anchor has slid on the finger since attach() (m): the friction slip,
    /// without the elastic displacement. Needs Stage::Topology.
    double findSlide(const SimTK::State& state, int i) const;

    /// GraspAttachment: whether any part is attached.
    bool isEngaged(const SimTK::State& state) const override { return countAttached(state) > 0; }
    /// GraspAttachment: attaches every part i with engagement.fingers[i] and engagement.mu, each
    /// first stiffened so that its elastic displacement under its largest expected loads (its
    /// friction limits, and on the locked normal its pressing force) moves the fingertip at most
    /// engagement.penetrationBound (calcStiffnessForBound with the finger's arm radius); damping
    /// grows with sqrt(K), keeping each axis's damping ratio. Leaves `state` realized to
    /// Stage::Position. @throws graspsim::InputError unless there is one load per part.
    void engage(SimTK::State& state, const AttachmentEngagement& engagement) const override;
    /// GraspAttachment: detaches every part.
    void release(SimTK::State& state) const override { detachAll(state); }
    /// GraspAttachment: Stage::Velocity (the parts are forces of the state).
    SimTK::Stage getReactionStage() const override { return SimTK::Stage::Velocity; }
    /// GraspAttachment: the sum of the attached parts' wrenches, moments about O's origin.
    SimTK::SpatialVec findReactionOnObject(const SimTK::State& state) const override;
    /// GraspAttachment: whether any attached part slides on `axis` (of its own site frame).
    bool isSliding(const SimTK::State& state, BushingAxis axis) const override;

private:
    void checkPart(int i) const;
    void stiffenPart(SimTK::State& state, int i, const FingerLoad& load, double mu, double penetrationBound) const;

    SimTK::MobilizedBody object_;
    std::vector<LimitedBushing> parts_;
    std::vector<SimTK::MobilizedBody> fingers_;
    std::vector<SimTK::Transform> X_OS_;
    // Anchor position in F_i at attach(), in the State: runs continued from one settled State
    // (capacity/settled_grasps.h) must not see each other's re-attachments.
    std::vector<SimTK::Measure_<SimTK::Vec3>::Variable> p_FA_attached_;
};

}  // namespace graspsim::grasp
