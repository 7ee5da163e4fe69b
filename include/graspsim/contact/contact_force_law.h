#pragma once
/// @file
/// The compliant contact force law: Hunt-Crossley normal force on Hertz elasticity, and
/// Hollars' Stribeck-like friction, exactly as Simbody's HuntCrossleyForce documents them, so
/// that parameters and results are comparable.
///
/// Normal force (N) on a point contact of depth x (m), penetration rate xdot = dx/dt (m/s,
/// positive while penetrating) and effective radius R (m):
///
///     f_H = (4/3) E* sqrt(R) x^(3/2)              (Hertz, elastic)
///     f_n = max(0, f_H (1 + (3/2) c xdot))         (Hunt-Crossley, never pulls)
///
/// Elastic energy stored (J): U = (8/15) E* sqrt(R) x^(5/2)   (dU/dx = f_H).
///
/// Friction on the slip velocity v_t (m/s; relative tangential velocity of the surfaces at the
/// contact point), with v = |v_t| and v_tr the transition velocity:
///
///     mu(v) = min(v / v_tr, 1) (mu_d + 2 (mu_s - mu_d) / (1 + (v / v_tr)^2)) + mu_v v
///     f_t   = -mu(v) f_n v_t / v                   (zero when v = 0)
///
/// mu rises linearly from 0 to mu_s at v = v_tr and decays toward mu_d (+ mu_v v) beyond.
/// Because friction vanishes at v = 0 there is no true stiction: a tangential load F below the
/// sticking limit mu_s f_n makes the contact creep at a speed v < v_tr with mu(v) f_n = F
/// (v = v_tr F / (mu_d f_n) exactly when mu_s = mu_d and mu_v = 0).
///
/// The parameters (E*, c, mu_s, mu_d, mu_v, v_tr) are those of the pair (contact_parameters.h).

#include "graspsim/simbody.h"

#include "graspsim/contact/contact_parameters.h"

namespace graspsim::contact {

/// Hertz elastic force f_H (N) at depth x >= 0 (m) and effective radius R (m).
double calcHertzForce(const ContactParameters& parameters, double radius, double depth);

/// Elastic energy U = (8/15) E* sqrt(R) x^(5/2) (J) stored at depth x >= 0 (m).
double calcHertzEnergy(const ContactParameters& parameters, double radius, double depth);

/// Hunt-Crossley normal force f_n (N, >= 0) at depth x >= 0 (m), penetration rate xdot (m/s,
/// positive while penetrating) and effective radius R (m).
double calcNormalForce(const ContactParameters& parameters, double radius, double depth,
                       double depthRate);

/// Friction coefficient mu(v) at slip speed v >= 0 (m/s).
double calcFrictionCoefficient(const ContactParameters& parameters, double slipSpeed);

/// Friction force f_t = -mu(|v_t|) f_n v_t / |v_t| (N) opposing the slip velocity v_t (m/s),
/// expressed in the frame v_t is expressed in; zero when v_t = 0.
SimTK::Vec3 calcFrictionForce(const ContactParameters& parameters, double normalForce,
                              const SimTK::Vec3& slipVelocity);

}  // namespace graspsim::contact
