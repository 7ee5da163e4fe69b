#pragma once
/// @file
/// The `multi` attachment of `--mode approx --attach multi`: what the grasp switch
/// (grasp_switch.h) does instead of merging the hand when ApproxOptions::attach is Multi.
///
/// Engage (same trigger as merged: full contact and Q >= Q_Th once settled):
///  (a) the contact reports are shared out per finger: a contact belongs to the goal finger whose
///      chain of bodies (palm excluded) carries it. Per finger i: the force it exerts on the object
///      f_i, F_perp_i = sum f . n, r_i = mean distance of its contact points from their centroid
///      (eq. 4.1-4.3 per finger);
///  (b) the contact pairs of the goal digits are disabled; the palm and digits without a goal stay
///      in ordinary contact (in the phone pinch the middle finger touches the phone and, with the
///      two pinching point contacts, is what keeps it from turning about the pinch axis);
///  (c) NO merge: the finger joints stay free under their PD torques, so each finger flexes on its
///      own; the IK is paused all the same (it is most of full contact's cost, and its goals do not
///      follow the object);
///  (d) every part of the approximation's grasp::MultiAttachment is attached: finger i's distal body to the
///      object at its goal site, limits mu F_perp_i (tangent) and mu r_i F_perp_i (rotation), the
///      normal preloaded to f_i (mu: the scenario's dynamic friction, as merged).
/// Every ik_interval while engaged, each attached finger i is DETACHED on its own (its part off, its
/// contact pairs on again, so it goes back to ordinary contact; a "detach" event) when
///  - it stopped pressing (the part's normal force <= 0: the contact would have opened; this one is
///    also watched between checks by a witness of the grasp switch, so the detach happens where the
///    force falls through zero, not up to ik_interval later while the fingertip is held to an
///    object that is leaving it), or
///  - its anchor slid more than ApproxOptions::releaseSlideDistance on the finger, or
///  - its fingertip is farther than the scenario's held tolerance from its goal on the object.
/// The whole approximation is RELEASED (every part off, every pair on) when fewer than two
/// fingers remain attached (one point contact cannot hold an object), or, as merged, when the
/// monitored quality drops below Q_M (checked by the grasp switch).
///
/// Cost in realism compared with full contact: a part is a sticky point contact at the site where
/// the finger touched at engagement, on the tangent plane there, so a finger cannot roll or re-seat
/// on the surface; friction limits are frozen at engagement (they do not follow the normal force)
/// and are a box per tangent axis, not a cone; the normal holds bilateral until the next check
/// (up to ik_interval late). Engagement also waits for every goal contact to stick (findSlidingContact()). Compared with merged: fingers keep their own dynamics, and one that leaves stops
/// following the object. Cost in time: one 6-DOF element per finger instead of one, plus the
/// free finger joints (merged locks them).

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/grasp/multi_attachment.h"
#include "graspsim/simulation/approximation_context.h"
#include "graspsim/simulation/simulation_options.h"

#include "graspsim/simbody.h"

#include <string>
#include <vector>

namespace graspsim::simulation {

struct GraspEvent;

/// The multi variant's engage / detach / release steps (see the file comment). Used by GraspSwitch.
class MultiAttachmentSwitch {
public:
    /// @param context the approximation's view of the scene, with a MultiAttachment
    ///        (ApproximationContext::multi); must outlive the switch.
    /// @param slideLimit how far a finger's anchor may slide before it is detached (m).
    /// @param penetrationBound how far an attached fingertip may sink into the object under loads
    ///        up to its limits (m): each part is stiffened from its own loads at attachment, as the
    ///        merged bushing is (grasp_switch.h, step (d)).
    MultiAttachmentSwitch(const ApproximationContext& context, double slideLimit, double penetrationBound);

    /// The first goal finger's contact that does not stick (slip speed at or above the scenario's
    /// friction transition velocity, its own threshold for "sticking"), or nullptr when every one
    /// sticks. Multi engages only then: each part is a sticking contact, and attaching one that
    /// slides (e.g. right after a release, the object falling) would freeze the slide. `reports`:
    /// the contacts of the state to judge; the result points into it.
    const contact::ContactReport* findSlidingContact(const std::vector<contact::ContactReport>& reports) const;
    /// Steps (a), (b), (d); returns the limits, per finger, as text for the engage event.
    std::string engage(SimTK::State& state, const std::vector<contact::ContactReport>& reports) const;
    /// Detaches the fingers that left (appending "detach" events with `quality`, N); returns why the
    /// whole approximation must be released, or an empty string.
    std::string update(SimTK::State& state, double quality, std::vector<GraspEvent>& events) const;
    /// Every part off, every contact pair on.
    void release(SimTK::State& state) const;
    /// The smallest pressing force over the attached fingers (N), +Infinity with none attached.
    /// Needs Stage::Velocity and realizes nothing, so a witness may call it mid-realization.
    double findSmallestPressing(const SimTK::State& state) const;

private:
    int findFinger(const std::string& body) const;
    std::string describeDetach(const SimTK::State& state, int finger) const;

    const ApproximationContext& context_;
    double slideLimit_;
    double penetrationBound_;
    std::vector<std::vector<std::string>> fingerBodies_;  // per goal: the digit's bodies, palm excluded
    std::vector<std::vector<int>> fingerPairs_;           // per goal: its contact pairs
};

}  // namespace graspsim::simulation
