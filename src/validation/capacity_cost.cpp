#include "graspsim/validation/capacity_cost.h"

#include "graspsim/capacity/grasp_capacity.h"
#include "graspsim/capacity/settled_grasps.h"
#include "graspsim/simulation/grasp_simulation.h"

#include "run_timing.h"

#include <cstdio>

namespace graspsim::validation {

namespace {

// The nine ramps of capacity --direction all, one after the other on one settled grasp (s).
double timeAllDirections(const scenario::Scenario& scenario, const simulation::SimulationOptions& options) {
    const double start = readWallClock();
    capacity::SettledGrasps grasps(scenario, options);
    for (const capacity::GraspCapacityRequest& request : capacity::makeAllDirectionRequests()) {
        capacity::measureGraspCapacityRamp(grasps, request);
    }
    return readWallClock() - start;
}

}  // namespace

CapacityCost measureCapacityCost(const scenario::Scenario& scenario, simulation::SimulationMode mode,
                                 simulation::IntegratorChoice integrator, bool allDirections) {
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
    if (allDirections) row.allWall = timeAllDirections(scenario, options);
    return row;
}

std::string formatCapacityCostTable(const std::vector<CapacityCost>& rows) {
    std::string text =
        "\nCapacity ramp against a 3 s simulation, same scene, mode and integrator, timed back to back (wall s;\n"
        "the ramp: -y force at the default rate until the drop or 4 s of load; the target is ramp / simulation <= 1;\n"
        "per direction: the nine ramps of --direction all on one thread, which share the settled grasp, over nine;\n"
        "on the implicit stepper, capacity's default, only: on CPodes a ramp that stalls takes half a minute)\n"
        "experiment   mode    integrator   ramp (sim s)   3 s simulation   ramp / simulation   per direction   / simulation\n";
    const double directions = static_cast<double>(capacity::makeAllDirectionRequests().size());
    for (const CapacityCost& r : rows) {
        const double perDirection = r.allWall / directions;
        char all[64] = "              -              -";
        if (r.allWall > 0) std::snprintf(all, sizeof all, "%15.3f   %12.2f", perDirection, r.simulationWall > 0 ? perDirection / r.simulationWall : 0.0);
        char line[240];
        std::snprintf(line, sizeof line, "%-12s %-7s %-12s %6.3f (%4.2f)   %14.3f   %17.2f %s%s\n", r.scenario.c_str(),
                      simulation::toString(r.mode).c_str(), simulation::toString(r.integrator).c_str(), r.rampWall,
                      r.rampSimTime, r.simulationWall, r.simulationWall > 0 ? r.rampWall / r.simulationWall : 0.0, all,
                      r.failure.empty() ? "" : "  (ramp stopped early)");
        text += line;
    }
    return text;
}

}  // namespace graspsim::validation
