#pragma once
/// @file
/// One run's system, assembled in order: the scene of full contact (grasp_scene.h), in
/// SimulationMode::Approx the approximation on top of it (grasp_approximation.h), then the loads
/// on the object (object_loads.h), and the topology realized once all are in. The order is part of
/// the result: Simbody sums the forces on a body in the order the elements were added, so every
/// run adds the same elements in the same order, and the outputs repeat bit for bit.

#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/grasp_approximation.h"
#include "graspsim/simulation/grasp_scene.h"
#include "graspsim/simulation/object_loads.h"
#include "graspsim/simulation/simulation_options.h"

#include "graspsim/simbody.h"

#include <memory>

namespace graspsim::simulation {

/// See the file comment. Neither copyable nor movable (Simbody elements refer into it).
class GraspExperiment {
public:
    /// Resolves the approximation's options (resolveApproxOptions) before anything is built.
    /// @throws graspsim::InputError for options the scenario cannot take.
    GraspExperiment(const scenario::Scenario& scenario, const SimulationOptions& options);
    GraspExperiment(const GraspExperiment&) = delete;
    GraspExperiment& operator=(const GraspExperiment&) = delete;

    const GraspScene& getScene() const { return *scene_; }
    GraspScene& updScene() { return *scene_; }
    /// The approximation in approx mode, nullptr in full mode.
    const GraspApproximation* getApproximation() const { return approximation_.get(); }
    /// Its grasp switch, nullptr in full mode.
    const GraspSwitch* findSwitch() const { return approximation_ ? &approximation_->getSwitch() : nullptr; }
    const ObjectLoads& getLoads() const { return *loads_; }
    ObjectLoads& updLoads() { return *loads_; }

    /// The scene's state at t = 0 (GraspScene::makeInitialState, which checks it) with the
    /// approximation's attachment released: contact holds the object until the switch engages.
    SimTK::State makeInitialState();

private:
    std::unique_ptr<GraspScene> scene_;
    std::unique_ptr<GraspApproximation> approximation_;  // destroyed before the scene's System
    std::unique_ptr<ObjectLoads> loads_;
};

}  // namespace graspsim::simulation
