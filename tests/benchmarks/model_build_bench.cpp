// Model building cost: the anthropometric arm from subject to a realized Simbody system.
// Issue target: build + realize under 50 ms for the arm. Run: build/bin/graspsim_benchmarks

#include "graspsim/model/body_model.h"
#include "graspsim/model/urdf_export.h"
#include "graspsim/model/urdf_import.h"
#include "graspsim/system/multibody_model.h"

#include <benchmark/benchmark.h>

using namespace graspsim;

namespace {

model::BuildOptions optionsFor(int body) {
    model::BuildOptions o;
    o.body = body == 0 ? model::BodyKind::Arm : model::BodyKind::Humanoid;
    return o;
}

void BM_BuildDescription(benchmark::State& state) {
    const model::BuildOptions o = optionsFor(static_cast<int>(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(model::buildBodyModel(o));
}
BENCHMARK(BM_BuildDescription)->Arg(0)->Arg(1)->ArgName("humanoid")->Unit(benchmark::kMillisecond);

// Description -> Simbody system -> realizeTopology -> realize(Dynamics) at the default state.
void BM_BuildAndRealize(benchmark::State& state) {
    const model::BuildOptions o = optionsFor(static_cast<int>(state.range(0)));
    for (auto _ : state) {
        const model::ModelDescription description = model::buildBodyModel(o);
        system::MultibodyModel multibody(description);
        SimTK::State s = multibody.realizeTopology();
        multibody.getSystem().realize(s, SimTK::Stage::Dynamics);
        benchmark::DoNotOptimize(s.getSystemStage());
    }
}
BENCHMARK(BM_BuildAndRealize)->Arg(0)->Arg(1)->ArgName("humanoid")->Unit(benchmark::kMillisecond);

void BM_UrdfRoundTrip(benchmark::State& state) {
    const model::ModelDescription arm = model::buildBodyModel(optionsFor(0));
    for (auto _ : state) benchmark::DoNotOptimize(model::readUrdf(model::writeUrdf(arm), "bench"));
}
BENCHMARK(BM_UrdfRoundTrip)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
