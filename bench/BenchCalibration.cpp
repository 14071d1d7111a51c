// Calibration on the paper's subset (300 rows): 2 parameters under 5 s, 4 under 30 s (issue).
#include "calibration/Calibration.h"
#include "plant/PlantExport.h"
#include "plant/VirtualPlant.h"

#include <benchmark/benchmark.h>

namespace {

const std::vector<drytwin::data::SiBatch>& demoData() {
    static const auto data = [] {
        const auto o = drytwin::plant::PlantOptions::demo(2025);
        auto r = drytwin::plant::runPlant(o);
        return drytwin::plant::toSiBatches(*r, o.seed);
    }();
    return data;
}

void BM_Calibrate(benchmark::State& state) {
    using drytwin::properties::Param;
    drytwin::calibration::CalibrationOptions o;
    if (state.range(0) == 4) {
        o.freeParameters = {Param::h_HDT, Param::k_HDT, Param::beta_top, Param::kappa};
    }
    int evaluations = 0;
    const auto& data = demoData(); // generated once, outside the timing
    for (auto _ : state) {
        auto r = drytwin::calibration::calibrate(data, drytwin::properties::ParameterSet{}, o);
        if (!r) {
            state.SkipWithError(r.error().message().c_str());
            break;
        }
        evaluations = r->evaluations;
    }
    state.counters["evaluations"] = evaluations;
}
BENCHMARK(BM_Calibrate)->Arg(2)->Arg(4)->Unit(benchmark::kSecond)->Iterations(1);

} // namespace

BENCHMARK_MAIN();
