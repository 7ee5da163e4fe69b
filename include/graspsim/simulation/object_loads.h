#pragma once
/// @file
/// The external loads on the object of one run: the scenario's perturbation named by
/// SimulationOptions::perturbation and the load of SimulationOptions::loadRamp. They are the last
/// force elements of a run's system (grasp_experiment.h): Simbody sums the forces on a body in the
/// order the elements were added, and every run, full or approx, adds them after the hand's and
/// the approximation's.

#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/perturbation_force.h"
#include "graspsim/simulation/ramp_load.h"
#include "graspsim/simulation/simulation_options.h"
#include "graspsim/system/multibody_model.h"

#include "graspsim/simbody.h"

#include <memory>

namespace graspsim::simulation {

/// See the file comment. Neither copyable nor movable (the force elements refer into it).
class ObjectLoads {
public:
    /// Adds the loads `options` asks for to `model`'s forces, on `object`.
    /// @throws graspsim::InputError for a perturbation the scenario does not define.
    ObjectLoads(system::MultibodyModel& model, const SimTK::MobilizedBody& object, const scenario::Scenario& scenario,
                const SimulationOptions& options);
    ObjectLoads(const ObjectLoads&) = delete;
    ObjectLoads& operator=(const ObjectLoads&) = delete;

    /// The perturbation of this run, or nullptr.
    const PerturbationForce* getPerturbation() const { return perturbation_.get(); }
    /// The load of SimulationOptions::loadRamp, or nullptr.
    const RampLoad* getLoadRamp() const { return loadRamp_.get(); }
    RampLoad* updLoadRamp() { return loadRamp_.get(); }
    /// The loads' wrench on the object at time t (s), moment about its centre of mass first
    /// (N m, N; in G): both depend on time only. Zero without loads.
    SimTK::SpatialVec findWrenchAt(double t) const;

private:
    std::unique_ptr<PerturbationForce> perturbation_;
    std::unique_ptr<RampLoad> loadRamp_;
};

}  // namespace graspsim::simulation
