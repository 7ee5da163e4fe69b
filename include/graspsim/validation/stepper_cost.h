#pragma once
/// @file
/// `graspsim bench`'s stepper table (cost_table.h): full compliant contact per stepper, the
/// engaged approximation and the floor side by side, in one run, per simulated second (wall time
/// and the integrators' counts) and per integrator step (where the time goes).

#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/simulation_options.h"

#include <string>
#include <vector>

namespace graspsim::validation {

/// One row of the stepper table. Counts per simulated second; -1 where the run's integrator does
/// not report the count or the figure is not measured for this kind of run.
struct StepperCost {
    std::string scenario;
    std::string run;                     ///< e.g. "full, cpodes", "full, implicit", "approx, bushing", "floor"
    double wallPerSimSecond = 0;         ///< wall s per simulated s
    double stepsPerSimSecond = -1;       ///< successful integrator steps
    double evaluationsPerSimSecond = -1; ///< dynamics evaluations (realizations to Acceleration, all causes)
    double jacobiansPerSimSecond = -1;   ///< Jacobian (iteration matrix) builds
    double factorizationsPerSimSecond = -1;  ///< LU factorizations of it
    double newtonPerSimSecond = -1;      ///< Newton iterations (0 for a linearly implicit method)
    double restartsPerSimSecond = -1;    ///< integrator restarts (back to order 1 and a new Jacobian)
    // Per integrator step (µs). dynamics: evaluations per step x one evaluation timed at the run's
    // last state (contact included); contact: the same for the contact element's force alone;
    // linear solve: the stepper's own clock (matrix, LU, solves; -1 where the stepper does not
    // measure it: CPodes's Jacobian is difference quotients, part of "dynamics"); IK: measured in
    // the run; rest: step - dynamics - linear solve - IK (output samples, events, the stepper).
    double stepUs = -1, dynamicsUs = -1, contactUs = -1, linearSolveUs = -1, ikUs = -1, restUs = -1;
};

/// A full-contact run of `scenario` for `duration` simulated s on `integrator` at the scenario's
/// accuracy and step size, its per-step breakdown timed at its last state with `realizations`
/// evaluations per timing (that timing is not counted in the run's wall time).
StepperCost measureFullContactStepper(const scenario::Scenario& scenario, simulation::IntegratorChoice integrator,
                                      double duration, int realizations);

/// How long after the scenario's settle_time the held window of measureHeldFullContact starts (s):
/// the object has come to rest in the grasp.
constexpr double kHeldWarmUp = 1.0;

/// Full contact on a held grasp, the phase a fixed-step engine's benchmark times from a settled
/// keyframe (MuJoCo's, ../shared/peers/mujoco): a run of `scenario` on `integrator` to
/// settle_time + `warmUp` + `held`, timed (wall s per simulated s) over its last `held` s only.
/// Counts are not split by phase there: left at -1.
StepperCost measureHeldFullContact(const scenario::Scenario& scenario, simulation::IntegratorChoice integrator, double warmUp,
                                   double held);

/// The rows as a text table with a legend.
std::string formatStepperTable(const std::vector<StepperCost>& rows);

}  // namespace graspsim::validation
