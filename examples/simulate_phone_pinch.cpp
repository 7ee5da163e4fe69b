// Simulates the thesis's phone pinch with the grasp approximation and reads the run's summary.
//
//   simulate_phone_pinch [DURATION_S]   (default: the scenario's own duration)

#include <graspsim/error.h>
#include <graspsim/scenario/scenario_file.h>
#include <graspsim/simulation/grasp_simulation.h>

#include <cstdlib>
#include <iostream>

int main(int argc, char** argv) {
    try {
        // Built-in scenarios are compiled into the library; a path to a YAML file works too.
        const graspsim::scenario::Scenario scenario = graspsim::scenario::loadScenario("phone-pinch");

        // Full contact until the grasp is good enough, then one friction-limited constraint.
        graspsim::simulation::SimulationOptions options;
        options.mode = graspsim::simulation::SimulationMode::Approx;
        if (argc > 1) options.duration = std::atof(argv[1]);  // s; 0 keeps the scenario's

        const graspsim::simulation::SimulationResult result = graspsim::simulation::runGraspSimulation(scenario, options);
        const graspsim::simulation::SimulationSummary& s = result.summary;
        std::cout << scenario.name << ": " << s.simTime << " s simulated, " << s.steps << " steps, "
                  << (s.held ? "held" : "not held") << "\n"
                  << "  approximation: ";
        if (s.engaged) {
            std::cout << "engaged at " << s.engageTime << " s with grasp quality " << s.qAtEngage << " N (threshold "
                      << s.qThreshold << " N)\n";
        } else {
            std::cout << "not engaged during the run\n";
        }
        std::cout << "  deepest contact " << s.maxPenetration * 1e3 << " mm, object moved "
                  << s.objectDisplacement * 1e3 << " mm after settling\n";
        return s.complete ? 0 : 3;
    } catch (const graspsim::Error& e) {
        std::cerr << e.what() << "\n";
        return 2;
    }
}
