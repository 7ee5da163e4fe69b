#pragma once
/// @file
/// Compliant contact between the hand and grasped objects as a Simbody force element.
///
/// Why not Simbody's own: CompliantContactSubsystem has no capsule geometry and no brick-sphere
/// tracker (and ContactGeometry cannot be extended from outside), and HuntCrossleyForce returns
/// from its per-contact loop at the first contact whose force is not positive, silently
/// dropping every later contact of that evaluation. This element evaluates every enabled pair
/// and every contact point of a pair on its own.
///
/// Per contact point P (from findContacts(), normal n from surface a to surface b), with V_GA,
/// V_GB the bodies' spatial velocities:
///  - relative velocity of b's material point at P w.r.t. a's: v = v_GB(P) - v_GA(P);
///  - penetration rate xdot = -v . n; slip velocity v_t = v - (v . n) n;
///  - normal force f_n from contact_force_law.h with the pair's ContactParameters, and friction
///    f_t from the chosen law: the regularized one of contact_force_law.h (default, stateless)
///    or the elastic anchor of anchor_friction.h (true stiction, one anchor per pair held in the
///    State as 4 Z variables); body b receives F = f_n n + f_t at P, body a receives -F at P.
/// Potential energy: sum over contacts of (8/15) E* sqrt(R) x^(5/2) (elastic part only; the
/// dissipation and friction are not conservative, and the anchor springs' energy is not counted).
///
/// Stages: forces are computed when the system is realized to Stage::Dynamics (they need
/// positions and velocities); the potential energy needs Stage::Position; reports need
/// Stage::Velocity. Each force evaluation keeps its contact points in a cache entry
/// (getEvaluatedContacts()), so that the contact Jacobian needs no second geometry pass.
/// With anchors, the anchors' rates (Z derivatives) are set in the same Dynamics-stage pass; do
/// not disable the element as a whole (Force::disable) then, as its anchors would get no rate
/// (disable its pairs instead: a disabled pair's anchor relaxes to zero).

#include "graspsim/simbody.h"

#include <string>
#include <vector>

#include "graspsim/contact/anchor_friction.h"
#include "graspsim/contact/contact_pair.h"

namespace graspsim::contact {

/// One contact point as the force element sees it at a state.
struct ContactReport {
    int pairIndex = -1;                    ///< index of the pair in the element's list
    std::string bodyA, bodyB;              ///< body names of surfaces a and b
    std::string shapeA, shapeB;            ///< shape names of surfaces a and b
    SimTK::Vec3 p_G{0, 0, 0};              ///< contact point in Ground (m)
    SimTK::UnitVec3 n_G;                   ///< unit normal from a toward b, in Ground
    double depth = 0;                      ///< penetration (m), > 0
    double radius = 0;                     ///< effective Hertz radius of curvature (m; shape_contact.h)
    double depthRate = 0;                  ///< penetration rate xdot (m/s), > 0 while penetrating
    SimTK::Vec3 slipVelocity_G{0, 0, 0};   ///< v_t, slip of b relative to a at P, in Ground (m/s)
    double normalForce = 0;                ///< f_n (N), >= 0, pushes b along +n_G and a along -n_G
    SimTK::Vec3 frictionForce_G{0, 0, 0};  ///< f_t on body b, in Ground (N); a gets -f_t
};

/// The penetration of one contact point of a pair: findContactReports' geometry without the
/// forces, the names or the velocities.
struct ContactDepth {
    int pairIndex = -1;  ///< index of the pair in the element's list
    double depth = 0;    ///< penetration (m), > 0
};

/// A report naming `pair` (index, bodies, shapes) with every measured field still zero: the
/// start of each contact model's reports.
ContactReport makePairReport(const ContactPair& pair, int pairIndex);

/// The sum of the reports' normal forces f_n (N): a grasp's grip force, friction being tangential.
double sumNormalForces(const std::vector<ContactReport>& reports);

/// The compliant contact force element (a Simbody Force::Custom handle; copies refer to the
/// same element, and the element itself belongs to the GeneralForceSubsystem).
///
/// Enabling and disabling pairs: each pair's on/off flag lives in the State, in one discrete
/// variable of Stage::Instance, as Simbody does for Force::disable() and Constraint::disable().
/// Why Instance rather than Dynamics: switching a pair is a jump in force, and after an event
/// handler Simbody's TimeStepper passes the lowest stage the handler modified to
/// Integrator::reinitialize(), which decides from it how much to restart. An Instance change
/// makes that an unmistakable restart (no step-size or, for CPodes, multistep history carried
/// across the jump), and it invalidates every realized stage so no cached result survives.
/// The cost, a full re-realization, is paid only at the switch. Change flags in an event
/// handler (the TimeStepper realizes and reinitializes after it), or before
/// Integrator::initialize(); changing them between two stepTo() calls of a bare Integrator
/// without reinitialize() is not supported.
class CompliantContactForce : public SimTK::Force::Custom {
public:
    /// An empty handle.
    CompliantContactForce() = default;

    /// Adds the element to `forces`. Each pair's parameters are validated here
    /// (ContactParameters::validate()).
    /// @throws graspsim::InputError naming the pair for invalid parameters or a pair of two
    ///         half-spaces.
    CompliantContactForce(SimTK::GeneralForceSubsystem& forces, std::vector<ContactPair> pairs);

    /// As above with the friction law chosen by `friction` (the default is the regularized law).
    /// @throws graspsim::InputError as above, or naming the anchor parameter that is not finite
    ///         and > 0 (AnchorFrictionParameters::validate()).
    CompliantContactForce(SimTK::GeneralForceSubsystem& forces, std::vector<ContactPair> pairs,
                          const FrictionSettings& friction);

    /// The friction law and its parameters, as given to the constructor.
    const FrictionSettings& getFrictionSettings() const;
    /// Pair `pairIndex`'s anchor deflection z (m): position of body b's contact material relative
    /// to its anchor, expressed in the frame of the pair's body a; zero with the regularized law.
    /// Needs Stage::Model. @throws graspsim::InputError if pairIndex is out of range.
    SimTK::Vec3 getAnchorDeflection(const SimTK::State& state, int pairIndex) const;

    /// Number of contact pairs.
    int getNumPairs() const;
    /// Every pair's index, 0 .. getNumPairs() - 1: the list setPairsEnabled() and
    /// findContactReports() take, for all pairs at once.
    std::vector<int> findAllPairIndices() const;
    /// Pair `pairIndex`, as given to the constructor.
    /// @throws graspsim::InputError if pairIndex is out of range.
    const ContactPair& getPair(int pairIndex) const;

    /// Whether pair `pairIndex` is evaluated in `state`. Needs Stage::Topology.
    /// @throws graspsim::InputError if pairIndex is out of range.
    bool isPairEnabled(const SimTK::State& state, int pairIndex) const;
    /// Switches pair `pairIndex` on or off; invalidates Stage::Instance and later.
    /// @throws graspsim::InputError if pairIndex is out of range.
    void setPairEnabled(SimTK::State& state, int pairIndex, bool enabled) const;
    /// Switches every listed pair on or off at once (one invalidation).
    /// @throws graspsim::InputError if an index is out of range (no flag changed then).
    void setPairsEnabled(SimTK::State& state, const std::vector<int>& pairIndices,
                         bool enabled) const;

    /// Every contact point of every enabled pair, with its forces. Needs Stage::Velocity.
    std::vector<ContactReport> findContactReports(const SimTK::State& state) const;
    /// The contact points of every enabled pair as the last force evaluation at `state` found
    /// them: findContactReports(state) without the body and shape names (left empty), from a
    /// cache entry the evaluation fills (Stage::Dynamics), or computed here where none filled it
    /// (state realized to Stage::Velocity only, or the element disabled). With the elastic-anchor
    /// law the friction forces are those of the anchors at the last Dynamics realization.
    /// The reference is valid until the state's positions or velocities change.
    const std::vector<ContactReport>& getEvaluatedContacts(const SimTK::State& state) const;
    /// Every contact point of the listed pairs, enabled or not, with the forces they would apply
    /// (nothing is applied): what switching them on would give, without an Instance-stage
    /// change. Needs Stage::Velocity. @throws graspsim::InputError for an index out of range.
    std::vector<ContactReport> findContactReports(const SimTK::State& state, const std::vector<int>& pairIndices) const;
    /// The depth of every contact point of the listed pairs, enabled or not, in pair order: the
    /// depths findContactReports(state, pairIndices) reports, without the forces, velocities and
    /// names (the engaged approximation measures penetration so at every check). Needs
    /// Stage::Position. @throws graspsim::InputError for an index out of range.
    std::vector<ContactDepth> findContactDepths(const SimTK::State& state, const std::vector<int>& pairIndices) const;

private:
    // A Force::Custom handle may hold no data; everything lives in its Implementation (src).
    void checkPairIndex(int pairIndex) const;
};

}  // namespace graspsim::contact
