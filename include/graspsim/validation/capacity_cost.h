#pragma once
/// @file
/// `graspsim bench`'s capacity table: what one holding-capacity ramp (`graspsim capacity`, the
/// default −y force at the default rate) costs against one 3 s simulation of the same scene in the
/// same mode and on the same integrator, timed back to back in one process (issue 17's target:
/// a ramp costs at most one 3 s simulation), and what a ramp costs as one direction of
/// `capacity --direction all`, whose nine ramps share the settled grasp (capacity/settled_grasps.h).

#include "graspsim/scenario/scenario.h"
#include "graspsim/simulation/simulation_options.h"

#include <string>
#include <vector>

namespace graspsim::validation {

/// One row: a scenario, a mode and an integrator.
struct CapacityCost {
    std::string scenario;
    simulation::SimulationMode mode = simulation::SimulationMode::Full;
    simulation::IntegratorChoice integrator = simulation::IntegratorChoice::SimbodyCpodes;
    double rampWall = 0;         ///< s, the whole ramp (scene built, settled, loaded to its drop or end)
    double rampSimTime = 0;      ///< simulated s of the ramp (to its drop or its end)
    double simulationWall = 0;   ///< s, the whole 3 s simulation (scene built, run)
    /// s, the nine ramps of `capacity --direction all` (six forces, three torques) on one thread,
    /// sharing one settled grasp; over their count it is a direction's share. 0: not timed.
    double allWall = 0;
    std::string failure;         ///< why the ramp stopped early, or empty
};

/// Times the ramp and the 3 s simulation of `scenario` in `mode` on `integrator`, back to back,
/// and with `allDirections` the nine ramps too.
CapacityCost measureCapacityCost(const scenario::Scenario& scenario, simulation::SimulationMode mode,
                                 simulation::IntegratorChoice integrator, bool allDirections = false);

/// The rows as a text table (ramp / simulation: the ratio the target bounds by 1).
std::string formatCapacityCostTable(const std::vector<CapacityCost>& rows);

}  // namespace graspsim::validation
