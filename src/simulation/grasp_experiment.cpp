#include "graspsim/simulation/grasp_experiment.h"

#include <optional>

namespace graspsim::simulation {

namespace {

std::optional<ApproxOptions> resolveForMode(const scenario::Scenario& scenario, const SimulationOptions& options) {
    if (options.mode != SimulationMode::Approx) return std::nullopt;
    return resolveApproxOptions(options.approx, scenario.approximation);
}

}  // namespace

GraspExperiment::GraspExperiment(const scenario::Scenario& scenario, const SimulationOptions& options) {
    const std::optional<ApproxOptions> approx = resolveForMode(scenario, options);
    scene_ = std::make_unique<GraspScene>(scenario, options);
    if (approx) approximation_ = std::make_unique<GraspApproximation>(*scene_, *approx);
    loads_ = std::make_unique<ObjectLoads>(scene_->updModel(), scene_->getObject(), scenario, options);
    if (approximation_) approximation_->setObjectLoads(*loads_);
    scene_->updModel().realizeTopology();
}

SimTK::State GraspExperiment::makeInitialState() {
    SimTK::State state = scene_->makeInitialState();
    if (approximation_) approximation_->getAttachment().release(state);
    return state;
}

}  // namespace graspsim::simulation
