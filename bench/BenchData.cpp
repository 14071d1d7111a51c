// Loading a data set of 10 batches × 6,300 rows (issue: "well under a second").
#include "data/BatchReader.h"
#include "data/BatchWriter.h"

#include <benchmark/benchmark.h>
#include <filesystem>
#include <fstream>
#include <random>

namespace {

std::string makeDataSetFolder() {
    namespace fs = std::filesystem;
    const fs::path dir = fs::temp_directory_path() / "drytwin_bench_data";
    fs::create_directories(dir);
    std::mt19937 rng(1);
    std::normal_distribution<double> n(0, 1);
    for (int b = 0; b < 10; ++b) {
        std::string s = "# batch: B" + std::to_string(b) + "\n";
        s += "time_s,T_hot_sp_C,T_hot_C,air_speed_m_s,feed_kg_h,X_in_pct,T_in_C,T_amb_C,RH_amb_pct,X_hdt_pct,"
             "T_hdt_C,X_out_pct,T_out_C\n";
        for (int r = 0; r < 6300; ++r) {
            const double v[] = {double(r),          170 + n(rng),      169 + n(rng), 16 + 0.1 * n(rng),
                                6200 + 50 * n(rng), 22 + 0.3 * n(rng), 25 + n(rng),  24 + n(rng),
                                55 + n(rng),        14 + 0.1 * n(rng), 58 + n(rng),  12.8 + 0.1 * n(rng),
                                55 + n(rng)};
            for (int c = 0; c < 13; ++c) {
                s += (c ? "," : "") + drytwin::data::formatNumber(v[c]);
            }
            s += "\n";
        }
        std::ofstream(dir / ("B" + std::to_string(b) + ".csv")) << s;
    }
    return dir.string();
}

void BM_LoadTenBatches(benchmark::State& state) {
    static const std::string dir = makeDataSetFolder();
    for (auto _ : state) {
        auto r = drytwin::data::loadDataSet(dir);
        if (!r.ok()) {
            state.SkipWithError("load failed");
        }
        benchmark::DoNotOptimize(r.dataSet.totalRows());
    }
}
BENCHMARK(BM_LoadTenBatches)->Unit(benchmark::kMillisecond);

} // namespace

BENCHMARK_MAIN();
