// The virtual plant writing the bundled demo (10 batches × 6,300 samples). Issue #22: the
// distributed demo in at most 60 s on this 2-core machine; the lumped one for comparison.
#include "plant/VirtualPlant.h"

#include <benchmark/benchmark.h>

namespace {

void BM_GenerateDemo(benchmark::State& state) {
    const auto kind = static_cast<drytwin::plant::PlantKind>(state.range(0));
    const auto options = drytwin::plant::PlantOptions::demo(2025, kind);
    for (auto _ : state) {
        auto r = drytwin::plant::runPlant(options);
        if (!r) {
            state.SkipWithError(r.error().message().c_str());
            break;
        }
        benchmark::DoNotOptimize(r->batches.back().xOutDb.data());
    }
    state.counters["samples"] = 63000;
    state.SetLabel(kind == drytwin::plant::PlantKind::Distributed ? "distributed, realistic sensors"
                                                                  : "lumped, built-in sensors");
}
BENCHMARK(BM_GenerateDemo)
    ->Arg(static_cast<int>(drytwin::plant::PlantKind::Lumped))
    ->Arg(static_cast<int>(drytwin::plant::PlantKind::Distributed))
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

} // namespace

BENCHMARK_MAIN();
