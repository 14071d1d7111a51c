// A historian export of a month at 1 s (issue #25): 2,592,000 rows, 15 columns, ISO time stamps,
// ';' and decimal commas, tag names, a line stop every 8 h. Writes it once (or reuses it), then
// loads it as drytwin does and prints the time, the peak memory and the runs found.
//   bench_plant_file [DAYS=30] [FILE=/tmp/drytwin-month.csv]
// Goal: a month in at most 30 s and 1 GB on this 2-core machine.
#include "data/BatchReader.h"
#include "data/ColumnMapping.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <string>
#include <sys/resource.h>

using namespace drytwin;

namespace {

const char* kMapping = R"({
  "time_s": {"header": "Timestamp", "format": "iso8601"},
  "T_hot_sp_C": "HDT_TIC101.SP", "T_hot_C": "HDT_TT101.PV", "air_speed_m_s": "HDT_ST102.PV",
  "feed_kg_h": "FEED_WT201.PV", "X_in_pct": "NIR_XIN.PV", "T_in_C": "FEED_TT202.PV",
  "T_amb_C": "HALL_TT301.PV", "RH_amb_pct": "HALL_MT302.PV", "X_hdt_pct": "NIR_XHDT.PV",
  "T_hdt_C": "HDT_TT103.PV", "X_out_pct": "NIR_XOUT.PV", "T_out_C": "WIN_TT401.PV"
})";

void writeMonth(const std::string& path, int days) {
    std::FILE* f = std::fopen(path.c_str(), "w");
    std::fprintf(f,
                 "Timestamp;HDT_TIC101.SP;HDT_TT101.PV;HDT_ST102.PV;FEED_WT201.PV;NIR_XIN.PV;FEED_TT202.PV;"
                 "HALL_TT301.PV;HALL_MT302.PV;NIR_XHDT.PV;HDT_TT103.PV;NIR_XOUT.PV;WIN_TT401.PV;"
                 "STEAM_PT501.PV;FAN_IT601.PV\n");
    const time_t start = 1748736000; // 2025-06-01T00:00:00Z
    char line[512];
    for (long i = 0; i < static_cast<long>(days) * 86400; ++i) {
        const time_t t = start + i;
        std::tm tm{};
        gmtime_r(&t, &tm);
        const bool stopped = (i % 28800) >= 27600; // 20 min stop every 8 h
        const double s = std::sin(i / 600.0);
        int n = std::snprintf(
            line, sizeof line,
            "%04d-%02d-%02dT%02d:%02d:%02d;%.1f;%.1f;%.2f;%.0f;%.2f;%.1f;%.1f;%.1f;%.2f;%.1f;"
            "%.2f;%.1f;%.2f;%.1f\n",
            tm.tm_year + 1900, tm.tm_mon + 1, tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec, 170 + 5 * s,
            169 + 5 * s, 16 + 0.1 * s, stopped ? 0.0 : 6200 + 100 * s, 22 + 0.5 * s, 25.0, 22 + 3 * s,
            50 + 5 * s, 14 + 0.3 * s, 60 + s, 13 + 0.2 * s, 55 + s, 6.1 + 0.1 * s, 80 + s);
        for (int k = 19; k < n; ++k) {
            if (line[k] == '.') {
                line[k] = ','; // decimal commas
            }
        }
        std::fwrite(line, 1, static_cast<std::size_t>(n), f);
    }
    std::fclose(f);
}

} // namespace

int main(int argc, char** argv) {
    const int days = argc > 1 ? std::atoi(argv[1]) : 30;
    const std::string path = argc > 2 ? argv[2] : "/tmp/drytwin-month.csv";
    if (!std::filesystem::exists(path)) {
        const auto t0 = std::chrono::steady_clock::now();
        writeMonth(path, days);
        std::printf("wrote %s (%d days, %.0f MB) in %.1f s\n", path.c_str(), days,
                    std::filesystem::file_size(path) / 1e6,
                    std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    }
    const std::string mappingPath = path + ".mapping.json";
    std::FILE* m = std::fopen(mappingPath.c_str(), "w");
    std::fputs(kMapping, m);
    std::fclose(m);
    auto mapping = data::readColumnMapping(mappingPath);
    if (!mapping) {
        std::fprintf(stderr, "%s\n", mapping.error().message().c_str());
        return 3;
    }
    data::ReadOptions o;
    o.mapping = *mapping;
    int lastTenth = -1;
    const auto t0 = std::chrono::steady_clock::now();
    auto r = data::loadDataSet(path, o, [&](const ProgressInfo& p) {
        const int tenth = static_cast<int>(p.fraction * 10);
        if (tenth != lastTenth) {
            lastTenth = tenth;
            std::fprintf(stderr, "  load %3d %%\n", tenth * 10);
        }
        return ProgressAction::Continue;
    });
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    rusage ru{};
    getrusage(RUSAGE_SELF, &ru);
    if (!r.ok()) {
        std::fprintf(stderr, "load failed: %s\n",
                     r.errors.empty() ? "cancelled" : r.errors[0].message().c_str());
        return 3;
    }
    std::size_t rows = 0;
    for (const auto& b : r.dataSet.batches) {
        rows += b.rows();
    }
    std::printf("loaded %zu runs, %zu rows of the step's grid, in %.1f s; peak RSS %.0f MB; %zu note(s)\n",
                r.dataSet.batches.size(), rows, seconds, ru.ru_maxrss / 1024.0, r.notes.size());
    return 0;
}
