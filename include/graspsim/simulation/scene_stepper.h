#pragma once
/// @file
/// The integrator of a compliant-contact grasp run, as SimulationOptions::integrator chooses it:
/// Simbody's CPodes, the CVODE reference, or the linearly implicit stepper (error-controlled or
/// fixed steps) with the analytic force Jacobians of the scene's joints, contacts and engaged
/// attachment. One place for `simulate`, `capacity` and everything else that steps a scene
/// (rigid contact has its own stepper, rigid_stepping.h).

#include "graspsim/error.h"
#include "graspsim/integration/fixed_step_too_long_error.h"
#include "graspsim/integration/force_jacobian.h"
#include "graspsim/integration/stepper.h"
#include "graspsim/simulation/simulation_options.h"

#include <memory>
#include <vector>

namespace graspsim::simulation {

class GraspExperiment;

/// A stepper with what it needs kept alive: the linearly implicit one's force Jacobians.
struct SceneStepper {
    std::vector<std::unique_ptr<integration::ForceJacobianContributor>> jacobians;
    std::unique_ptr<integration::Stepper> stepper;
};

/// The stepper of `options.integrator` for `experiment`'s System, at `options.accuracy` (the
/// scenario's if 0) and, for the linearly implicit one, steps up to findStepSize's (or at it, with
/// implicit-fixed). Not initialized. The experiment must outlive it.
SceneStepper makeSceneStepper(const GraspExperiment& experiment, const SimulationOptions& options);

/// The stepper's refusal of a fixed step (`--integrator implicit-fixed`) in the run's own terms:
/// where the step came from (findStepSize), its value,
/// the time, and what to use instead (a shorter step or error control). For the caller to throw;
/// a run that cannot be trusted gives no result.
InputError describeFixedStepTooLong(const scenario::Scenario& scenario, const SimulationOptions& options,
                                    const integration::FixedStepTooLongError& error);

}  // namespace graspsim::simulation
