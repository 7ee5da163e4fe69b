#include "graspsim/simulation/scene_stepper.h"

#include "graspsim/contact/compliant_contact_jacobian.h"
#include "graspsim/integration/cvode_integrator.h"
#include "graspsim/integration/joint_impedance_jacobian.h"
#include "graspsim/integration/linearly_implicit_stepper.h"
#include "graspsim/integration/simbody_stepper.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/grasp_experiment.h"

#include <algorithm>
#include <cstdio>

namespace graspsim::simulation {

namespace {

// The linearly implicit stepper (ROS2) with the joints' impedance and the compliant contacts
// implicit; steps up to `stepSize`, chosen by error control at `accuracy` (0: fixed steps).
SceneStepper makeLinearlyImplicitStepper(const GraspExperiment& experiment, double stepSize, double accuracy) {
    const GraspScene& scene = experiment.getScene();
    const GraspApproximation* approximation = experiment.getApproximation();
    SceneStepper made;
    const SimTK::SimbodyMatterSubsystem& matter = scene.getModel().getMatter();
    made.jacobians.push_back(std::make_unique<integration::JointImpedanceJacobian>(
        matter, scene.getModel().getForces(), scene.findJointImpedances()));
    made.jacobians.push_back(std::make_unique<contact::CompliantContactJacobian>(matter, scene.getCompliantContacts()));
    if (approximation) {
        auto attachment = approximation->getAttachment().makeForceJacobian(matter, scene.getPalm(), scene.getObject());
        if (attachment) made.jacobians.push_back(std::move(attachment));
    }
    std::vector<const integration::ForceJacobianContributor*> contributors;
    for (const auto& j : made.jacobians) contributors.push_back(j.get());
    integration::LinearlyImplicitOptions implicit;
    implicit.stepSize = stepSize;
    implicit.accuracy = accuracy;
    // Its steps go on past output samples (dense output), but not past the loads' jumps.
    if (const PerturbationForce* p = experiment.getLoads().getPerturbation()) implicit.landingTimes = {p->getStartTime(), p->getEndTime()};
    if (const RampLoad* r = experiment.getLoads().getLoadRamp()) implicit.landingTimes.push_back(r->getSpec().start);
    // Events handled at an interpolated instant hand Report-stage changes (the PD ramp, which starts
    // one IK interval after its update) on to the step's end; that needs steps shorter than it.
    implicit.interpolate = stepSize <= scene.getScenario().controller.ikInterval;
    made.stepper = std::make_unique<integration::LinearlyImplicitStepper>(scene.getSystem(), contributors, implicit);
    return made;
}

}  // namespace

// The accuracy is a relative tolerance for both BDF integrators; CVODE takes its atol and
// constraint tolerance from it as Simbody's integrators do (cvode_integrator.h).
SceneStepper makeSceneStepper(const GraspExperiment& experiment, const SimulationOptions& options) {
    const GraspScene& scene = experiment.getScene();
    const scenario::SimulationSpec& spec = scene.getScenario().simulation;
    const double accuracy = options.accuracy > 0 ? options.accuracy : spec.accuracy;
    const IntegratorChoice integrator = resolveIntegrator(scene.getScenario(), options);
    if (integrator == IntegratorChoice::LinearlyImplicit) {
        double longest = findStepSize(scene.getScenario(), options).step;
        // Its error estimate watches q and u, not the anchors' states, which it integrates
        // explicitly: past this bound they blow up unseen (checkIntegratorChoice's fixed-step limit).
        if (scene.getScenario().friction.model == contact::FrictionModel::Anchor) {
            longest = std::min(longest, kAnchorStabilityLimit * scene.getScenario().friction.anchor.relaxationTime);
        }
        return makeLinearlyImplicitStepper(experiment, longest, accuracy);
    }
    if (integrator == IntegratorChoice::LinearlyImplicitFixed) {
        return makeLinearlyImplicitStepper(experiment, findStepSize(scene.getScenario(), options).step, 0.0);
    }
    SceneStepper made;
    if (integrator == IntegratorChoice::SimbodyCpodes) {
        made.stepper = std::make_unique<integration::SimbodyCpodesStepper>(scene.getSystem(), accuracy);
        return made;
    }
    integration::CvodeOptions cvode;
    cvode.relativeTolerance = accuracy;
    made.stepper = std::make_unique<integration::CvodeIntegrator>(scene.getSystem(), cvode);
    return made;
}

InputError describeFixedStepTooLong(const scenario::Scenario& scenario, const SimulationOptions& options,
                                    const integration::FixedStepTooLongError& error) {
    // The value as given: the steps themselves are the intervals between samples cut into equal
    // steps no longer than it (error.getStepSize()).
    const StepSizeChoice given = findStepSize(scenario, options);
    char text[700];
    std::snprintf(text, sizeof text,
                  "%s: %g s is not accepted with --integrator implicit-fixed for scenario '%s': the step from t = %.4f s "
                  "has an error estimate %.3g times the state's own scale (its second- and first-order solutions "
                  "disagree entirely: the step is unstable or far too long here); use a shorter --step-size (0.001 "
                  "holds the shipped scenes) or --integrator implicit",
                  given.source.c_str(), given.step, scenario.name.c_str(), error.getTime(), error.getEstimate());
    return InputError(text);
}

}  // namespace graspsim::simulation
