// Per-step cost of full-contact grasp simulation, the thesis's Table 5.1 quantities: IK and
// dynamics apart, and simulated seconds per wall-clock second.
// Run: build/bin/graspsim_benchmarks --benchmark_filter=FullContact

#include "graspsim/scenario/scenario_file.h"
#include "graspsim/simulation/grasp_simulation.h"

#include <benchmark/benchmark.h>

using namespace graspsim;

namespace {

void BM_FullContactGrasp(benchmark::State& state, const char* scenarioName) {
    const scenario::Scenario s = scenario::findBuiltinScenario(scenarioName);
    simulation::SimulationOptions options;
    options.duration = 1.0;  // holding after the release at 0.5 s
    simulation::SimulationSummary last;
    for (auto _ : state) last = simulation::runGraspSimulation(s, options).summary;
    state.counters["step_us"] = last.meanStepUs;
    state.counters["ik_us_per_step"] = last.ikUsPerStep;
    state.counters["dynamics_us_per_step"] = last.dynamicsUsPerStep;
    state.counters["steps"] = static_cast<double>(last.steps);
    state.counters["sim_s_per_wall_s"] = last.simTime / last.wallTime;
}
BENCHMARK_CAPTURE(BM_FullContactGrasp, ball_clutch, "ball-clutch")->Unit(benchmark::kMillisecond)->Iterations(2);
BENCHMARK_CAPTURE(BM_FullContactGrasp, phone_pinch, "phone-pinch")->Unit(benchmark::kMillisecond)->Iterations(2);

}  // namespace
