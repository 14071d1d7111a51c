// The PBM over 10 batches × 6,300 samples (issue: under 0.5 s on this 2-core machine).
#include "physics/LineSimulator.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"

#include <benchmark/benchmark.h>

namespace {

const std::vector<drytwin::physics::LineInputs>& demoInputs() {
    static const auto inputs = [] {
        // The lumped demo: no missing cells, and the numbers stay comparable with earlier versions.
        auto plant = drytwin::plant::runPlant(
            drytwin::plant::PlantOptions::demo(2025, drytwin::plant::PlantKind::Lumped));
        std::vector<drytwin::physics::LineInputs> v;
        for (const auto& b : plant->batches) {
            v.push_back(drytwin::plant::toLineInputs(b));
        }
        return v;
    }();
    return inputs;
}

void BM_PbmTenBatches(benchmark::State& state) {
    const auto& inputs = demoInputs();
    const drytwin::properties::ParameterSet p;
    for (auto _ : state) {
        auto r = drytwin::physics::simulateBatches(inputs, p, {}, static_cast<unsigned>(state.range(0)));
        if (!r) {
            state.SkipWithError(r.error().message().c_str());
        }
        benchmark::DoNotOptimize(r->front().xOutDb.data());
    }
    state.counters["samples"] = 63000;
}
BENCHMARK(BM_PbmTenBatches)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();

void BM_PbmCalibrationSubset(benchmark::State& state) {
    // The paper's calibration subset: 300 rows, 1 in 10, with sensitivities to h_HDT and k_HDT.
    const auto& in = demoInputs().front();
    std::vector<std::size_t> rows;
    for (std::size_t k = 0; k < 3000; k += 10) {
        rows.push_back(k);
    }
    drytwin::physics::SimulationOptions o;
    if (state.range(0) == 1) {
        o.sensitivities = {drytwin::properties::Param::h_HDT, drytwin::properties::Param::k_HDT};
    }
    const drytwin::properties::ParameterSet p;
    for (auto _ : state) {
        auto r = drytwin::physics::simulateLine(in, p, o, rows);
        benchmark::DoNotOptimize(r->xOutDb.data());
    }
}
BENCHMARK(BM_PbmCalibrationSubset)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
