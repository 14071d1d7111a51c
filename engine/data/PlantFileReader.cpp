// Plant files as historians export them (CONTRACT.md §1; the rules in docs/historian-files.md).
// This file puts the pieces of data/historian/ together: decode the text, look at its shape, lay
// out its columns, read every row once (the clock checked as it goes), then decide the number
// format on the whole file and cut the rows into production runs.
#include "data/PlantFileReader.h"

#include "data/historian/ClockSteps.h"
#include "data/historian/CsvLines.h"
#include "data/historian/LineLengthGuard.h"
#include "data/historian/NarrowLayout.h"
#include "data/historian/NumberFormat.h"
#include "data/historian/PlaceInFile.h"
#include "data/historian/RunSegmentation.h"
#include "data/historian/TextDecoding.h"
#include "data/historian/TimeFormatDetection.h"
#include "data/historian/ValueColumns.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <map>
#include <optional>

namespace drytwin::data {

using namespace historian;

namespace {

/// Relative time (in units of @p scale seconds) may group thousands ("1.000" after "999" in a
/// German export): an ambiguous cell takes the reading nearer the stamp the last step leads to expect.
double relativeSeconds(const NumberCell& n, double scale, const std::vector<RowStamp>& rows,
                       double lastStep) {
    const bool ambiguous =
        n.marks == NumberMarks::PointOrThousands || n.marks == NumberMarks::CommaOrThousands;
    if (!ambiguous || rows.empty()) {
        return n.value * scale;
    }
    const double expected = rows.back().t + lastStep;
    const double asDecimal = n.value * scale, asGrouped = thousandsValue(n.value) * scale;
    return std::abs(asGrouped - expected) < std::abs(asDecimal - expected) ? asGrouped : asDecimal;
}

/// The rows of a historian export (UTF-8 @p text of shape result.shape) into runs.
Expected<PlantFileRuns> readHistorianRows(const std::string& text, const std::string& file,
                                          const ColumnMapping& mapping, const Progress& progress,
                                          PlantFileRuns result) {
    FileShape& shape = result.shape;
    const RunSplitOptions& runs = mapping.runs;
    auto laidOut = layOutColumns(shape, mapping, file);
    if (!laidOut) {
        return laidOut.error();
    }
    ColumnLayout& layout = *laidOut;
    result.notes.insert(result.notes.end(), layout.notes.begin(), layout.notes.end());
    std::vector<ValueColumn>& columns = layout.values;
    const std::size_t nCols = shape.headers.size();
    const std::size_t timeIndex = layout.timeIndex;
    const std::size_t batchIndex = layout.batchIndex;
    const int timeColumn = static_cast<int>(timeIndex) + 1;

    // One pass over the lines.
    std::vector<RowStamp> rows;
    std::vector<std::string> batchIds;
    std::map<std::string, int> batchIdIndex;
    std::vector<std::size_t> clockJumpBefore; // row indices where daylight saving set the clock back
    std::vector<std::string> metadata;
    ClockWatch clock(file, timeColumn, shape.timeFormat, std::max(60.0, runs.maxInterpolatedGapS));
    DatelessDays dateless(file, timeColumn, shape.timeHeader);
    CsvLineSplitter split(shape.delimiter);
    LineCursor lines(text);
    std::string_view line;
    bool headerDone = false, unitsDone = !shape.unitsRow;
    double lastStep = runs.stepS;
    Error cellError;
    std::size_t nextProgress = 0;
    rows.reserve(text.size() / 64);
    for (auto& c : columns) {
        c.values.reserve(text.size() / 64);
    }
    while (lines.next(line)) {
        const int lineNo = lines.lineNumber();
        if (lines.position() >= nextProgress) {
            nextProgress = lines.position() + (1u << 20);
            if (reportProgress(progress, "load",
                               0.9 * static_cast<double>(lines.position()) / static_cast<double>(text.size()),
                               std::filesystem::path(file).filename().string())) {
                return cancelledError("load");
            }
        }
        const auto t = trimmed(line);
        if (t.empty()) {
            continue;
        }
        if (!headerDone) {
            if (t.front() == '#') {
                metadata.emplace_back(t);
                continue;
            }
            headerDone = true;
            continue;
        }
        if (!unitsDone) {
            unitsDone = true;
            continue;
        }
        if (!split.split(line)) {
            return fileError(file, lineNo, 1, "malformed CSV (an unclosed quote?)");
        }
        const auto& fields = split.fields();
        if (fields.size() != nCols) {
            return fileError(file, lineNo, static_cast<int>(std::min(fields.size(), nCols)) + 1,
                             "expected " + std::to_string(nCols) + " fields as in the header, found " +
                                 std::to_string(fields.size()) + " (" + delimiterName(shape.delimiter) +
                                 "-separated)");
        }
        RowStamp r;
        r.line = lineNo;
        TimeStamp stamp;
        StampReading reading = StampReading::NotThisFormat;
        std::string impossible;
        if (shape.timeFormat == TimeFormat::Seconds) {
            const NumberCell n = readNumberCell(fields[timeIndex]);
            reading = n.isNumber ? StampReading::Read : StampReading::NotThisFormat;
            stamp.seconds = n.isNumber ? relativeSeconds(n, layout.timeScale, rows, lastStep) : 0;
        } else {
            reading = readTimeStamp(fields[timeIndex], shape.timeFormat, stamp, &impossible);
        }
        if (reading == StampReading::ImpossibleDate) {
            return fileError(file, lineNo, timeColumn, impossibleStampReason(fields[timeIndex], impossible));
        }
        if (reading != StampReading::Read) {
            return fileError(file, lineNo, timeColumn,
                             "bad time stamp '" + std::string(trimmed(fields[timeIndex])) +
                                 "' (the column is " + timeFormatName(shape.timeFormat) +
                                 "; if that is wrong, name the format in the column mapping: \"time_s\": "
                                 "{\"header\": \"" +
                                 shape.timeHeader + "\", \"format\": …})");
        }
        if (auto placed = dateless.place(stamp, lineNo, fields[timeIndex]); !placed) {
            return placed.error();
        }
        r.t = stamp.seconds;
        bool batchChanged = false;
        if (batchIndex < nCols) {
            const std::string id(trimmed(fields[batchIndex]));
            auto [it, inserted] = batchIdIndex.emplace(id, static_cast<int>(batchIds.size()));
            if (inserted) {
                batchIds.push_back(id);
            }
            r.batch = it->second;
            batchChanged = !rows.empty() && rows.back().batch != r.batch;
        }
        auto step = clock.step(stamp, lineNo, batchChanged);
        if (!step) {
            return step.error();
        }
        if (*step == ClockStep::Duplicate) {
            continue;
        }
        if (*step == ClockStep::DaylightSavingEnd) {
            clockJumpBefore.push_back(rows.size());
        }
        if (*step == ClockStep::Forward) {
            lastStep = r.t - rows.back().t;
        }
        for (auto& c : columns) {
            if (!c.readCell(fields[c.field], lineNo, file, cellError)) {
                return cellError;
            }
        }
        rows.push_back(r);
    }
    for (auto& n : dateless.notes()) {
        result.notes.push_back(std::move(n));
    }
    for (auto& n : clock.notes()) {
        result.notes.push_back(std::move(n));
    }
    shape.timesOfDayOnly = dateless.timesOfDayOnly();
    if (rows.empty()) {
        return fileError(file, lines.lineNumber(), 1, "the file has a header but no data rows");
    }
    auto mark = finishColumns(columns, mapping, shape, file, result.notes);
    if (!mark) {
        return mark.error();
    }
    shape.decimalComma = *mark == ',';

    // Where runs end: daylight-saving steps, batch-id changes, gaps, line stops.
    const std::vector<double>* feed = nullptr;
    for (const auto& c : columns) {
        if (c.contract == Column::Feed) {
            feed = &c.values;
        }
    }
    // An export sampled more slowly than the longest gap bridged (every 15, 30 or 60 s against
    // 10 s) would be nothing but gaps, and was refused as "no production run … check the feed":
    // its own step is not a gap. Gaps then count from 2.5 steps, and each run is interpolated
    // onto the grid as any other, with a note.
    RunSplitOptions bySampling = runs;
    {
        std::vector<double> times;
        times.reserve(rows.size());
        for (const auto& r : rows) {
            times.push_back(r.t);
        }
        const double step = medianPositiveStep(times); // -1 when time never moves on
        if (step > runs.maxInterpolatedGapS) {
            bySampling.maxInterpolatedGapS = 2.5 * step;
            char text[320];
            std::snprintf(text, sizeof text,
                          ": rows are %.4g s apart (median), more than the %.4g s bridged across a gap "
                          "(\"runs\": {\"max_interpolated_gap_s\"}): a gap counts from %.4g s here, "
                          "and each run is interpolated onto the %.4g s grid",
                          step, runs.maxInterpolatedGapS, bySampling.maxInterpolatedGapS, runs.stepS);
            result.notes.push_back(file + text);
        }
    }
    const std::vector<RowSpan> spans = cutIntoRuns(rows, feed, clockJumpBefore, bySampling);

    // Each run onto the step's grid.
    resampleRuns(spans, rows, columns, batchIds, metadata, shape, file, bySampling, result.runs,
                 result.notes);
    if (result.runs.empty()) {
        return fileError(file, rows.front().line, 1,
                         "no production run: every stretch of the file is a line stop (feed below " +
                             std::to_string(static_cast<long>(runs.lineStopFeedKgPerHour)) +
                             " kg/h) or shorter than " + std::to_string(static_cast<long>(runs.minRunS)) +
                             " s; check the feed column's values and unit, or the \"runs\" settings of the "
                             "column mapping");
    }
    reportProgress(progress, "load", 1.0);
    return result;
}

/// A date-only cell ("28.11.2026", "2026-11-28", "11/28/2026").
bool isDateOnly(std::string_view cell) {
    const auto t = trimmed(cell);
    if (t.size() < 8 || t.size() > 10) {
        return false;
    }
    int digits = 0, marks = 0;
    for (char c : t) {
        digits += std::isdigit(static_cast<unsigned char>(c)) ? 1 : 0;
        marks += (c == '.' || c == '-' || c == '/') ? 1 : 0;
    }
    return marks == 2 && digits + marks == static_cast<int>(t.size());
}

/// A time of day ("13:05:01", "8:00", "13:05:01.250").
bool isTimeOfDay(std::string_view cell) {
    const auto t = trimmed(cell);
    int colons = 0;
    for (char c : t) {
        if (c == ':') {
            ++colons;
        } else if (!std::isdigit(static_cast<unsigned char>(c)) && c != '.') {
            return false;
        }
    }
    return (colons == 1 || colons == 2) && t.size() >= 4 && t.size() <= 15;
}

/// @p text with a date column and the time-of-day column after it joined into one stamp column
/// (the delimiter between them a space on every line), and the note; nothing where the file's
/// first stamp is not so written, or where a quote could hide a delimiter.
std::optional<std::pair<std::string, std::string>> joinDateAndTimeColumns(const std::string& text,
                                                                          const std::string& file) {
    LineCursor lines(text);
    std::string_view line, header, first;
    while (lines.next(line)) {
        const auto t = trimmed(line);
        if (t.empty() || t.front() == '#') {
            continue;
        }
        if (header.empty()) {
            header = line;
        } else {
            first = line;
            break;
        }
    }
    if (header.empty() || first.empty()) {
        return std::nullopt;
    }
    const char delimiter = detectDelimiter(header);
    const auto fieldsOf = [delimiter](std::string_view l) {
        std::vector<std::string_view> out;
        std::size_t start = 0;
        for (std::size_t i = 0; i <= l.size(); ++i) {
            if (i == l.size() || l[i] == delimiter) {
                out.push_back(l.substr(start, i - start));
                start = i + 1;
            }
        }
        return out;
    };
    const auto names = fieldsOf(header);
    const auto cells = fieldsOf(first);
    std::size_t at = names.size();
    for (std::size_t c = 0; c + 1 < names.size() && c + 1 < cells.size(); ++c) {
        if (namedLikeTime(std::string(trimmed(names[c]))) &&
            namedLikeTime(std::string(trimmed(names[c + 1]))) && isDateOnly(cells[c]) &&
            isTimeOfDay(cells[c + 1])) {
            at = c;
            break;
        }
    }
    // Only now the whole text (a month at 1 s is half a gigabyte): a quote could hide a delimiter.
    if (at == names.size() || text.find('"') != std::string::npos) {
        return std::nullopt;
    }
    // Every line's delimiter after field `at` becomes a space (comment lines stay as they are).
    std::string out;
    out.reserve(text.size());
    std::size_t pos = 0;
    while (pos < text.size()) {
        std::size_t end = text.find('\n', pos);
        end = end == std::string::npos ? text.size() : end + 1;
        std::string_view l(text.data() + pos, end - pos);
        const auto t = trimmed(l);
        if (!t.empty() && t.front() != '#') {
            std::size_t seen = 0;
            for (std::size_t i = 0; i < l.size(); ++i) {
                if (l[i] == delimiter && seen++ == at) {
                    out.append(l.substr(0, i));
                    out.push_back(' ');
                    out.append(l.substr(i + 1));
                    l = {};
                    break;
                }
            }
        }
        out.append(l);
        pos = end;
    }
    return std::make_pair(std::move(out), file + ": the date and the time of day in two columns ('" +
                                              std::string(trimmed(names[at])) + "', '" +
                                              std::string(trimmed(names[at + 1])) +
                                              "'), read as one time stamp");
}

} // namespace

Expected<PlantFileRuns> parsePlantText(const std::string& raw, const std::string& file,
                                       const ReadOptions& options, const Progress& progress) {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    auto decoded = decodeText(raw, file);
    if (!decoded) {
        return decoded.error();
    }
    PlantFileRuns result;
    result.notes = decoded->notes;
    // A last line without a line end may be a line cut off while the file was written or copied
    // ("…,12.888,5" for 58.4 loaded as 5 °C with exit 0 in a fresh user's test): it is left out,
    // with a note, where complete lines come before it.
    const std::string* body = &decoded->text(raw); // without a byte-order mark (decodeText)
    std::string withoutCutLine;
    if (!body->empty() && body->back() != '\n' && body->back() != '\r') {
        const char lineEnd = body->find('\n') != std::string::npos ? '\n' : '\r';
        const auto breaks = static_cast<int>(std::count(body->begin(), body->end(), lineEnd));
        if (breaks >= 2) {
            withoutCutLine = body->substr(0, body->find_last_of(lineEnd) + 1);
            result.notes.push_back(placeInFile(file, breaks + 1, 1) +
                                   ": the last line has no line end; it may have been cut off while the "
                                   "file was written or copied, and is left out");
            body = &withoutCutLine;
        }
    }
    // Title lines above the header (PI DataLink's "PI DataLink export", "Server: …", "Start: …"):
    // lines without two separators before the first line that has them are read as comments, with
    // a note. Taken for the header, the first one made the file "missing required column 'time_s'".
    std::string withTitlesAsComments;
    {
        std::vector<std::size_t> titleStarts;
        int firstTitleLine = 0, lastTitleLine = 0, lineNo = 0;
        bool headerFound = false;
        std::size_t headerAt = 0;
        for (std::size_t pos = 0; pos < body->size() && titleStarts.size() <= 20;) {
            std::size_t end = body->find('\n', pos);
            end = end == std::string::npos ? body->size() : end;
            const auto t = trimmed(std::string_view(body->data() + pos, end - pos));
            ++lineNo;
            if (!t.empty() && t.front() != '#') {
                const auto separators = std::count_if(
                    t.begin(), t.end(), [](char c) { return c == ',' || c == ';' || c == '\t' || c == '|'; });
                if (separators >= 2) {
                    headerFound = true;
                    headerAt = pos;
                    break;
                }
                titleStarts.push_back(pos);
                firstTitleLine = firstTitleLine == 0 ? lineNo : firstTitleLine;
                lastTitleLine = lineNo;
            }
            pos = end + 1;
        }
        if (headerFound && !titleStarts.empty() && titleStarts.size() <= 20) {
            // The lines above the header rebuilt, the rest copied once (a month's export is large).
            withTitlesAsComments.reserve(body->size() + 2 * titleStarts.size());
            std::size_t copied = 0;
            for (const std::size_t start : titleStarts) {
                withTitlesAsComments.append(*body, copied, start - copied);
                withTitlesAsComments.append("# ");
                copied = start;
            }
            withTitlesAsComments.append(*body, copied, headerAt - copied);
            withTitlesAsComments.append(*body, headerAt, std::string::npos);
            result.notes.push_back(
                file + ":" + std::to_string(firstTitleLine) +
                (lastTitleLine > firstTitleLine ? "-" + std::to_string(lastTitleLine) : "") +
                ": title lines above the header (no separators), read as comments");
            body = &withTitlesAsComments;
        }
    }
    // The date and the time of day in two columns (`Datum;Uhrzeit`, `Date,Time`), as Excel and
    // some SCADA exports write them: read as one stamp, "28.11.2026 13:05:01", with a note.
    // "'28.11.2026' is not a time stamp" said nothing of the column beside it.
    std::string withDateAndTimeJoined;
    if (auto joined = joinDateAndTimeColumns(*body, file)) {
        withDateAndTimeJoined = std::move(joined->first);
        result.notes.push_back(std::move(joined->second));
        body = &withDateAndTimeJoined;
    }
    // A tag/value export (one row per tag and stamp) is read as the wide table it stands for.
    auto narrow = pivotNarrowExport(*body, file, options.mapping.runs.maxInterpolatedGapS);
    if (!narrow) {
        return narrow.error();
    }
    if (*narrow) {
        for (auto& n : (*narrow)->notes) {
            result.notes.push_back(std::move(n));
        }
    }
    const std::string& text = *narrow ? (*narrow)->wideText : *body;
    auto sniffed = sniffPlantText(text, file, options.mapping);
    if (!sniffed || !sniffed->historian) {
        // The contract's own form, or neither shape fits: the batch reader accepts what it can;
        // otherwise the plant-file reader's reason (time column, format) is the one a historian
        // export needs.
        auto one = parseBatchText(text, file, options);
        if (!one) {
            // A contract header with no row under it is that, not a time column the historian
            // reader could not read ("no time stamps in the first rows" said a review's file).
            const bool contractWithoutRows = one.error().code == ErrorCode::NotEnoughData;
            return !sniffed && sniffed.error().code != ErrorCode::MissingColumn && !contractWithoutRows
                       ? sniffed.error()
                       : one.error();
        }
        if (sniffed) {
            result.shape = *sniffed;
        }
        result.runs.push_back(std::move(*one));
        return result;
    }
    result.shape = *sniffed;
    return readHistorianRows(text, file, options.mapping, progress, std::move(result));
}

Expected<PlantFileRuns> readPlantFile(const std::string& path, const ReadOptions& options,
                                      const Progress& progress) {
    // Read with the line limit checked as the bytes come: a file without line breaks is refused
    // after the limit, whatever its size.
    auto text = readFileWithLineLimit(path);
    if (!text) {
        return text.error();
    }
    return parsePlantText(*text, path, options, progress);
}

Expected<std::string> readPlantFileHead(const std::string& path, std::size_t maxBytes) {
    return readFileWithLineLimit(path, kMaxLineBytes, maxBytes);
}

} // namespace drytwin::data
