#include "HeadlessCommands.h"

#include "common/AtomicFile.h"
#include "data/BatchReader.h"
#include "data/DataSetSummary.h"

#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>

namespace drytwin::app {

namespace {

int fail(const Error& e) {
    std::fprintf(stderr, "drytwin: error: %s\n", e.message().c_str());
    return exitCodeFor(e.kind);
}

/// Loads the data set named by --data (with --mapping); prints every rejected file.
bool loadData(const CommandOptions& o, data::DataSet& out, int& exitCode) {
    data::ReadOptions ro;
    if (!o.mappingPath.empty()) {
        auto m = data::readColumnMapping(o.mappingPath);
        if (!m) {
            exitCode = fail(m.error());
            return false;
        }
        ro.mapping = *m;
    }
    auto loaded = data::loadDataSet(o.dataPath, ro, o.progress);
    if (loaded.cancelled) {
        std::fprintf(stderr, "drytwin: cancelled\n");
        exitCode = 130;
        return false;
    }
    if (!loaded.errors.empty()) {
        for (const auto& e : loaded.errors) {
            std::fprintf(stderr, "drytwin: error: %s\n", e.message().c_str());
        }
        std::fprintf(stderr, "drytwin: %zu file(s) rejected; nothing was changed\n", loaded.errors.size());
        exitCode = 3;
        return false;
    }
    out = std::move(loaded.dataSet);
    return true;
}

std::string fmt(double v, int precision = 3) {
    if (std::isnan(v)) {
        return "-";
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", precision, v);
    return buf;
}

int notImplemented(const char* name) {
    std::fprintf(stderr, "drytwin %s: not implemented in this version yet (see the README's status table)\n",
                 name);
    return 2;
}

} // namespace

int runInspect(const CommandOptions& o) {
    if (auto st = o.cleaning.validate(); !st) {
        return fail(Error{ErrorKind::Usage, "--" + st.error().place, st.error().reason});
    }
    data::DataSet ds;
    int rc = 0;
    if (!loadData(o, ds, rc)) {
        return rc;
    }
    const auto s = data::summarize(ds, o.cleaning);
    std::printf("Data set %s: %zu batch(es), %zu rows, %zu missing cell(s)\n\n", o.dataPath.c_str(),
                s.batches.size(), s.rows, s.missing);
    std::printf("%-14s %7s %10s %10s %8s %8s %8s %8s  %s\n", "batch", "rows", "start [s]", "end [s]",
                "step [s]", "gap [s]", "missing", "dropped", "file");
    for (const auto& b : s.batches) {
        std::printf("%-14s %7zu %10s %10s %8s %8s %8zu %8zu  %s\n", b.id.c_str(), b.rows,
                    fmt(b.startS, 1).c_str(), fmt(b.endS, 1).c_str(), fmt(b.medianStepS, 2).c_str(),
                    fmt(b.largestGapS, 2).c_str(), b.missing, b.droppedByCleaning, b.path.c_str());
    }
    std::printf("\n%-15s %-7s %12s %12s %12s %8s\n", "column", "unit", "min", "max", "mean", "missing");
    for (const auto& c : s.columns) {
        if (!c.present) {
            std::printf("%-15s %-7s %12s\n", c.name.c_str(), c.unit.c_str(), "(absent)");
            continue;
        }
        std::printf("%-15s %-7s %12s %12s %12s %8zu\n", c.name.c_str(), c.unit.c_str(), fmt(c.min).c_str(),
                    fmt(c.max).c_str(), fmt(c.mean).c_str(), c.missing);
    }
    if (!s.extraColumns.empty()) {
        std::printf("\nextra columns kept as text:");
        for (const auto& e : s.extraColumns) {
            std::printf(" %s", e.c_str());
        }
        std::printf("\n");
    }
    const auto& c = s.cleaning;
    std::printf(
        "\nCleaning rules (paper §IV.A) keep %zu of %zu rows (%.1f %%). Dropped by rule (a row can fail "
        "several):\n",
        c.kept, c.rows, c.rows ? 100.0 * static_cast<double>(c.kept) / static_cast<double>(c.rows) : 0.0);
    std::printf("  X_hdt_pct < %g %% wb: %zu\n  T_hdt_C < %g °C: %zu\n  feed_kg_h < %g kg/h: %zu\n"
                "  missing input or output: %zu\n",
                o.cleaning.minXhdtPct, c.droppedXhdt, o.cleaning.minThdtC, c.droppedThdt,
                o.cleaning.minFeedKgPerHour, c.droppedFeed, c.droppedMissing);
    for (const auto& r : c.skippedRules) {
        std::printf("  rule not applied: %s\n", r.c_str());
    }
    if (!o.jsonPath.empty()) {
        nlohmann::json j;
        j["rows"] = s.rows;
        j["missing"] = s.missing;
        for (const auto& b : s.batches) {
            j["batches"].push_back({{"id", b.id},
                                    {"rows", b.rows},
                                    {"start_s", b.startS},
                                    {"end_s", b.endS},
                                    {"missing", b.missing},
                                    {"dropped_by_cleaning", b.droppedByCleaning},
                                    {"file", b.path}});
        }
        for (const auto& col : s.columns) {
            if (col.present) {
                j["columns"][col.name] = {{"unit", col.unit},
                                          {"min", col.min},
                                          {"max", col.max},
                                          {"mean", col.mean},
                                          {"missing", col.missing}};
            }
        }
        j["cleaning"] = {{"kept", c.kept},
                         {"dropped_x_hdt", c.droppedXhdt},
                         {"dropped_t_hdt", c.droppedThdt},
                         {"dropped_feed", c.droppedFeed},
                         {"dropped_missing", c.droppedMissing}};
        if (auto st = writeFileAtomically(o.jsonPath, j.dump(2) + "\n"); !st) {
            return fail(st.error());
        }
    }
    return 0;
}

int runGenerate(const CommandOptions&) {
    return notImplemented("generate");
}
int runSimulate(const CommandOptions&) {
    return notImplemented("simulate");
}
int runCalibrate(const CommandOptions&) {
    return notImplemented("calibrate");
}
int runEvaluate(const CommandOptions&) {
    return notImplemented("evaluate");
}
int runPipeline(const CommandOptions&) {
    return notImplemented("pipeline");
}

} // namespace drytwin::app
