#pragma once
/// @file
/// The analytic two-finger squeeze as a capacity case: a box of mass m on a Slider along y of
/// Ground, squeezed along x between two spheres on Sliders, each pushed with N, no gravity. The
/// load pulls the box along y. Coulomb friction (mu_s = mu_d = mu): the box stays for F < 2 mu N and
/// slides with a = (F - 2 mu N) / m above it, so its holding capacity is 2 mu N.
///
/// The same scene as validation's two-finger friction case, with its parameters free, so the
/// capacity protocol can be checked against 2 mu N over a grid of mu and N.

#include "graspsim/capacity/capacity_protocol.h"

namespace graspsim::capacity {

/// How compliant contact is integrated: Simbody's Runge-Kutta-Merson at 1e-7 (the reference), or
/// graspsim's linearly implicit stepper (ROS2) at a scenario's defaults (accuracy 1e-3, steps up
/// to 5 ms) with the contacts' analytic Jacobian, as `graspsim simulate --integrator implicit`.
enum class SqueezeIntegrator { Reference, LinearlyImplicit };

/// Parameters of the squeeze.
struct SqueezeCase {
    double mu = 0.5;             ///< Coulomb coefficient, static = dynamic
    double press = 10;           ///< N, each sphere
    double boxMass = 1;          ///< kg
    double transitionVelocity = 1e-3;  ///< m/s, compliant friction's transition speed
    bool rigid = false;          ///< rigid (Coulomb, PGS time stepper) or compliant (Hunt-Crossley) contact
    SqueezeIntegrator integrator = SqueezeIntegrator::Reference;  ///< compliant contact only
    /// s, the linearly implicit stepper's longest step (a scenario's default, 5 ms; the slide
    /// times at this cap: docs/capacity.md, "Constant loads above capacity").
    double implicitStepCap = 5e-3;
    /// The Coulomb holding capacity, 2 mu N (N).
    double findLimit() const { return 2 * mu * press; }
};

/// A factory of loaded squeeze runs for runRamp / runBisection. The load must be a force along y;
/// slip is the box's travel along its slider.
LoadedRunFactory makeSqueezeRuns(const SqueezeCase& squeeze);

}  // namespace graspsim::capacity
