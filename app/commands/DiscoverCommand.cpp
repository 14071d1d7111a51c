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

namespace {

/// Detection first: whether the data differ from the reference, by each detector, from when, and
/// in which columns.
void printDetection(const discovery::DiscoveryResult& d) {
    const auto& det = d.detection;
    std::printf("Against the reference period %s (%zu batch(es), %zu rows; the model commissioned there):\n",
                d.referencePath.c_str(), d.referenceBatches, d.referenceRows);
    std::printf(
        "  %s (each detector's false-alarm rate %.3g per data set; DryTwin's split between its monitor "
        "and its causes' test)\n",
        det.changed         ? "CHANGED"
        : det.namedChange() ? "CHANGED (a named cause)"
                            : "no change detected",
        det.falseAlarmRate);
    if (!det.changed && det.namedChange()) {
        std::string causes;
        for (const auto& c : det.namedCauses) {
            causes += (causes.empty() ? "" : ", ") + c;
        }
        std::printf(
            "  the detectors, judging the data set as a whole, did not flag it; fitting the causes found "
            "%s beyond its normal spread with a held-out gain (below). Such a name is a claim the "
            "detectors' rate does not cover: check it on the plots.\n",
            causes.c_str());
    }
    const auto line = [](const char* name, const monitoring::Detection& m) {
        std::printf("  %-38s %s, p %.3g (%s)", name, m.changed ? "flags a change" : "no change", m.pValue,
                    m.statistic.c_str());
        if (m.hasFirstAlarm) {
            std::printf(", first alarm %s at %.1f min", m.firstAlarmRun.c_str(), m.firstAlarmTimeS / 60);
        }
        if (m.hasOnset) {
            // The change-point estimate looks back from the alarm: it may lie in an earlier batch.
            std::printf(", the change began (change-point estimate) in %s at %.1f min [95 %%: %.1f to %.1f]",
                        m.onsetRun.c_str(), m.onsetS / 60, m.onsetLowS / 60, m.onsetHighS / 60);
        }
        std::printf("\n");
        if (m.changed && !m.contributions.empty()) {
            std::printf("  %-38s", "  largest contributions:");
            for (std::size_t i = 0; i < m.contributions.size() && i < 3; ++i) {
                const auto& c = m.contributions[i];
                std::printf(" %s %.0f %%", c.column.c_str(),
                            100 *
                                (m.statistic == "SPE" ? c.speReconstructionShare : c.t2ReconstructionShare));
            }
            std::printf("\n");
        }
    };
    line("DryTwin, monitor of the model's errors:", det.drytwin);
    std::printf("  %-38s %s, p %.3g (Bonferroni; smallest: %s%s)\n", "DryTwin, the causes' estimates:",
                det.causeTest.changed ? "one moved beyond its normal spread"
                                      : "none moved at the detector's rate",
                det.causeTest.pValue, det.causeTest.cause.empty() ? "-" : det.causeTest.cause.c_str(),
                det.causeTest.look() == "gauge_scatter" ? ", the gauge's scatter"
                : det.causeTest.look() == "named_fit"   ? ", at its fitted value"
                                                        : "");
    line("dynamic PCA (the measured columns):", det.pca);
    std::printf("\n");
}

} // namespace

int runDiscover(const CommandOptions& o) {
    workflow::DiscoverOptions options;
    options.discovery.maxCauses = o.maxCauses;
    options.discovery.minExplainedFraction = o.minExplained;
    options.discovery.fastBandWindowS = o.fastWindowS;
    options.discovery.causes = o.causes;
    options.discovery.falseAlarmRate = o.falseAlarmRate;
    options.referencePath = o.referencePath;
    options.referenceMappingPath = o.referenceMappingPath.empty() ? o.mappingPath : o.referenceMappingPath;
    workflow::Session session;
    int rc = 0;
    if (auto st = options.validate(); !st) {
        return fail(st.error());
    }
    if (!open(o, session, rc)) {
        return rc;
    }
    auto result = session.discover(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    const auto& d = result->discovery;
    if (d.hasReference) {
        printDetection(d);
    }
    std::printf(
        d.hasReference
            ? "What the simulation gets wrong beyond the line's own structure on the reference (model as "
              "commissioned there; residual = measured - structure - simulated):\n"
            : "What the simulation gets wrong (after refitting h_HDT, k_HDT on the training part; residual "
              "= measured - simulated):\n");
    std::printf("%-6s %-5s %10s %10s %12s %10s %12s  %s\n", "output", "unit", "bias", "± se", "trend [/h]",
                "± se", "line [s]", "strongest correlate (differences)");
    for (const auto& r : d.residuals) {
        const auto c = r.correlates.empty() ? std::string("-")
                                            : r.correlates[0].column + " at " + fmt(r.correlates[0].lagS, 0) +
                                                  " s, ccf " + fmt(r.correlates[0].ccf, 2);
        std::printf("%-6s %-5s %10.4f %10.4f %12.4f %10.4f %12s  %s\n", r.output.c_str(), r.unit.c_str(),
                    r.bias, r.biasSe, r.trendPerHour, r.trendSe,
                    r.peakPowerRatio > 1
                        ? (fmt(r.peakPeriodS, 0) + " (x" + fmt(r.peakPowerRatio, 1) + ")").c_str()
                        : "-",
                    c.c_str());
    }
    for (const auto& note : d.notes) {
        std::printf("note: %s\n", note.c_str());
    }
    std::printf(
        d.hasReference
            ? "\nCandidate causes (z: change of the one-step estimate from the reference's, in units of "
              "both errors and the reference's spread; p: its test, or * a timing cause's own score test "
              "where that is smaller (a lag's one-step estimate understates its change); Bonferroni):\n"
            : "\nCandidate causes (score test on the training part, HAC variance, Holm-corrected):\n");
    std::printf("%-28s %8s %10s %10s %12s %14s\n", "cause", "z", "p ", "p (Holm)", "fitted", "train loss");
    for (const auto& c : d.ranking) {
        std::printf(
            "%-28s %8.2f %9.3g%s %10.3g %12s %14s%s\n", c.cause.c_str(), c.score, c.pValue,
            c.pFromOwnScreen ? "*" : " ", c.pHolm, c.fitted ? "yes" : "no",
            c.fitted ? (fmt(c.fitLossBefore, 4) + " -> " + fmt(c.fitLossAfter, 4)).c_str() : "-",
            c.screenedFromS >= 0 ? ("  (tested from " + fmt(c.screenedFromS / 60, 0) + " min)").c_str() : "");
    }
    for (std::size_t i = 0; i < d.rounds.size(); ++i) {
        const auto& rd = d.rounds[i];
        std::printf("round %zu: %s%s%s\n", i + 1, rd.best.empty() ? "" : (rd.best + ": ").c_str(),
                    rd.named ? "named" : "stop, ", rd.named ? "" : rd.reason.c_str());
        for (const auto& x : rd.rejected) {
            std::printf("  not named: %s (%s): %s\n", x.cause.c_str(), x.code.c_str(), x.reason.c_str());
        }
    }
    std::printf("\nVerdict: %s\n", d.verdict.c_str());
    for (const auto& f : d.findings) {
        if (f.group.empty()) {
            std::printf("\n* %s\n  %s\n", f.cause.c_str(), f.evidence.c_str());
        } else {
            std::string members = f.cause;
            for (const auto& l : f.lookAlikes) {
                if (!l.ruledOut) {
                    members += " or " + l.cause;
                }
            }
            std::printf("\n* one of a look-alike group (%s): %s\n  %s\n", f.group.c_str(), members.c_str(),
                        f.evidence.c_str());
        }
        if (!f.perPart.empty()) {
            std::printf("  per part: %s\n", discovery::describeParts(f.perPart).c_str());
        }
        if (f.restated &&
            std::abs(f.value - f.valueWhenNamed) > 0.25 * (f.ci95HighWhenNamed - f.ci95LowWhenNamed)) {
            const auto& info = properties::info(f.parameter);
            std::printf(
                "  in the final model, fitted jointly with every other named cause: %s = %.4g%s, 95 %% CI "
                "[%.4g, %.4g] (the sentence above and the parts: the fit when it was named)\n",
                std::string(info.symbol).c_str(), f.value, properties::spacedUnit(f.parameter).c_str(),
                f.ci95Low, f.ci95High);
        }
        if (f.hasReference) {
            const auto& info = properties::info(f.parameter);
            std::printf(
                "  changed from the reference: %s %.4g%s here, %.4g (normal range %.4g to %.4g) on the "
                "reference\n",
                std::string(info.symbol).c_str(), f.value, properties::spacedUnit(f.parameter).c_str(),
                f.referenceValue, f.referenceCi95Low, f.referenceCi95High);
        }
    }
    if (!d.bounds.empty()) {
        std::printf(
            "\nNot named; what the data allow (one step from 0 at the final model, 95 %%, held within "
            "each parameter's range):\n");
        for (const auto& b : d.bounds) {
            const auto& info = properties::info(b.parameter);
            std::printf("  %-28s %-15s %10.4g  [%.3g, %.3g] %s\n", b.cause.c_str(),
                        std::string(info.symbol).c_str(), b.estimate, b.ci95Low, b.ci95High,
                        std::string(info.unit).c_str());
        }
    }
    // Against a reference where nothing changed, a pattern left in the error is the line's as it
    // was on the reference too: said, so that it is not read as a finding beside "no change".
    if (d.hasReference && !d.detection.lineChanged() && !d.unexplained.empty()) {
        std::printf("\nPatterns left in the error below: the data did not change against the reference, so "
                    "they are within what the reference period shows, not a change.");
    }
    for (const auto& s : d.unexplained) {
        std::printf("\nUnexplained (%s): %s", s.output.c_str(), s.type.c_str());
        if (s.type == "periodic") {
            std::printf(", period %.0f s, power x%.1f over its background", s.periodS, s.strength);
        } else if (s.type == "lagged_input") {
            std::printf(", %s at %.0f s (ccf %.2f)", s.column.c_str(), s.lagS, s.strength);
        } else if (s.type == "batch_shift") {
            std::printf(", batches");
            for (const auto& b : s.batches) {
                std::printf(" %s", b.c_str());
            }
        } else if (s.type == "dynamics") {
            std::printf(": the error follows the simulated rate of change (a lag of %.3g s would explain "
                        "%.0f %% of it): the line's dynamics differ from the model's",
                        s.lagS, 100 * s.strength);
        } else {
            std::printf(", %+.3g per hour", s.strength);
        }
        std::printf("\n");
    }
    if (result->hasHybrid) {
        std::printf("\nPGRL-CC retrained on top, held-out one-step MAE: X_out %.4f -> %.4f %% wb, T_out %.4f "
                    "-> %.4f °C\n",
                    result->hybridMaeMoistureBefore, result->hybridMaeMoistureAfter,
                    result->hybridMaeTemperatureBefore, result->hybridMaeTemperatureAfter);
        if (result->keptStartingModel) {
            std::printf("The hybrid on the extended physics model is worse on the held-out part: the model "
                        "written keeps the starting physics and its residual model (the findings stand).\n");
        }
        const auto& ref = result->references;
        if (std::isfinite(ref.persistenceMoisture)) {
            const bool kept = result->keptStartingModel;
            const double maeX = kept ? result->hybridMaeMoistureBefore : result->hybridMaeMoistureAfter;
            const double maeT = kept ? result->hybridMaeTemperatureBefore : result->hybridMaeTemperatureAfter;
            std::printf(
                "References on the same rows: the last measurement held X_out %.4f %% wb, T_out %.4f °C; "
                "the PBM with its last error held X_out %.4f -> %.4f %% wb, T_out %.4f -> %.4f °C.\n",
                ref.persistenceMoisture, ref.persistenceTemperature, ref.pbmHoldMoistureBefore,
                ref.pbmHoldMoistureAfter, ref.pbmHoldTemperatureBefore, ref.pbmHoldTemperatureAfter);
            // Within half a percent is a tie, not a win: "beats both (0.0345 against 0.0345)" read
            // as a joke.
            const auto verdict = [](double mae, double best) {
                return mae < 0.995 * best    ? "beats both"
                       : mae <= 1.005 * best ? "is level with the better of them"
                                             : "does NOT beat the better of them";
            };
            std::printf("PGRL-CC on the model written: X_out %s (%.5f against %.5f), T_out %s (%.5f against "
                        "%.5f).\n",
                        verdict(maeX, ref.bestMoisture(kept)), maeX, ref.bestMoisture(kept),
                        verdict(maeT, ref.bestTemperature(kept)), maeT, ref.bestTemperature(kept));
        }
    }
    std::printf("\n%.1f s\n", result->ending.elapsedSeconds);
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(
                o.jsonPath,
                io::discoveryJson(d, result->hasHybrid, result->hybridMaeMoistureBefore,
                                  result->hybridMaeMoistureAfter, result->hybridMaeTemperatureBefore,
                                  result->hybridMaeTemperatureAfter, result->keptStartingModel,
                                  result->references));
            !st) {
            return fail(st.error());
        }
    }
    if (!o.outPath.empty()) {
        if (auto st = io::writeModelFile(result->extendedModel, o.outPath); !st) {
            return fail(st.error());
        }
    }
    return 0;
}

} // namespace drytwin::app
