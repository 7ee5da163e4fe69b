#pragma once
/// @file
/// Rigid contact: a unilateral contact with Coulomb friction between two of our exact shapes,
/// for Simbody's SemiExplicitEulerTimeStepper (the `rigid` contact model, as opposed to the
/// compliant CompliantContactForce).
///
/// Simbody 3.7 only has rigid contact for sphere-sphere, sphere-plane, point-plane and
/// edge-edge. RigidContact is a SimTK::UnilateralContact subclass (the public, abstract
/// interface the time stepper drives) over a RigidContactConstraint (a Constraint::Custom with
/// one normal and two friction equations), so any pair with a sphere or a capsule on one side
/// (sphere, capsule, box, half-space on the other) gets rigid contact with the exact geometry
/// of shape_contact.h, recomputed at every pose the stepper asks about. Nothing is replaced
/// by a simpler shape.
///
/// What the stepper does with it, each step: getPerr() (the exact gap) decides whether the
/// contact is proximal (gap <= the stepper's constraint tolerance); proximal contacts are
/// enabled, the others disabled; the impulse solver then makes the normal multiplier
/// non-attractive (lambda_n <= 0, see UnilateralContact's sign convention 1) and keeps the two
/// friction multipliers inside the Coulomb cone |lambda_t| <= mu |lambda_n|, with mu from
/// calcEffectiveCOF() at the slip speed at the start of the step.
///
/// Use the PGS impulse solver (SemiExplicitEulerTimeStepper::setImpulseSolverType(PGS)), or
/// RigidImpulseSolver (rigid_impulse_solver.h: the same impulses without Debian's debug work),
/// which simulation::RigidStepper installs.
/// Simbody 3.7's default PLUS solver, in a box squeezed between two spheres, keeps the box stuck
/// at any pull, with friction impulses beyond the Coulomb cone; Simbody's own PointPlaneContact
/// does exactly the same in that scene, so this is the solver's, not this class's. PGS stops at
/// its own tolerance, so a stuck contact creeps at about 1e-5 m/s.
///
/// Limits (not silent): one contact point per pair, so a capsule lying flat on a face or
/// parallel to another capsule is held at the middle of the line of contact only (it can rock
/// about it); box-box and box-half-space pairs are rejected here (RigidContactSet turns them into
/// contacts of the boxes' rounded corners, with the limits documented in rigid_contact_set.h). A contact is found on the first step
/// that ends within the stepper's constraint tolerance, so an impact can leave a penetration of
/// up to one step's approach (impact speed x step); Simbody 3.7's stepper does not project it
/// out (its own SpherePlaneContact rests at the same depth). The stepper passes its default
/// friction transition speed unchanged (0 unless set), so with mu_s > mu_d any nonzero slip
/// speed gets mu_d. Debian's Simbody 3.7 is built without NDEBUG, so the stepper and its
/// impulse solvers print a debug trace to stdout at every step (about 10 kB per step in the tests).
#include "graspsim/simbody.h"

#include <string>

#include "graspsim/contact/contact_pair.h"
#include "graspsim/contact/contact_shape.h"
#include "graspsim/contact/rigid_contact_geometry.h"

namespace graspsim::contact {

/// Rigid contact's own settings; the pair's friction comes from its ContactParameters
/// (staticFriction, dynamicFriction, viscousFriction; the stiffness, dissipation and transition
/// velocity of the compliant law have no rigid counterpart).
struct RigidContactOptions {
    /// Coefficient of restitution at high impact speed (0..1); lower impact speeds get more,
    /// down to the capture speed (SimTK::ConditionalConstraint::calcEffectiveCOR()).
    double minRestitution = 0;
    /// First margin (m) used to find the gap of separated shapes (rigid_contact_geometry.h).
    /// Any positive value gives the same results; it only affects the cost of the query.
    double searchMargin = 0.01;

    /// Checks: minRestitution in [0, 1]; searchMargin finite and > 0.
    /// @throws graspsim::InputError "<source>: <field> (<value>) must be <accepted>".
    void validate(const std::string& source) const;
};

/// A unilateral contact with Coulomb friction between shape A on body A and shape B on body B;
/// the normal points from A toward B. Create it with add(), which hands it to the matter
/// subsystem (SimbodyMatterSubsystem::adoptUnilateralContact()).
class RigidContact : public SimTK::UnilateralContact {
public:
    /// Builds the contact of `pair` (A = pair.a, B = pair.b, friction from pair.parameters) and
    /// its (disabled by default) constraint in `matter`.
    /// @throws graspsim::InputError for an unsupported pair (two solids), both shapes on one
    ///         body, or bad parameters (ContactParameters::validate()) or options.
    RigidContact(SimTK::SimbodyMatterSubsystem& matter, const ContactPair& pair,
                 const RigidContactOptions& options = {});

    /// Creates a RigidContact for `pair` and adopts it into `matter`, whose topology must not be
    /// realized yet. Returns its index.
    static SimTK::UnilateralContactIndex add(SimTK::SimbodyMatterSubsystem& matter,
                                             const ContactPair& pair,
                                             const RigidContactOptions& options = {});

    /// The exact contact geometry in Ground at the pose in `state` (Stage::Position).
    RigidContactGeometry findGeometryInGround(const SimTK::State& state) const;

    /// The Constraint::Custom underneath (for multipliers and reactions).
    const SimTK::Constraint::Custom& getConstraint() const { return m_constraint; }

    // SimTK::UnilateralContact interface.
    bool disable(SimTK::State& state) const override;
    bool enable(SimTK::State& state) const override;
    bool isEnabled(const SimTK::State& state) const override;
    /// The contact point in Ground (m).
    SimTK::Vec3 whereToDisplay(const SimTK::State& state) const override;
    SimTK::Real calcEffectiveCOR(const SimTK::State& state, SimTK::Real defaultCaptureSpeed,
                                 SimTK::Real defaultMinCORSpeed,
                                 SimTK::Real impactSpeed) const override;
    /// The exact signed gap between the surfaces (m); negative when overlapping. Needs
    /// Stage::Position; valid whether or not the contact is enabled.
    SimTK::Real getPerr(const SimTK::State& state) const override;
    /// Whether the gap is at most ptol (m), as getPerr() <= ptol. Pairs that a cheap lower bound
    /// of the gap puts more than ptol apart are answered without the exact gap search.
    bool isProximal(const SimTK::State& state, SimTK::Real ptol) const override;
    /// Normal separation speed n . (v_B(P) - v_A(P)) (m/s); needs Stage::Velocity.
    SimTK::Real getVerr(const SimTK::State& state) const override;
    /// Normal relative acceleration (m/s^2) with the frozen-frame terms of
    /// rigid_contact_constraint.h; needs Stage::Acceleration.
    SimTK::Real getAerr(const SimTK::State& state) const override;
    SimTK::MultiplierIndex getContactMultiplierIndex(const SimTK::State& state) const override;
    bool hasFriction(const SimTK::State&) const override { return true; }
    SimTK::Real calcEffectiveCOF(const SimTK::State& state, SimTK::Real defaultTransitionSpeed,
                                 SimTK::Real slipSpeed) const override;
    /// Slip velocity (m/s) of B relative to A along (tx, ty) = (n.perp(), n x tx).
    SimTK::Vec2 getSlipVelocity(const SimTK::State& state) const override;
    void getFrictionMultiplierIndices(const SimTK::State& state, SimTK::MultiplierIndex& ix_x,
                                      SimTK::MultiplierIndex& ix_y) const override;

private:
    /// A lower bound of the gap (m): the distance from a box to the other shape's bounding sphere
    /// (ContactShape::calcBoundingRadius()), else the distance between the bounding spheres.
    double findGapLowerBound(const SimTK::State& state) const;
    /// v_B(P) - v_A(P) in Ground (Stage::Velocity), and the geometry it was taken at.
    SimTK::Vec3 findSlipVelocityInGround(const SimTK::State& state,
                                         RigidContactGeometry& geometry) const;

    ContactSurface m_a, m_b;
    ContactParameters m_parameters;
    RigidContactOptions m_options;
    SimTK::Constraint::Custom m_constraint;
};

}  // namespace graspsim::contact
