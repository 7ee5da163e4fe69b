#pragma once
/// @file
/// The parameters of one contact pair: what the compliant force law (contact_force_law.h), the
/// elastic-anchor friction (anchor_friction.h) and rigid contact (rigid_contact.h) need to know
/// about the two surfaces together. They are given per pair, not per surface: the scenario file
/// gives them, and the grasp approximation reads the same values (friction limits, the sticking
/// speed, the grasp quality's mu) from the scene.
///
/// The defaults are the scenario file's defaults (models/scenarios/ball-clutch.yaml documents
/// their sources): a soft finger pad on smooth plastic.

#include <string>

namespace graspsim::contact {

/// Where a capsule touches a box, a half-space or an object solid (cylinder, ellipsoid, convex
/// mesh) in compliant contact (shape_contact.h). Rigid contact, the planner and the set-up check
/// always use Deepest.
enum class CapsuleContact {
    /// One contact, at the core point deepest in the solid. A capsule lying flat on a face has its
    /// deepest point at one end or the other with the sign of a tilt of a few microradians, so its
    /// contact jumps by the capsule's length (docs/contact.md, "A capsule lying flat").
    Deepest,
    /// A contact at each end of the core within reach of the solid, each with its own depth, and
    /// one at a deeper interior minimum (a box edge across the capsule) with the deeper end's
    /// depth taken off: the force and moment are continuous as the capsule tilts through flat.
    Ends,
};

/// "deepest" or "ends".
std::string toString(CapsuleContact rule);

/// Parses "deepest" or "ends".
/// @param source names the field or flag for the message (e.g. "contact.capsule_contact").
/// @throws graspsim::InputError "<source>: '<text>' is not accepted; use deepest or ends".
CapsuleContact parseCapsuleContact(const std::string& text, const std::string& source);

/// Contact parameters of one pair of surfaces.
struct ContactParameters {
    /// Effective (pair) plane-strain modulus E* (Pa), > 0: 1/E* = (1 - nu_a^2)/E_a +
    /// (1 - nu_b^2)/E_b. Default 5e5, a soft finger pad on a much stiffer object.
    double effectiveStiffness = 5e5;
    /// Hunt-Crossley dissipation c (s/m), >= 0: the coefficient of restitution of a slow impact
    /// at speed v is about 1 - c v. Default 0.8 (soft tissue is lossy).
    double dissipation = 0.8;
    /// Coulomb friction coefficient when sticking, mu_s (dimensionless), >= dynamicFriction.
    /// Default 0.9.
    double staticFriction = 0.9;
    /// Coulomb friction coefficient when sliding, mu_d (dimensionless), >= 0. Default 0.7.
    double dynamicFriction = 0.7;
    /// Viscous friction coefficient mu_v (s/m), >= 0: adds mu_v * slip speed to the coefficient.
    /// Default 0.
    double viscousFriction = 0;
    /// Slip speed v_tr (m/s), > 0, at which the regularized friction reaches its static peak;
    /// slower slip counts as sticking. Unused by the anchor law and by rigid contact.
    /// Default 1e-3.
    double transitionVelocity = 1e-3;
    /// Where a capsule touches a solid (compliant contact only). Default Deepest.
    CapsuleContact capsuleContact = CapsuleContact::Deepest;

    /// Checks every field: effectiveStiffness and transitionVelocity finite and > 0;
    /// dissipation and the three friction coefficients finite and >= 0; dynamicFriction <=
    /// staticFriction. The one check of these rules: the contact elements call it once per pair.
    /// @param source names the pair for the message (e.g. "contact pair 'a vs b'").
    /// @throws graspsim::InputError "<source>: <field> (<value>) must be <accepted>".
    void validate(const std::string& source) const;
};

}  // namespace graspsim::contact
