#include "data/DataSetSummary.h"

#include "common/NumberText.h"

#include <cstdio>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <tuple>

namespace drytwin::data {

namespace {

/// The plausibility notes' limits (°C, K, factor): generous, so that a note means a unit or a
/// column is wrong, not that the line is unusual.
constexpr double kHottestPlausibleHotAirC = 260;    // 500 °F; tobacco and grain lines run 120–250 °C
constexpr double kHottestPlausibleAmbientC = 55;    // the hottest air ever measured outdoors is 57 °C
constexpr double kLargestPlausibleBatchShiftK = 75; // process temperatures; two products' hot air 55 K apart
constexpr double kLightestPlausibleFeedKgH = 50;    // a pneumatic drier's smallest feed: hundreds of kg/h
constexpr double kLargestPlausibleBatchFactor = 10; // RH may go from 12 to 90 %; a unit moves ×100

/// What a reader must know but no single cell shows, in the batch's file: a sampling step other than
/// the contract's 1 s, and a gap in time (a stop, a lost connection) that the model runs across as
/// if the line had run on.
void timingNotes(const Batch& b, const BatchSummary& bs, int gapLine, std::vector<std::string>& notes) {
    const std::string where = b.sourcePath.empty() ? b.id : b.sourcePath;
    char text[256];
    if (std::abs(bs.medianStepS - 1.0) > 0.05) {
        std::snprintf(text, sizeof text,
                      ": rows are typically %.3g s apart, not the 1 s the model and the learnt layer's lags "
                      "assume; the physics follows the time stamps, the lags and horizons count rows",
                      bs.medianStepS);
        notes.push_back(where + text);
    }
    if (bs.largestGapS > std::max(10.0, 5 * bs.medianStepS)) {
        std::snprintf(
            text, sizeof text,
            ":%d: a gap of %.0f s in time (rows typically %.3g s apart): the model runs across it as "
            "if the line had run on; a stop is better cut into two batches",
            gapLine, bs.largestGapS, bs.medianStepS);
        notes.push_back(where + text);
    }
}

/// A column that holds no value at all: every row then fails the cleaning (a required one), and a
/// later "no usable rows" would not say why.
void emptyColumnNote(const Batch& b, const Batch::NumericColumn& col, DataSetSummary& summary) {
    if (col.id == Column::Time || col.values.empty() ||
        std::any_of(col.values.begin(), col.values.end(), [](double v) { return std::isfinite(v); })) {
        return;
    }
    const std::string name(spec(col.id).name);
    const bool required = spec(col.id).required;
    summary.notes.push_back((b.sourcePath.empty() ? b.id : b.sourcePath) + ": column '" + col.fileName + "'" +
                            (col.fileName == name ? std::string() : " (" + name + ")") +
                            " holds no value in any of its " + std::to_string(col.values.size()) + " rows" +
                            (required ? ": every row fails the cleaning, nothing of this batch can be used"
                                      : ": it is treated as not measured"));
    if (required) {
        summary.emptyRequiredColumns.push_back(summary.notes.back());
    }
}

/// Column means in the contract's units (NaN where a column is absent or empty).
using ColumnMeans = std::array<double, kColumnCount>;

/// One plausibility check that failed: which check (to group batches by), and what to say.
struct PlausibilityNote {
    std::string check;
    std::string text;
};

/// Columns each possible alone but impossible together, which a wrong unit or two swapped headers
/// give (a fresh user's test: °F under a °C header, a moisture fraction under % wb, X_out and T_out
/// swapped, each calibrated with exit 0), and values no line of this kind has. For @p m, a data
/// set's or a batch's means. The thresholds leave room for any product a pneumatic drier dries.
std::vector<PlausibilityNote> pairNotes(const ColumnMeans& m) {
    const auto at = [&m](Column c) { return m[static_cast<std::size_t>(c)]; };
    const double xIn = at(Column::XIn), xOut = at(Column::XOut);
    const double tHot = at(Column::THot), tHotSp = at(Column::THotSp), tOut = at(Column::TOut);
    const double tHdt = at(Column::THdt), tAmb = at(Column::TAmb);
    std::vector<PlausibilityNote> out;
    char text[512];
    if (xOut > xIn) {
        std::snprintf(text, sizeof text,
                      "X_out_pct (mean %.3g %% wb) is above X_in_pct (mean %.3g %% wb): a drier does not wet "
                      "its product; check that the columns are not swapped and are in %% wet basis",
                      xOut, xIn);
        out.push_back({"outlet wetter than inlet", text});
    } else if (xOut > 0 && xIn > 100 * xOut) {
        std::snprintf(text, sizeof text,
                      "X_out_pct (mean %.3g %% wb) is below a hundredth of X_in_pct (mean %.3g %% wb): a "
                      "fraction (0.12) given for a percentage (12 %%)? Check its unit",
                      xOut, xIn);
        out.push_back({"outlet a fraction", text});
    }
    if (std::abs(tHot - tHotSp) > 30) {
        std::snprintf(text, sizeof text,
                      "T_hot_C (mean %.4g °C) is %.0f K from its setpoint T_hot_sp_C (mean %.4g °C): one of "
                      "them in another unit (°F, K) or another column? Check both",
                      tHot, std::abs(tHot - tHotSp), tHotSp);
        out.push_back({"hot air off its setpoint", text});
    } else {
        // Both in °F agree with each other: 160 °C of hot air reads 320. The column said is the
        // one above the limit (the setpoint is optional).
        const bool setpoint = !(tHot > kHottestPlausibleHotAirC) && tHotSp > kHottestPlausibleHotAirC;
        const double hot = setpoint ? tHotSp : tHot;
        if (hot > kHottestPlausibleHotAirC) {
            std::snprintf(text, sizeof text,
                          "%s (mean %.4g °C) is hotter than the hot air of the lines this model was built "
                          "for (tobacco, grain: up to about 250 °C); °F (%.0f °F is %.0f °C) or K? Check its "
                          "unit and %s's",
                          setpoint ? "T_hot_sp_C" : "T_hot_C", hot, hot, (hot - 32) / 1.8,
                          setpoint ? "T_hot_C" : "T_hot_sp_C");
            out.push_back({"hot air too hot", text});
        }
    }
    if (tOut > tHdt + 20) {
        std::snprintf(text, sizeof text,
                      "T_out_C (mean %.4g °C) is %.0f K above the tube outlet's T_hdt_C (mean %.4g °C): the "
                      "product cools on its way from the tube, it does not heat up; another unit (°F) or "
                      "swapped columns? Check both",
                      tOut, tOut - tHdt, tHdt);
        out.push_back({"outlet hotter than tube", text});
    } else if (tOut > tHot) {
        std::snprintf(text, sizeof text,
                      "T_out_C (mean %.4g °C) is above the hot air T_hot_C (mean %.4g °C) that heats the "
                      "product: another unit (°F) or swapped columns? Check both",
                      tOut, tHot);
        out.push_back({"outlet hotter than hot air", text});
    }
    if (const double feed = at(Column::Feed); feed > 0 && feed < kLightestPlausibleFeedKgH) {
        // Every row then fails the cleaning's feed rule (paper §IV.A) and nothing says why.
        std::snprintf(text, sizeof text,
                      "feed_kg_h (mean %.3g kg/h) is less than a pneumatic line carries (hundreds to "
                      "thousands of kg/h); t/h (%.3g t/h is %.0f kg/h)? Check its unit",
                      feed, feed, 1000 * feed);
        out.push_back({"feed too small", text});
    }
    if (tAmb > kHottestPlausibleAmbientC) {
        std::snprintf(text, sizeof text,
                      "T_amb_C (mean %.3g °C) is hotter than any air a plant hall breathes (above %.0f °C); "
                      "°F (%.0f °F is %.0f °C)? Check its unit",
                      tAmb, kHottestPlausibleAmbientC, tAmb, (tAmb - 32) / 1.8);
        out.push_back({"ambient too hot", text});
    }
    return out;
}

/// The data set's plausibility notes: each check on every batch's own means, so that one batch in
/// another unit (a folder of files from two exports) is named rather than averaged away; a check
/// every batch fails is said once, for the data set.
void plausibilityNotes(const std::vector<ColumnMeans>& perBatch, const std::vector<std::string>& where,
                       std::vector<std::string>& notes) {
    std::map<std::string, std::vector<std::pair<std::size_t, std::string>>> failing; // check → batches
    std::vector<std::string> order;
    for (std::size_t b = 0; b < perBatch.size(); ++b) {
        for (auto& note : pairNotes(perBatch[b])) {
            if (failing[note.check].empty()) {
                order.push_back(note.check);
            }
            failing[note.check].emplace_back(b, std::move(note.text));
        }
    }
    for (const auto& check : order) {
        const auto& batches = failing[check];
        if (batches.size() == perBatch.size() && perBatch.size() > 1) {
            notes.push_back("every batch: " + batches.front().second); // with the first batch's numbers
            continue;
        }
        for (const auto& [b, text] : batches) {
            notes.push_back(where[b] + ": " + text);
        }
    }
}

/// The median of @p v (the mean of the middle two for an even count); @p v is reordered.
double medianOf(std::vector<double>& v) {
    const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
    std::nth_element(v.begin(), mid, v.end());
    if (v.size() % 2 == 1) {
        return *mid;
    }
    return 0.5 * (*mid + *std::max_element(v.begin(), mid));
}

/// Does a temperature batch mean @p v read as the others' @p median would in another unit (°F or
/// K), or lie further from it than any product change moves a process temperature? Ambient and
/// the inlet product's temperature swing over seasons by as much as °F differs from °C at 20 °C
/// (48 K), so for them only the unit's own signature counts; and never where the other batches
/// themselves lie as far apart (@p othersRange: a winter batch among summer ones).
bool temperatureInAnotherUnit(Column c, double v, double median, double othersRange) {
    const double apart = std::abs(v - median);
    if (apart <= std::max(15.0, 2 * othersRange)) {
        return false;
    }
    const double tolerance = std::max(5.0, 0.1 * std::abs(median));
    const bool fahrenheit = std::abs((v - 32) / 1.8 - median) < tolerance;
    const bool kelvin = std::abs(v - 273.15 - median) < tolerance;
    const bool seasonal = c == Column::TAmb || c == Column::TIn;
    return fahrenheit || kelvin || (!seasonal && apart > kLargestPlausibleBatchShiftK);
}

/// A batch whose column reads in another unit than the other batches' (°F among °C, a fraction
/// among percentages, t/h among kg/h): its mean far from the median of the others' means, by more
/// than any season or product change moves it. Needs two other batches to say which one is odd.
void batchAgainstOthersNotes(const std::vector<ColumnMeans>& perBatch, const std::vector<std::string>& where,
                             std::vector<std::string>& notes) {
    if (perBatch.size() < 3) {
        return;
    }
    for (const auto& c : columnSpecs()) {
        if (c.id == Column::Time) {
            continue;
        }
        const auto i = static_cast<std::size_t>(c.id);
        const std::string_view unit = c.unit;
        const bool temperature = unit == "°C";
        for (std::size_t b = 0; b < perBatch.size(); ++b) {
            std::vector<double> others;
            for (std::size_t o = 0; o < perBatch.size(); ++o) {
                if (o != b && std::isfinite(perBatch[o][i])) {
                    others.push_back(perBatch[o][i]);
                }
            }
            const double v = perBatch[b][i];
            if (others.size() < 2 || !std::isfinite(v)) {
                continue;
            }
            const auto [lowest, highest] = std::minmax_element(others.begin(), others.end());
            const double othersRange = *highest - *lowest;
            const double median = medianOf(others);
            // The rest are positive amounts: a factor of ten is a unit (a batch at 0, a line stop,
            // is no unit).
            const bool odd = temperature ? temperatureInAnotherUnit(c.id, v, median, othersRange)
                                         : median > 0 && v > 0 &&
                                               (v > kLargestPlausibleBatchFactor * median ||
                                                v * kLargestPlausibleBatchFactor < median);
            if (!odd) {
                continue;
            }
            char text[512];
            std::snprintf(text, sizeof text,
                          ": %s reads %.4g %s on average, the other batches about %.4g (their median): "
                          "this batch in another unit (°F, K, a fraction, t/h) or another column? Check it",
                          std::string(c.name).c_str(), v, std::string(unit).c_str(), median);
            notes.push_back(where[b] + text);
        }
    }
}

} // namespace

DataSetSummary summarize(const DataSet& data, const CleaningOptions& cleaningOptions) {
    DataSetSummary s;
    s.notes = data.notes;
    s.cleaning = clean(data, cleaningOptions);
    std::vector<double> sum(kColumnCount, 0.0);
    std::vector<std::size_t> count(kColumnCount, 0);
    for (const auto& spec : columnSpecs()) {
        ColumnSummary c;
        c.name = std::string(spec.name);
        c.unit = std::string(spec.unit);
        c.min = std::numeric_limits<double>::infinity();
        c.max = -std::numeric_limits<double>::infinity();
        s.columns.push_back(c);
    }
    std::set<std::string> extras;
    // A header that is an optional contract column spelt otherwise ("T_inlet_C"): read as text and
    // the column taken as absent, which changes the model's result without an error; said once per
    // header, with the files it is in.
    std::map<std::pair<std::string, Column>, std::vector<std::string>> lookalikes;
    std::vector<std::size_t> listed(kColumnCount, 0), listedMissing(kColumnCount, 0);
    std::vector<ColumnMeans> batchMeans;
    std::vector<std::string> batchPlaces;
    for (std::size_t bi = 0; bi < data.batches.size(); ++bi) {
        const Batch& b = data.batches[bi];
        ColumnMeans& means = batchMeans.emplace_back();
        means.fill(std::numeric_limits<double>::quiet_NaN());
        // A run cut from a long plant file shares the file with the others: named by its id too.
        batchPlaces.push_back(b.sourcePath.empty() ? b.id
                              : b.run              ? b.sourcePath + " (" + b.id + ")"
                                                   : b.sourcePath);
        BatchSummary bs;
        const std::size_t missingBefore = s.missingCells.size();
        bs.id = b.id;
        bs.path = b.sourcePath;
        bs.run = b.run;
        bs.rows = b.rows();
        bs.missing = b.missing.size();
        const auto& keep = s.cleaning.keep[bi];
        bs.droppedByCleaning = static_cast<std::size_t>(std::count(keep.begin(), keep.end(), 0));
        if (const auto* t = b.values(Column::Time); t && !t->empty()) {
            bs.startS = t->front();
            bs.endS = t->back();
            std::vector<double> steps;
            for (std::size_t i = 1; i < t->size(); ++i) {
                steps.push_back((*t)[i] - (*t)[i - 1]);
            }
            if (!steps.empty()) {
                const auto largest = std::max_element(steps.begin(), steps.end());
                bs.largestGapS = *largest;
                const std::size_t gapRow = static_cast<std::size_t>(largest - steps.begin()) + 1;
                std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                                 steps.end());
                bs.medianStepS = steps[steps.size() / 2];
                if (!b.run) { // a historian run is put on its own grid, its gaps noted where it is cut
                    timingNotes(b, bs, gapRow < b.lineOfRow.size() ? b.lineOfRow[gapRow] : 0, s.notes);
                }
            }
        }
        for (std::size_t ci = 0; ci < b.numeric.size(); ++ci) {
            const auto& col = b.numeric[ci];
            const auto i = static_cast<std::size_t>(col.id);
            // The file's column: as read, else its place in the file order (a batch made in code).
            int fileColumn = col.fileColumn;
            if (fileColumn == 0 && !b.sourcePath.empty()) {
                const auto at = std::find(b.fileOrder.begin(), b.fileOrder.end(), static_cast<int>(ci));
                fileColumn = at == b.fileOrder.end() ? 0 : static_cast<int>(at - b.fileOrder.begin()) + 1;
            }
            auto& cs = s.columns[i];
            cs.present = true;
            double low = 0, high = 0;
            if (possibleRange(col.id, low, high)) {
                for (std::size_t r = 0; r < col.values.size(); ++r) {
                    const double v = col.values[r];
                    if (!std::isnan(v) && (v < low || v > high)) {
                        ++s.impossibleTotal;
                        if (listed[i] < DataSetSummary::kMaxListedImpossible) {
                            ++listed[i];
                            s.impossible.push_back({b.sourcePath.empty() ? b.id : b.sourcePath,
                                                    r < b.lineOfRow.size() ? b.lineOfRow[r] : 0, fileColumn,
                                                    col.fileName, std::string(spec(col.id).name), v,
                                                    "must lie in [" + shortNumber(low) + ", " +
                                                        shortNumber(high) + "] " + cs.unit});
                        }
                    }
                }
            }
            emptyColumnNote(b, col, s);
            double batchSum = 0;
            std::size_t batchCount = 0;
            for (std::size_t r = 0; r < col.values.size(); ++r) {
                const double v = col.values[r];
                if (std::isnan(v)) {
                    ++cs.missing;
                    continue;
                }
                cs.min = std::min(cs.min, v);
                cs.max = std::max(cs.max, v);
                sum[i] += v;
                ++count[i];
                batchSum += v;
                ++batchCount;
            }
            if (batchCount > 0) {
                means[i] = batchSum / static_cast<double>(batchCount);
            }
            // Where the missing cells are, each place of the file once: a historian run is put
            // on a 1 s grid, so one missing 5 s sample empties several rows (listed four times
            // before) and a row between two samples belongs to the line after as much as before;
            // its reader records the file's own cells (b.missing).
            std::set<int> lines;
            if (b.run) {
                const std::string contractName(spec(col.id).name);
                for (const auto& m : b.missing) {
                    if (m.column == fileColumn && m.columnName == contractName) {
                        lines.insert(m.line);
                    }
                }
            } else {
                for (std::size_t r = 0; r < col.values.size(); ++r) {
                    if (std::isnan(col.values[r])) {
                        lines.insert(r < b.lineOfRow.size() ? b.lineOfRow[r] : 0);
                    }
                }
            }
            s.missingPlaces += lines.size();
            for (const int line : lines) {
                if (listedMissing[i] >= DataSetSummary::kMaxListedMissing) {
                    break;
                }
                ++listedMissing[i];
                s.missingCells.push_back({b.sourcePath.empty() ? b.id : b.sourcePath, line, fileColumn,
                                          col.fileName, std::string(spec(col.id).name)});
            }
        }
        for (const auto& t : b.text) {
            extras.insert(t.fileName);
            for (const auto& contract : columnSpecs()) {
                if (!contract.required && !b.values(contract.id) &&
                    headerLooksLike(t.fileName, contract.id)) {
                    lookalikes[{t.fileName, contract.id}].push_back(b.sourcePath.empty() ? b.id
                                                                                         : b.sourcePath);
                }
            }
        }
        // A file's missing cells in the order an editor shows them.
        std::sort(s.missingCells.begin() + static_cast<std::ptrdiff_t>(missingBefore), s.missingCells.end(),
                  [](const MissingCellPlace& a, const MissingCellPlace& c) {
                      return std::tie(a.line, a.fileColumn) < std::tie(c.line, c.fileColumn);
                  });
        s.rows += bs.rows;
        s.missing += bs.missing;
        s.batches.push_back(bs);
    }
    for (std::size_t i = 0; i < s.columns.size(); ++i) {
        auto& c = s.columns[i];
        if (count[i] > 0) {
            c.mean = sum[i] / static_cast<double>(count[i]);
        } else {
            c.min = c.max = c.mean = std::numeric_limits<double>::quiet_NaN();
        }
    }
    s.extraColumns.assign(extras.begin(), extras.end());
    plausibilityNotes(batchMeans, batchPlaces, s.notes);
    batchAgainstOthersNotes(batchMeans, batchPlaces, s.notes);
    for (const auto& [key, files] : lookalikes) {
        const auto& [header, id] = key;
        const ColumnSpec& contract = spec(id);
        const std::string where =
            files.front() + (files.size() > 1 ? " and " + std::to_string(files.size() - 1) + " more" : "");
        s.notes.push_back(where + ": column '" + header +
                          "' is not a contract column and is kept as text; it looks like '" +
                          std::string(contract.name) + "' [" + std::string(contract.unit) + ", " +
                          std::string(contract.meaning) + "], which therefore counts as absent (" +
                          std::string(contract.defaultReason) + "). Rename the header to '" +
                          std::string(contract.name) + "' or give a column mapping.");
    }
    return s;
}

} // namespace drytwin::data
