#pragma once
/// @file
/// Friction with true stiction: an elastic anchor (a "bristle") per contact pair, in the manner
/// of Simbody 3.8's ExponentialSpringForce and of elasto-plastic (LuGre-type) models, selectable
/// beside the regularized law of contact_force_law.h.
///
/// Why: the regularized law's friction vanishes at zero slip, so any tangential load creeps (a
/// held ball slides about 0.19 mm per simulated second). Here the surfaces are tied by a spring
/// to an anchor point; the spring holds a load up to the static limit with no slip at all, and
/// beyond it the anchor slides so that the friction is the kinetic one.
///
/// State: per pair a deflection z (m), the position of body b's contact material relative to
/// its anchor, stored in body a's frame A, and a sliding state sigma in [0, 1] as in
/// ExponentialSpringForce (4 continuous Z variables of the Simbody State per pair, so every
/// integrator, including the CVODE reference, integrates them). Per evaluation, with the pair's
/// mean normal n, its tangential slip velocity v_t (m/s, b relative to a), its normal force N (N)
/// and its tangential stiffness k (N/m):
///
///     z_t  = z - (z . n) n                                  (tangential deflection)
///     c    = 2 sqrt(k m_d)                                  (critical damping on mass m_d)
///     f_e  = -k z_t - c v_t                                 (spring and damper on b)
///     F    = (mu_s - sigma (mu_s - mu_d) + mu_v |v_t|) N    (the friction limit)
///     f    = f_e                    if |f_e| <= F           (sticking)
///          = F f_e / |f_e|          otherwise               (at the limit)
///     s    = max(0, 1 - F / (k |z_t|))                      (> 0: the anchor slides)
///     dz/dt|_A = v_t - (s / tau) z_t - ((z . n) / tau) n
///     d sigma/dt = ((s > 0 ? 1 : 0) - sigma) / tau
///
/// While k |z_t| <= F the anchor is fixed to a (dz/dt = v_t: a pure spring, no creep); beyond
/// it the anchor slides toward the point where the spring alone gives F, within the relaxation
/// time tau, and sigma moves the limit from static to kinetic in tau; once the spring holds the
/// load again, sigma returns to 0 (static). Slip speed is deliberately not what picks static or
/// kinetic friction: v_t includes the spring's own elastic motion, which would break a load
/// between mu_d N and mu_s N loose while the springs take it up. The normal part of z relaxes
/// in tau. The force and z are continuous in the state (min-capped force, max(0, .) sliding);
/// only sigma's rate switches, which integrators step over like any kink. The transition
/// velocity of the regularized law is not used.
///
/// Contacts appearing and disappearing: k and N come from the contact depth (both vanish at
/// zero depth), so the friction vanishes continuously as a contact opens, and with no contact
/// (or the pair disabled) the anchor relaxes to the current point, dz/dt = -z / tau, so a new
/// contact starts unloaded and stuck. No discrete reset is needed.
///
/// Tangential stiffness, from physics rather than a free number: Mindlin's tangential stiffness
/// of a Hertz contact is k_t = (2 (1 - nu) / (2 - nu)) k_n, with k_n = dF_H/dx = 2 E* sqrt(R x)
/// the normal contact stiffness (N/m). For skin (nu = 0.5) the ratio is 2/3; a fingertip carrying
/// 2 N (E* = 0.66 MPa, R = 1 cm, x = 0.8 mm) gets k_t of about 2.5 N/mm, the order measured on
/// finger pads. The spring's deflection at the static limit is then mu_s x (< 1 mm).
/// Damping: critical for the spring on a finger segment (thesis: 20 g), c = 2 sqrt(k_t m_d):
/// between a finger and a held object the relative motion is the finger's (the lighter body).
/// For an object on a fixed pad, state the object's mass instead.
///
/// Pairs with several contact points (box faces, meshes): one anchor per pair. k and N are the
/// sums over the points, n and v_t the stiffness-weighted means (v_t is then the slip at the
/// weighted centre), and the pair's friction is shared among the points by the same weights,
/// so its net force and moment are those of f applied at that centre. Limitation: the anchor
/// resists translation of the pair only; twisting about the normal within one pair is not
/// resisted by friction (a single point contact has no twist friction in either law).

#include "graspsim/simbody.h"

#include <string>

#include "graspsim/contact/contact_force_law.h"
#include "graspsim/contact/friction_settings.h"

namespace graspsim::contact {

/// A contact pair as its anchor sees it: the sums and weighted means over its contact points.
struct AnchorContact {
    double stiffness = 0;               ///< k, sum of the points' tangential stiffnesses (N/m)
    double normalForce = 0;             ///< N, sum of the points' normal forces (N)
    SimTK::UnitVec3 n_G;                ///< mean unit normal from a toward b, in Ground
    SimTK::Vec3 slipVelocity_G{0, 0, 0};  ///< v_t, tangential slip of b relative to a (m/s), in G
};

/// A pair anchor's state (or its rate, per second).
struct AnchorState {
    SimTK::Vec3 deflection_G{0, 0, 0};  ///< z (m), in Ground; as a rate, dz/dt seen in body a (m/s)
    double sliding = 0;                 ///< sigma, 0 (stuck) to 1 (sliding)
};

/// The anchor's friction force on b and its state's rate.
struct AnchorFriction {
    SimTK::Vec3 force_G{0, 0, 0};  ///< f on body b (N), in Ground; a gets -f
    AnchorState rate;              ///< dz/dt (m/s, in Ground) and d sigma/dt (1/s)
};

/// Mindlin tangential stiffness k_t = ratio * 2 E* sqrt(R x) (N/m) of one point contact of
/// depth x >= 0 (m) and effective radius R (m).
double calcAnchorStiffness(const ContactParameters& contact, const AnchorFrictionParameters& anchor,
                           double radius, double depth);

/// The friction limit coefficient mu_s - sigma (mu_s - mu_d) + mu_v v at sliding state sigma
/// and slip speed v >= 0 (m/s).
double calcAnchorFrictionLimit(const ContactParameters& contact, double sliding, double slipSpeed);

/// Friction force and state rate of a pair in contact, at anchor state `state`.
AnchorFriction calcAnchorFriction(const ContactParameters& contact, const AnchorFrictionParameters& anchor,
                                  const AnchorContact& pair, const AnchorState& state);

/// State rate (-z / tau, -sigma / tau) of a pair out of contact or disabled: back to the current
/// point, unloaded and stuck.
AnchorState calcAnchorRelaxationRate(const AnchorFrictionParameters& anchor, const AnchorState& state);

}  // namespace graspsim::contact
