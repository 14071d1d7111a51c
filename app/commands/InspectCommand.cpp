#include "HeadlessCommands.h"
#include "commands/CommandHelpers.h"

#include "common/AtomicFile.h"
#include "common/Units.h"
#include "control/BundledScenarios.h"
#include "io/ModelFile.h"
#include "io/ResultFiles.h"
#include "plant/Mechanisms.h"
#include "workflow/Session.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace drytwin::app {

using namespace detail;

int runInspect(const CommandOptions& o) {
    if (auto st = o.cleaning.validate(); !st) {
        return fail(Error{ErrorKind::Usage, "--" + st.error().place, st.error().reason});
    }
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc, true, false)) { // its own list below holds every note
        return rc;
    }
    auto summary = session.inspect();
    if (!summary) {
        return fail(summary.error());
    }
    const auto& s = *summary;
    std::printf("Data set %s: %zu batch(es), %zu rows, %zu missing cell(s)\n\n", o.dataPath.c_str(),
                s.batches.size(), s.rows, s.missing);
    std::printf("%-14s %7s %10s %10s %8s %8s %8s %8s  %s\n", "batch", "rows", "start [s]", "end [s]",
                "step [s]", "gap [s]", "missing", "dropped", "file");
    for (const auto& b : s.batches) {
        std::printf("%-14s %7zu %10s %10s %8s %8s %8zu %8zu  %s\n", b.id.c_str(), b.rows,
                    fmt(b.startS, 1).c_str(), fmt(b.endS, 1).c_str(), fmt(b.medianStepS, 2).c_str(),
                    fmt(b.largestGapS, 2).c_str(), b.missing, b.droppedByCleaning, b.path.c_str());
    }
    bool anyRun = false;
    for (const auto& b : s.batches) {
        anyRun = anyRun || b.run.has_value();
    }
    if (anyRun) {
        std::printf("\nproduction runs cut from long plant files:\n%-14s %-20s %-13s %9s %12s %8s  %s\n",
                    "run", "start", "file lines", "samples", "interpolated", "gap", "ended by");
        for (const auto& b : s.batches) {
            if (!b.run) {
                continue;
            }
            const auto& r = *b.run;
            std::printf("%-14s %-20s %-13s %9zu %12zu %8zu  %s\n", b.id.c_str(), r.startTimestamp.c_str(),
                        (std::to_string(r.firstLine) + "-" + std::to_string(r.lastLine)).c_str(), r.samples,
                        r.interpolatedCells, r.gapCells, r.splitReason.c_str());
        }
    }
    if (!s.notes.empty()) {
        std::printf("\nnoted while reading:\n");
        for (const auto& n : s.notes) {
            std::printf("  %s\n", n.c_str());
        }
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
    if (!s.missingCells.empty()) {
        std::printf("\nMissing cells (the first %zu per column; the cleaning rules decide what to do with "
                    "them):\n",
                    data::DataSetSummary::kMaxListedMissing);
        for (const auto& m : s.missingCells) {
            const std::string column =
                m.column == m.contractColumn ? m.column : m.column + " (" + m.contractColumn + ")";
            std::printf("  %s:%d:%d: %s\n", m.file.c_str(), m.line, m.fileColumn, column.c_str());
        }
        if (s.missingCells.size() < s.missingPlaces) {
            std::printf("  … and %zu more\n", s.missingPlaces - s.missingCells.size());
        }
    }
    if (s.impossibleTotal > 0) {
        std::printf(
            "\nWARNING: %zu physically impossible value(s); no model should see them (fix the file or "
            "the column mapping/units):\n",
            s.impossibleTotal);
        for (const auto& w : s.impossible) {
            const std::string column =
                w.column == w.contractColumn ? w.column : w.column + " (" + w.contractColumn + ")";
            std::printf("  %s:%d:%d: %s = %g %s\n", w.file.c_str(), w.line, w.fileColumn, column.c_str(),
                        w.value, w.rule.c_str());
        }
        if (s.impossible.size() < s.impossibleTotal) {
            std::printf("  … and %zu more (the first %zu per column are listed)\n",
                        s.impossibleTotal - s.impossible.size(), data::DataSetSummary::kMaxListedImpossible);
        }
    }
    const auto& c = s.cleaning;
    std::printf(
        "\nCleaning rules (paper §IV.A) keep %zu of %zu rows (%.1f %%). Dropped by rule (a row can fail "
        "several):\n",
        c.kept, c.rows, c.rows ? 100.0 * static_cast<double>(c.kept) / static_cast<double>(c.rows) : 0.0);
    for (const auto& [rule, rows] : data::droppedByRule(c, o.cleaning)) {
        std::printf("  %s: %zu\n", rule.c_str(), rows);
    }
    for (const auto& f : c.stuck) { // where a transmitter hung: an input is bridged, the rows left out
        const char* batch = f.batch < s.batches.size() ? s.batches[f.batch].id.c_str() : "?";
        std::printf("    %s in %s: %g from row %zu for %.0f s\n",
                    std::string(data::spec(f.column).name).c_str(), batch, f.value, f.begin + 1, f.seconds);
    }
    for (const auto& r : c.skippedRules) {
        std::printf("  rule not applied: %s\n", r.c_str());
    }
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(o.jsonPath, io::inspectJson(s)); !st) {
            return fail(st.error());
        }
    }
    return 0;
}

} // namespace drytwin::app
