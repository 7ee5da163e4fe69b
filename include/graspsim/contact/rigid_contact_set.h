#pragma once
/// @file
/// The rigid contacts of a list of contact pairs (the rigid counterpart of
/// CompliantContactForce's pair list), and their reports.
///
/// Each supported pair (a sphere or a capsule on one side, rigid_contact.h) becomes one
/// RigidContact. A pair of two solids (box-box, box-half-space, box against a cylinder,
/// ellipsoid or convex mesh), which RigidContact does not take, becomes corner contacts: each of a box's 8 corners, rounded with the box's
/// cornerRadius (the radius the compliant model gives box corners, contact_shape.h), is a sphere
/// of that radius inside the corner, touching the box's three faces there, in contact with the
/// other solid; for box-box in both directions (16 contacts). What this catches: a box face
/// resting on a box face or a plane (through the corners of the smaller face), a corner
/// striking a face. What it does not: edge-edge contact of two boxes (crossed edges touching
/// away from any corner), and a sharp corner is met up to (sqrt(3) - 1) cornerRadius late
/// along its diagonal (3.7 mm for the default 5 mm). In the grasp scenes these pairs are the
/// palm boxes against the phone, which do not touch while the phone is held.
///
/// Reports: the stepper leaves its state at Stage::Dynamics with the last step's multipliers
/// (forces, N) filled in; a proximal (enabled) contact's normal force is -lambda_n, its friction
/// force on body b -(lambda_x tx + lambda_y ty) in the contact's friction basis, its penetration
/// -perr (negative for a proximal contact that is not quite touching).
#include "graspsim/simbody.h"

#include <vector>

#include "graspsim/contact/compliant_contact_force.h"
#include "graspsim/contact/contact_pair.h"
#include "graspsim/contact/rigid_contact.h"

namespace graspsim::contact {

/// The contact pairs that `pair` becomes in the rigid model: the pair itself if
/// isRigidContactSupported(), else the corner pairs described in the file comment.
std::vector<ContactPair> makeRigidContactPairs(const ContactPair& pair);

/// Rigid contacts of a pair list, adopted by a matter subsystem.
class RigidContactSet {
public:
    /// No contacts.
    RigidContactSet() = default;

    /// Adds the rigid contacts of every pair to `matter` (its topology must not be realized
    /// yet), with each pair's friction (ContactParameters) and the default RigidContactOptions.
    /// @throws graspsim::InputError naming the pair for an invalid shape or parameters.
    RigidContactSet(SimTK::SimbodyMatterSubsystem& matter, const std::vector<ContactPair>& pairs);

    /// Number of rigid contacts (corner contacts counted one by one).
    int getNumContacts() const { return static_cast<int>(contacts_.size()); }
    const RigidContact& getContact(int k) const;
    /// Index, in the constructor's list, of the pair contact k came from.
    int getPairIndex(int k) const { return pairIndices_.at(static_cast<std::size_t>(k)); }

    /// A report for every enabled (proximal) contact with its forces from the multipliers in
    /// `state` (see the file comment; Stage::Dynamics after a step). pairIndex is the pair's
    /// index in the constructor's list; shape names of corner contacts say which corner.
    std::vector<ContactReport> findContactReports(const SimTK::State& state) const;

private:
    ContactReport makeReport(const SimTK::State& state, int k, const SimTK::Vector& lambda) const;

    const SimTK::SimbodyMatterSubsystem* matter_ = nullptr;
    std::vector<SimTK::UnilateralContactIndex> contacts_;
    std::vector<ContactPair> pairs_;  // the pair of each contact (a corner's own pair)
    std::vector<int> pairIndices_;
};

}  // namespace graspsim::contact
