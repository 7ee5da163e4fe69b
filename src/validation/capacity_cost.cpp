#include "graspsim/validation/capacity_cost.h"

#include "graspsim/capacity/grasp_capacity.h"
#include "graspsim/simulation/grasp_simulation.h"

#include "run_timing.h"

#include <cstdio>

namespace graspsim::validation {

CapacityCost measureCapacityCost(const scenario::Scenario& scenario, simulation::SimulationMode mode,
                                 simulation::IntegratorChoice integrator) {
    CapacityCost row;
    row.scenario = scenario.name;
    row.mode = mode;
    row.integrator = integrator;
    simulation::SimulationOptions options;
    options.mode = mode;
    options.integrator = integrator;
    options.duration = 3.0;
    double start = readWallClock();
    simulation::runGraspSimulation(scenario, options);
    row.simulationWall = readWallClock() - start;
    options.duration = 0;
    start = readWallClock();
    const capacity::GraspCapacity ramp = capacity::measureGraspCapacityRamp(scenario, options, capacity::GraspCapacityRequest{});
    row.rampWall = readWallClock() - start;
    row.rampSimTime = ramp.trace.samples.empty() ? ramp.start : ramp.trace.samples.back().time;
    row.failure = ramp.trace.failure;
    return row;
}

std::string formatCapacityCostTable(const std::vector<CapacityCost>& rows) {
    std::string text =
        "\nCapacity ramp against a 3 s simulation, same scene, mode and integrator, timed back to back (wall s;\n"
        "the ramp: -y force at the default rate until the drop or 4 s of load; the target is ramp / simulation <= 1)\n"
        "experiment   mode    integrator   ramp (sim s)   3 s simulation   ramp / simulation\n";
    for (const CapacityCost& r : rows) {
        char line[200];
        std::snprintf(line, sizeof line, "%-12s %-7s %-12s %6.3f (%4.2f)   %14.3f   %17.2f%s\n", r.scenario.c_str(),
                      simulation::toString(r.mode).c_str(), simulation::toString(r.integrator).c_str(), r.rampWall,
                      r.rampSimTime, r.simulationWall, r.simulationWall > 0 ? r.rampWall / r.simulationWall : 0.0,
                      r.failure.empty() ? "" : "  (ramp stopped early)");
        text += line;
    }
    return text;
}

}  // namespace graspsim::validation
