#include "data/historian/FileShape.h"

#include "data/historian/CsvLines.h"
#include "data/historian/NumberFormat.h"
#include "data/historian/PlaceInFile.h"
#include "data/historian/TimeFormatDetection.h"

#include <algorithm>

namespace drytwin::data {

using namespace historian;

namespace {

/// The time column: the mapping's, else time_s, else the first named like a time stamp that the
/// mapping does not give another column; headers.size() when there is none.
std::size_t findTimeColumn(const std::vector<std::string>& headers, const ColumnMapping& mapping) {
    const auto mapped = mapping.contractToFile.find("time_s");
    const std::string wanted = mapped != mapping.contractToFile.end() ? mapped->second : "time_s";
    for (std::size_t c = 0; c < headers.size(); ++c) {
        if (headers[c] == wanted) {
            return c;
        }
    }
    if (mapped == mapping.contractToFile.end()) {
        for (std::size_t c = 0; c < headers.size(); ++c) {
            if (namedLikeTime(headers[c]) && mapping.contractNameFor(headers[c]).empty()) {
                return c;
            }
        }
    }
    return headers.size();
}

/// A units row: text but no number in the value columns, and no time stamp.
bool looksLikeUnitsRow(const std::vector<std::string_view>& fields, std::size_t timeIndex) {
    int text = 0, numbers = 0;
    for (std::size_t c = 0; c < fields.size(); ++c) {
        if (c == timeIndex || trimmed(fields[c]).empty()) {
            continue;
        }
        std::string_view state;
        if (readNumberCell(fields[c]).isNumber) {
            ++numbers;
        } else if (!isMissingCell(fields[c], state)) {
            ++text;
        }
    }
    TimeStamp t;
    const bool timeLooksLikeStamp =
        timeIndex < fields.size() && (readNumberCell(fields[timeIndex]).isNumber ||
                                      parseTimeStamp(fields[timeIndex], TimeFormat::Iso8601, t));
    return text > 0 && numbers == 0 && !timeLooksLikeStamp;
}

} // namespace

Expected<FileShape> sniffPlantText(const std::string& text, const std::string& file,
                                   const ColumnMapping& mapping) {
    FileShape shape;
    LineCursor lines(text);
    std::string_view header, line;
    while (lines.next(line)) {
        const auto t = trimmed(line);
        if (t.empty() || t.front() == '#') {
            continue;
        }
        header = line;
        shape.headerLine = lines.lineNumber();
        break;
    }
    if (header.empty()) {
        return fileError(file, std::max(lines.lineNumber(), 1), 1, "no header row");
    }
    if (header.substr(0, 3) == "\xEF\xBB\xBF") {
        header.remove_prefix(3);
    }
    shape.delimiter = detectDelimiter(header);
    CsvLineSplitter split(shape.delimiter);
    if (!split.split(header)) {
        return fileError(file, shape.headerLine, 1, "malformed header row (an unclosed quote?)");
    }
    for (auto f : split.fields()) {
        shape.headers.emplace_back(trimmed(f));
    }
    const std::size_t timeIndex = findTimeColumn(shape.headers, mapping);
    if (timeIndex == shape.headers.size()) {
        const auto mapped = mapping.contractToFile.find("time_s");
        if (mapped != mapping.contractToFile.end()) {
            const std::string near = closestHeader(mapped->second, shape.headers);
            return fileError(
                file, shape.headerLine, 1,
                "the column mapping" + (mapping.sourceName.empty() ? "" : " " + mapping.sourceName) +
                    " names the time column '" + mapped->second + "', which the header row lacks" +
                    (near.empty() ? "" : " (the file has '" + near + "')") +
                    "; correct \"time_s\" in the mapping",
                ErrorCode::MissingColumn, {file, "time_s"});
        }
        return fileError(
            file, shape.headerLine, 1,
            "no time column: neither 'time_s' nor a column named like a time stamp (Timestamp, Time, "
            "Date); name it in the column mapping (\"time_s\": {\"header\": …})",
            ErrorCode::MissingColumn, {file, "time_s"});
    }
    shape.timeHeader = shape.headers[timeIndex];

    // The first data lines: a units row, decimal commas, the time format.
    std::vector<std::string> firstCells;
    std::size_t points = 0, commas = 0, commaOrThousands = 0;
    int dataSeen = 0;
    const std::size_t afterHeader = lines.position();
    const int headerLineNo = lines.lineNumber();
    LineCursor data(text, afterHeader, headerLineNo);
    while (dataSeen < 200 && data.next(line)) {
        if (trimmed(line).empty()) {
            continue;
        }
        if (!split.split(line)) {
            return fileError(file, data.lineNumber(), 1, "malformed CSV line (an unclosed quote?)");
        }
        const auto& fields = split.fields();
        if (dataSeen == 0 && data.lineNumber() == headerLineNo + 1 && looksLikeUnitsRow(fields, timeIndex)) {
            shape.unitsRow = true;
            for (auto f : fields) {
                shape.units.emplace_back(trimmed(f));
            }
            continue;
        }
        ++dataSeen;
        if (timeIndex < fields.size()) {
            firstCells.emplace_back(fields[timeIndex]);
        }
        for (std::size_t c = 0; c < fields.size(); ++c) {
            if (c == timeIndex) {
                continue;
            }
            const NumberCell n = readNumberCell(fields[c]);
            points += n.marks == NumberMarks::DecimalPoint;
            commas += n.marks == NumberMarks::DecimalComma;
            commaOrThousands += n.marks == NumberMarks::CommaOrThousands;
        }
    }
    // A first look only: the reader decides each column's decimal mark on the whole file.
    shape.decimalComma = shape.delimiter != ',' && points == 0 && (commas > 0 || commaOrThousands > 0);
    if (mapping.decimalMark != 0) {
        shape.decimalComma = mapping.decimalMark == ',';
    }
    const int firstDataLine = headerLineNo + 1 + (shape.unitsRow ? 1 : 0);
    if (!mapping.timeFormat.empty()) {
        shape.timeFormat = *timeFormatByName(mapping.timeFormat); // ColumnMapping::validate checked it
    } else {
        const std::vector<std::string_view> views(firstCells.begin(), firstCells.end());
        const TimeFormatGuess g = detectTimeFormat(views, shape.timeHeader);
        std::string why = g.why;
        std::optional<TimeFormat> format = g.format;
        if (g.dayOrMonthFirst) {
            // The first rows fit both: the whole column decides (a day past the 12th, or which
            // reading keeps consecutive stamps close).
            DayMonthOrderVote vote;
            LineCursor all(text, afterHeader, headerLineNo);
            bool skippedUnits = !shape.unitsRow;
            while (all.next(line)) {
                if (trimmed(line).empty()) {
                    continue;
                }
                if (!skippedUnits) {
                    skippedUnits = true;
                    continue;
                }
                if (split.split(line) && timeIndex < split.fields().size()) {
                    vote.add(split.fields()[timeIndex]);
                }
            }
            format = vote.decide(shape.timeHeader, why);
        }
        if (!format) {
            return fileError(file, firstDataLine, static_cast<int>(timeIndex) + 1,
                             "time column '" + shape.timeHeader + "': " + why);
        }
        shape.timeFormat = *format;
    }
    // Relative seconds, commas and no units row is the contract's own form, whatever the time
    // column is called (the mapping renames it): one batch, read as before.
    // Units in the header ("T_hot_C [°C]") are read as a units row's would be (ValueColumns.cpp).
    const bool unitsInHeader =
        std::any_of(shape.headers.begin(), shape.headers.end(), [](const std::string& h) {
            return !h.empty() && h.back() == ']' && h.find('[') != std::string::npos;
        });
    shape.historian = shape.delimiter != ',' || shape.decimalComma || shape.unitsRow || unitsInHeader ||
                      shape.timeFormat != TimeFormat::Seconds || !mapping.batchIdHeader.empty();
    return shape;
}

} // namespace drytwin::data
