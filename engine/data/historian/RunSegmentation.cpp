#include "data/historian/RunSegmentation.h"

#include "data/historian/PlaceInFile.h"
#include "data/historian/TimeStamps.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <map>

namespace drytwin::data::historian {

std::vector<RowSpan> cutIntoRuns(const std::vector<RowStamp>& rows, const std::vector<double>* feed,
                                 const std::vector<std::size_t>& clockJumpBefore,
                                 const RunSplitOptions& runs) {
    const std::size_t n = rows.size();
    std::vector<char> inStop(n, 0);
    if (feed) {
        const auto& f = *feed;
        for (std::size_t i = 0; i < n;) {
            if (!(f[i] < runs.lineStopFeedKgPerHour)) {
                ++i;
                continue;
            }
            std::size_t j = i;
            while (j < n && f[j] < runs.lineStopFeedKgPerHour) {
                ++j;
            }
            if (rows[j - 1].t - rows[i].t + runs.stepS >= runs.minStopS) {
                std::fill(inStop.begin() + static_cast<long>(i), inStop.begin() + static_cast<long>(j), 1);
            }
            i = j;
        }
    }
    std::vector<RowSpan> spans;
    std::size_t jump = 0;
    for (std::size_t i = 0; i < n;) {
        if (inStop[i]) {
            ++i;
            continue;
        }
        RowSpan s{i, i + 1, "end of file"};
        while (s.end < n) {
            const std::size_t k = s.end;
            if (inStop[k]) {
                s.reason = "line stop";
                break;
            }
            if (jump < clockJumpBefore.size() && clockJumpBefore[jump] == k) {
                s.reason = "clock jump";
                break;
            }
            if (rows[k].batch != rows[k - 1].batch) {
                s.reason = "batch id";
                break;
            }
            if (rows[k].t - rows[k - 1].t > runs.maxInterpolatedGapS) {
                s.reason = "gap";
                break;
            }
            ++s.end;
        }
        while (jump < clockJumpBefore.size() && clockJumpBefore[jump] <= s.end) {
            ++jump;
        }
        spans.push_back(s);
        i = s.end;
    }
    return spans;
}

void resampleRuns(const std::vector<RowSpan>& spans, const std::vector<RowStamp>& rows,
                  std::vector<ValueColumn>& columns, const std::vector<std::string>& batchIds,
                  const std::vector<std::string>& metadata, const FileShape& shape, const std::string& file,
                  const RunSplitOptions& runs, std::vector<Batch>& out, std::vector<std::string>& notes) {
    const std::string stem = std::filesystem::path(file).stem().string();
    std::map<std::string, int> idUses;
    int runNumber = 0;
    const auto startOf = [&](double t) {
        if (shape.timeFormat == TimeFormat::Seconds) {
            char buf[48];
            std::snprintf(buf, sizeof buf, "t = %.3f s", t);
            return std::string(buf);
        }
        if (shape.timesOfDayOnly) {
            return timeOfDayText(t) + " (no date)";
        }
        return isoTimestamp(t);
    };
    // Every run's grid first, then column by column into all runs, each source column freed
    // once used: the numbers of a month at 1 s are held once and a column more, not twice.
    struct Grid {
        std::vector<std::size_t> before; // the sample at or before each grid row
        std::vector<double> weight;      // 0: on that sample; else the share towards the next
    };
    std::vector<Grid> grids;
    const std::size_t firstRun = out.size();
    for (const auto& s : spans) {
        const double t0 = rows[s.begin].t;
        const double span = rows[s.end - 1].t - t0;
        if (span + runs.stepS < runs.minRunS) {
            notes.push_back(placeInFile(file, rows[s.begin].line, 1) + "-" +
                            std::to_string(rows[s.end - 1].line) + ": a run of " +
                            std::to_string(static_cast<long>(std::lround(span + runs.stepS))) +
                            " s is shorter than the minimum of " +
                            std::to_string(static_cast<long>(runs.minRunS)) + " s; left out");
            continue;
        }
        ++runNumber;
        Batch b;
        b.sourcePath = file;
        std::string id;
        if (rows[s.begin].batch >= 0) {
            id = batchIds[static_cast<std::size_t>(rows[s.begin].batch)];
            const int use = ++idUses[id];
            if (use > 1) {
                id += "_" + std::to_string(use);
            }
        } else {
            char buf[16];
            std::snprintf(buf, sizeof buf, "_R%02d", runNumber);
            id = stem + buf;
        }
        b.id = id;
        RunSource src;
        src.file = file;
        src.firstLine = rows[s.begin].line;
        src.lastLine = rows[s.end - 1].line;
        src.startTimestamp = startOf(t0);
        src.samples = s.end - s.begin;
        src.splitReason = s.reason;
        const auto gridRows = static_cast<std::size_t>(std::floor(span / runs.stepS + 1e-9)) + 1;
        std::vector<double> time(gridRows);
        b.lineOfRow.resize(gridRows);
        Grid g;
        g.before.resize(gridRows);
        g.weight.resize(gridRows);
        std::size_t j = s.begin;
        const double eps = 1e-3 * runs.stepS; // stamps rounded to a millisecond are on the grid
        for (std::size_t k = 0; k < gridRows; ++k) {
            const double tg = t0 + static_cast<double>(k) * runs.stepS;
            time[k] = static_cast<double>(k) * runs.stepS;
            while (j + 1 < s.end && rows[j + 1].t <= tg + eps) {
                ++j;
            }
            g.before[k] = j;
            g.weight[k] = std::abs(rows[j].t - tg) <= eps || j + 1 >= s.end
                              ? 0.0
                              : (tg - rows[j].t) / (rows[j + 1].t - rows[j].t);
            b.lineOfRow[k] = rows[j].line;
        }
        b.metadataLines = metadata;
        b.metadataLines.push_back("# batch: " + id);
        b.metadataLines.push_back("# source: " + std::filesystem::path(file).filename().string() + " lines " +
                                  std::to_string(src.firstLine) + "-" + std::to_string(src.lastLine));
        b.metadataLines.push_back("# start: " + src.startTimestamp);
        const auto timeField = std::find(shape.headers.begin(), shape.headers.end(), shape.timeHeader);
        b.numeric.push_back({Column::Time, shape.timeHeader, std::move(time),
                             static_cast<int>(timeField - shape.headers.begin()) + 1});
        b.fileOrder.push_back(0);
        b.run = src;
        out.push_back(std::move(b));
        grids.push_back(std::move(g));
    }
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (auto& c : columns) {
        if (!c.numeric || !c.contract) {
            std::vector<double>().swap(c.values);
            continue; // extra columns of a historian export are not part of a run
        }
        const std::string name(spec(*c.contract).name);
        const int fileColumn = static_cast<int>(c.field) + 1;
        for (std::size_t r = firstRun; r < out.size(); ++r) {
            Batch& b = out[r];
            const Grid& g = grids[r - firstRun];
            RunSource& src = *b.run;
            std::vector<double> v(g.before.size(), nan);
            for (std::size_t k = 0; k < v.size(); ++k) {
                const std::size_t i = g.before[k];
                const double a = c.values[i];
                if (g.weight[k] == 0.0) {
                    v[k] = a;
                    if (std::isnan(a)) {
                        b.missing.push_back({rows[i].line, fileColumn, name});
                    }
                    continue;
                }
                const double z = c.values[i + 1];
                if (std::isfinite(a) && std::isfinite(z)) {
                    v[k] = a + g.weight[k] * (z - a);
                    ++src.interpolatedCells;
                } else {
                    ++src.gapCells;
                    // The sample that is missing: the one after where the one before has a value.
                    b.missing.push_back(
                        {std::isfinite(a) ? rows[i + 1].line : rows[i].line, fileColumn, name});
                }
            }
            b.fileOrder.push_back(static_cast<int>(b.numeric.size()));
            b.numeric.push_back({*c.contract, c.header, std::move(v), fileColumn});
        }
        std::vector<double>().swap(c.values);
    }
}

} // namespace drytwin::data::historian
