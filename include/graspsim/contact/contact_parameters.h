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

    /// Checks every field: effectiveStiffness and transitionVelocity finite and > 0;
    /// dissipation and the three friction coefficients finite and >= 0; dynamicFriction <=
    /// staticFriction. The one check of these rules: the contact elements call it once per pair.
    /// @param source names the pair for the message (e.g. "contact pair 'a vs b'").
    /// @throws graspsim::InputError "<source>: <field> (<value>) must be <accepted>".
    void validate(const std::string& source) const;
};

}  // namespace graspsim::contact
