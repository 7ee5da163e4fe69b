#pragma once
/// @file
/// Grasp scenes settled once and shared by the loads measured on them.
///
/// Every load of a capacity measurement starts from the same settled grasp: up to the load's start
/// (findLoadStart) the scene is the same whatever the load's direction or size, since the load is
/// zero before it. SettledGrasps simulates that stretch (the approach, the closing and the settle,
/// about 1.1 s of a scene) once per scene, to 1 ms before the load's start, and hands each run a
/// copy of the settled State, with the run's load set on the scene's simulation::RampLoad and a
/// fresh stepper started from it (which then steps into the load, so a step load is seen to begin,
/// as in a run of its own). The directions of `capacity --direction all`, the loads of a bisection
/// and the constant loads of `validate` then pay the settle once per thread instead of once per run.
///
/// Sharing is exact: every quantity a run changes lives in its SimTK::State (the switch's record,
/// the attachment's settings, the controller's targets), and the only thing set outside it, the
/// load, is set again for each run. A run started from a shared scene gives the same figures bit
/// for bit whichever runs used the scene before it. It differs from a run that steps through to the
/// load without stopping only by the stepper's restart 1 ms before it (the measured difference is in
/// docs/capacity.md, "Sharing the settled grasp").

#include "graspsim/capacity/capacity_protocol.h"
#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/simulation_options.h"

#include <memory>
#include <mutex>
#include <vector>

namespace graspsim::capacity {

/// See the file comment. Safe to use from several threads at once: each run leases a scene of its
/// own, and a scene is settled only when no idle one is there to lease.
class SettledGrasps {
public:
    /// How runs start (both are kept: the second is the first's cross-check).
    enum class Start {
        Shared,  ///< from a settled scene's State, copied (the default)
        Own,     ///< each run builds and settles a scene of its own, stepping through the load's start
    };

    /// Refers to `scenario`, which must outlive this object and every run it makes.
    /// options.loadRamp and options.perturbation are replaced by each run's load.
    SettledGrasps(const scenario::Scenario& scenario, const simulation::SimulationOptions& options, Start start = Start::Shared);
    ~SettledGrasps();
    SettledGrasps(const SettledGrasps&) = delete;
    SettledGrasps& operator=(const SettledGrasps&) = delete;

    /// A run of `load` for runLoadedScene and the protocols (the factory of makeGraspRuns). It must
    /// not outlive this object. In approx mode it throws graspsim::NumericalError, at the load's
    /// start, if the approximation is not engaged there.
    /// @throws graspsim::InputError for options the scenario cannot take (GraspExperiment).
    std::unique_ptr<LoadedRun> makeRun(const simulation::LoadRampSpec& load);

    const scenario::Scenario& getScenario() const { return scenario_; }
    const simulation::SimulationOptions& getOptions() const { return options_; }
    /// How many scenes were settled so far: one per run running at once, with Start::Shared.
    int countSettled() const;

private:
    friend class GraspRun;
    struct Scene;  // a GraspExperiment and its settled State (defined in the source)
    std::unique_ptr<Scene> leaseScene(double start);
    void returnScene(std::unique_ptr<Scene> scene);
    void countSettle();

    const scenario::Scenario& scenario_;
    simulation::SimulationOptions options_;
    Start startKind_;
    mutable std::mutex mutex_;
    std::vector<std::unique_ptr<Scene>> idle_;
    int settled_ = 0;
};

/// The factory of `grasps`' runs, for runRamp, runBisection and runOverload. `grasps` must outlive it.
LoadedRunFactory makeGraspRuns(SettledGrasps& grasps);

}  // namespace graspsim::capacity
