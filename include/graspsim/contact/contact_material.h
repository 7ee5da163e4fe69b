#pragma once
/// @file
/// The material of one contact surface, with the same parameters as Simbody's
/// HuntCrossleyForce::setBodyParameters() plus its transition velocity, so numbers carry over.
/// How two materials combine into the parameters of a contact is in contact_force_law.h.

#include <string>

namespace graspsim::contact {

/// Contact properties of one surface. Defaults: a 1 MPa frictionless, undamped surface with
/// Simbody's default transition velocity.
struct ContactMaterial {
    /// Plane-strain modulus E / (1 - nu^2) (Pa), from Young's modulus E and Poisson's ratio nu.
    double stiffness = 1e6;
    /// Hunt-Crossley dissipation c (s/m): the coefficient of restitution of a slow impact at
    /// speed v is about 1 - c v.
    double dissipation = 0;
    /// Coulomb friction coefficient when sticking (dimensionless).
    double staticFriction = 0;
    /// Coulomb friction coefficient when sliding (dimensionless), <= staticFriction.
    double dynamicFriction = 0;
    /// Viscous friction coefficient (s/m): adds viscousFriction * slip speed to the coefficient.
    double viscousFriction = 0;
    /// Slip speed (m/s) at which friction reaches its static peak. Friction is a continuous
    /// function of slip speed, so a tangential load below the static limit still creeps, at
    /// a speed below about transitionVelocity * load / (static limit) (see contact_force_law.h).
    double transitionVelocity = 0.01;

    /// Checks every field: stiffness finite and > 0; dissipation, the three friction
    /// coefficients finite and >= 0; dynamicFriction <= staticFriction; transitionVelocity
    /// finite and > 0.
    /// @param source names the material for the message (e.g. "hand material").
    /// @throws graspsim::InputError "<source>: <field> (<value>) must be <accepted>".
    void validate(const std::string& source) const;

    /// The pad of a human finger or palm (skin over soft tissue). Assumptions, not
    /// transcribed from one source: stiffness 0.67 MPa (Young's modulus 0.5 MPa, nu = 0.5,
    /// within the 0.1-1 MPa range of in-vivo fingertip measurements in the literature);
    /// dissipation 1 s/m (skin is strongly damped: restitution about 0.9 at 0.1 m/s);
    /// friction static 0.8, dynamic 0.6 (dry skin on smooth plastic is reported between about
    /// 0.3 and 1.5, rising with moisture); no viscous friction; transition velocity 1 mm/s, so
    /// a held object creeps by less than about 1 mm/s.
    static ContactMaterial fingerPad();

    /// A hard plastic object (ABS-like): stiffness 2.6 GPa (E = 2.3 GPa, nu = 0.35, handbook
    /// values); dissipation 0.5 s/m; friction static 0.8, dynamic 0.6, so that skin on
    /// plastic keeps the skin's coefficients (combined as 2 a b / (a + b)); transition velocity
    /// 1 mm/s. Skin on this plastic: effective stiffness E* = 0.66 MPa (assumption, as above).
    static ContactMaterial rigidPlastic();
};

}  // namespace graspsim::contact
