#pragma once
/// @file
/// The analytic cases of `graspsim validate`: small scenes whose answer is known in closed
/// form, run through the same components as the grasp scenes.
///
/// - Two-finger friction (thesis eq. 2.17-2.18 reduced to two contacts): a box of mass m on a
///   Slider along y of Ground, squeezed along x between two spheres on Sliders, each pushed with
///   N; a pull F along y. Coulomb: the box stays for F < 2 mu N and slides with
///   a = (F - 2 mu N) / m above it. mu_s = mu_d, so the limit is sharp. Compliant contact
///   (CompliantContactForce, Runge-Kutta-Merson) and rigid contact (RigidContact,
///   SemiExplicitEulerTimeStepper with PGS). Compliant (regularized) friction has no true
///   stiction: below the limit the box creeps at v = v_t F / (2 mu N), which is its bound.
/// - A simple pendulum (point mass on a massless rod, Pin joint, 60 degree amplitude): period
///   against T = 4 sqrt(L/g) K(sin(theta0/2)), with Simbody's Runge-Kutta-Merson integrator.

#include "graspsim/validation/validation_checks.h"

#include <vector>

namespace graspsim::validation {

/// Runs the cases and returns one check each (run name "analytic").
std::vector<ValidationCheck> runAnalyticCases();

/// Acceleration (m/s^2, from the speed change over the last `window` s) and displacement (m) of
/// the squeezed box after `duration` s, for pull `pull` (N). `rigid` picks the contact model.
struct SqueezeOutcome {
    double acceleration = 0;
    double displacement = 0;
};
SqueezeOutcome runSqueeze(bool rigid, double pull, double duration);

/// Parameters of the two-finger case.
constexpr double kSqueezeMu = 0.5;       ///< Coulomb coefficient, static = dynamic
constexpr double kSqueezePress = 10;     ///< N, each sphere
constexpr double kSqueezeBoxMass = 1;    ///< kg
constexpr double kSqueezeTransition = 1e-3;  ///< m/s, compliant friction's transition speed

/// Measured pendulum period (s) from successive upward zero crossings of the angle, and the exact one.
struct PendulumOutcome {
    double measured = 0;
    double exact = 0;
};
PendulumOutcome runPendulum(double amplitude, double accuracy);

}  // namespace graspsim::validation
