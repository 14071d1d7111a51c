// Tag/value exports: PI's "Archive data" and its SDK, Wonderware's History queries and WinCC's
// archive exports write one row per tag and time stamp. The reader knows the wide layout (one
// column per tag), so such a file is pivoted first, in memory: its tags become the columns that
// the column mapping maps, its stamps the rows, in the order of time. Hand-written: it is a group-
// by of three columns; a data-frame library would be a large dependency for it.
#include "data/historian/NarrowLayout.h"

#include "data/historian/CsvLines.h"
#include "data/historian/PlaceInFile.h"
#include "data/historian/TimeFormatDetection.h"
#include "data/historian/TimeStamps.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <set>
#include <unordered_map>

namespace drytwin::data::historian {

namespace {

bool namedLikeTag(const std::string& header) {
    static const std::set<std::string> names{"tag",      "tagname",   "tag name",   "tag_name", "name",
                                             "point",    "pointname", "point name", "item",     "itemname",
                                             "variable", "signal",    "valuename",  "位号",     "标签"};
    return names.count(lowerAscii(trimmed(header))) > 0;
}

bool namedLikeValue(const std::string& header) {
    static const std::set<std::string> names{"value", "val", "wert", "valeur", "pv", "数值", "值"};
    return names.count(lowerAscii(trimmed(header))) > 0;
}

/// A column a tag/value export writes beside its time, tag and value: the sample's quality or
/// status, the tag's unit or description, the time zone (Wonderware's History writes
/// `DateTime,TagName,Value,Quality,QualityDetail,OPCQuality,wwTimeZone`).
bool namedLikeSampleMetadata(const std::string& header) {
    const std::string h = lowerAscii(trimmed(header));
    for (const char* word : {"quality", "status", "unit", "zone", "flag", "annotation", "description",
                             "comment", "version", "state"}) {
        if (h.find(word) != std::string::npos) {
            return true;
        }
    }
    return false;
}

/// A cell for the wide text: quoted when it holds the delimiter or a quote.
std::string csvCell(std::string_view cell, char delimiter) {
    if (cell.find(delimiter) == std::string_view::npos && cell.find('"') == std::string_view::npos) {
        return std::string(cell);
    }
    std::string out = "\"";
    for (char c : cell) {
        out += c;
        if (c == '"') {
            out += '"';
        }
    }
    return out + "\"";
}

struct Row {
    int line = 0;
    std::string time, tag, value;
};

} // namespace

Expected<std::optional<NarrowPivot>> pivotNarrowExport(const std::string& text, const std::string& file,
                                                       double maxHoldS) {
    LineCursor lines(text);
    std::string_view line;
    std::vector<std::string> metadata;
    bool haveHeader = false;
    while (lines.next(line)) {
        const auto t = trimmed(line);
        if (t.empty()) {
            continue;
        }
        if (t.front() == '#') {
            metadata.emplace_back(t);
            continue;
        }
        haveHeader = true;
        break;
    }
    if (!haveHeader) {
        return std::optional<NarrowPivot>();
    }
    const int headerLine = lines.lineNumber();
    const char delimiter = detectDelimiter(line);
    CsvLineSplitter split(delimiter);
    if (!split.split(line)) {
        return std::optional<NarrowPivot>();
    }
    std::vector<std::string> headers;
    for (const auto& f : split.fields()) {
        headers.emplace_back(trimmed(f));
    }
    // The layout: a time, a tag and a value column, and at most a few more (quality, status, unit).
    constexpr std::size_t kNone = static_cast<std::size_t>(-1);
    std::size_t timeAt = kNone, tagAt = kNone, valueAt = kNone;
    for (std::size_t i = 0; i < headers.size(); ++i) {
        if (timeAt == kNone && namedLikeTime(headers[i])) {
            timeAt = i;
        } else if (tagAt == kNone && namedLikeTag(headers[i])) {
            tagAt = i;
        } else if (valueAt == kNone && namedLikeValue(headers[i])) {
            valueAt = i;
        }
    }
    // More than six columns only where every other one describes the sample (a wide file with a
    // "Value" column among its tags is not one): Wonderware's seven were refused as a wide file
    // whose tags needed mapping.
    const auto othersDescribeTheSample = [&] {
        for (std::size_t i = 0; i < headers.size(); ++i) {
            if (i != timeAt && i != tagAt && i != valueAt && !namedLikeSampleMetadata(headers[i])) {
                return false;
            }
        }
        return true;
    };
    if (headers.size() < 3 || timeAt == kNone || tagAt == kNone || valueAt == kNone ||
        (headers.size() > 6 && (headers.size() > 12 || !othersDescribeTheSample()))) {
        return std::optional<NarrowPivot>();
    }

    std::vector<Row> rows;
    std::vector<std::string_view> firstStamps;
    std::vector<std::string> stampSample;
    while (lines.next(line)) {
        if (trimmed(line).empty()) {
            continue;
        }
        if (!split.split(line)) {
            return fileError(file, lines.lineNumber(), 1, "malformed CSV (an unclosed quote?)");
        }
        const auto& f = split.fields();
        if (f.size() != headers.size()) {
            return fileError(file, lines.lineNumber(),
                             static_cast<int>(std::min(f.size(), headers.size())) + 1,
                             "expected " + std::to_string(headers.size()) +
                                 " fields as in the header of this "
                                 "tag/value export, found " +
                                 std::to_string(f.size()));
        }
        Row r{lines.lineNumber(), std::string(trimmed(f[timeAt])), std::string(trimmed(f[tagAt])),
              std::string(trimmed(f[valueAt]))};
        if (r.tag.empty()) {
            return fileError(file, r.line, static_cast<int>(tagAt) + 1, "the tag is empty");
        }
        rows.push_back(std::move(r));
    }
    if (rows.empty()) {
        return fileError(file, headerLine, 1, "the tag/value export has a header but no data rows");
    }
    // The stamps' format from the first of them, as for a wide file's time column.
    for (std::size_t i = 0; i < rows.size() && stampSample.size() < 200; ++i) {
        stampSample.push_back(rows[i].time);
    }
    for (const auto& s : stampSample) {
        firstStamps.emplace_back(s);
    }
    const TimeFormatGuess guess = detectTimeFormat(firstStamps, headers[timeAt]);
    std::optional<TimeFormat> format = guess.format;
    if (!format && guess.dayOrMonthFirst) {
        DayMonthOrderVote vote;
        for (const auto& r : rows) {
            vote.add(r.time);
        }
        std::string why;
        format = vote.decide(headers[timeAt], why);
        if (!format) {
            return fileError(file, rows.front().line, static_cast<int>(timeAt) + 1, why);
        }
    }
    if (!format) {
        return fileError(file, rows.front().line, static_cast<int>(timeAt) + 1,
                         "time column '" + headers[timeAt] + "': " + guess.why);
    }

    // Group by stamp (in time order) and tag (in the order they first appear).
    std::map<double, std::string> stampText; // seconds → the stamp as the file writes it
    std::vector<std::string> tags;
    std::unordered_map<std::string, std::size_t> tagIndex;
    std::map<std::pair<double, std::size_t>, std::string> cells;
    std::size_t repeated = 0;
    for (const auto& r : rows) {
        TimeStamp stamp;
        std::string impossible;
        const StampReading reading = readTimeStamp(r.time, *format, stamp, &impossible);
        if (reading == StampReading::ImpossibleDate) {
            return fileError(file, r.line, static_cast<int>(timeAt) + 1,
                             impossibleStampReason(r.time, impossible));
        }
        if (reading != StampReading::Read) {
            return fileError(file, r.line, static_cast<int>(timeAt) + 1,
                             "bad time stamp '" + r.time + "' (the column is " + timeFormatName(*format) +
                                 ")");
        }
        stampText.emplace(stamp.seconds, r.time);
        const auto [it, inserted] = tagIndex.emplace(r.tag, tags.size());
        if (inserted) {
            tags.push_back(r.tag);
        }
        const auto [cell, fresh] = cells.insert_or_assign({stamp.seconds, it->second}, r.value);
        repeated += fresh ? 0 : 1;
    }

    NarrowPivot out;
    out.tags = tags.size();
    out.stamps = stampText.size();
    for (const auto& m : metadata) {
        out.wideText += m + "\n";
    }
    out.wideText += csvCell(headers[timeAt], delimiter);
    for (const auto& t : tags) {
        out.wideText += delimiter + csvCell(t, delimiter);
    }
    out.wideText += "\n";
    // A tag with no sample at a stamp holds its last sample, as a historian's deadband or
    // exception reporting means (the value did not move by more than the band), for at most
    // maxHoldS; beyond that, or before its first sample, the cell stays empty (a gap).
    std::size_t held = 0, empty = 0;
    std::vector<const std::string*> last(tags.size(), nullptr);
    std::vector<double> lastAt(tags.size(), 0);
    for (const auto& [seconds, stampAsWritten] : stampText) {
        out.wideText += csvCell(stampAsWritten, delimiter);
        for (std::size_t t = 0; t < tags.size(); ++t) {
            out.wideText += delimiter;
            const auto c = cells.find({seconds, t});
            if (c != cells.end()) {
                out.wideText += csvCell(c->second, delimiter);
                last[t] = &c->second;
                lastAt[t] = seconds;
            } else if (last[t] && seconds - lastAt[t] <= maxHoldS) {
                out.wideText += csvCell(*last[t], delimiter);
                ++held;
            } else {
                ++empty;
            }
        }
        out.wideText += "\n";
    }
    char note[400];
    std::snprintf(
        note, sizeof note,
        "%s: a tag/value export (one row per tag and time stamp: columns '%s', '%s', '%s'), read as "
        "one column per tag: %zu tags over %zu time stamps; %zu cells where a tag has no sample at a "
        "stamp hold its last sample (at most %.0f s back), %zu are left empty; places in later "
        "messages count rows of that table",
        file.c_str(), headers[timeAt].c_str(), headers[tagAt].c_str(), headers[valueAt].c_str(), tags.size(),
        stampText.size(), held, maxHoldS, empty);
    out.notes.emplace_back(note);
    // Many empty cells are a tag reporting only on change for longer than the hold: the rows
    // where they fall are left out by the cleaning (a fresh user's deadband export kept 32 %).
    if (empty * 10 > (held + empty + cells.size())) {
        out.notes.push_back(
            file + ": " + std::to_string(empty) +
            " cells are left empty: where a tag reports only on change (exception reporting, a "
            "deadband), give the historian's longest report interval as \"runs\": "
            "{\"max_interpolated_gap_s\": …} in the column mapping so that each holds its value "
            "that long");
    }
    if (repeated > 0) {
        out.notes.push_back(file + ": " + std::to_string(repeated) +
                            " rows repeat a tag at a time stamp already read; the later value is kept");
    }
    return std::optional<NarrowPivot>(std::move(out));
}

} // namespace drytwin::data::historian
