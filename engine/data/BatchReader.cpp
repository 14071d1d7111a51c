#include "data/BatchReader.h"

#include "common/TextList.h"
#include "data/PlantFileReader.h"
#include "data/historian/LineLengthGuard.h"
#include "data/historian/NumberFormat.h"
#include "data/historian/TextDecoding.h"
#include "data/historian/TimeFormatDetection.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <chrono>
#include <cmath>
#include <cstring>
#include <csv.h>
#include <filesystem>
#include <limits>
#include <set>

namespace drytwin::data {

namespace {

struct RawRow {
    int line = 0;
    std::vector<std::string> fields;
};

std::string place(const std::string& file, int line, int column) {
    return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

Error badInput(const std::string& file, int line, int column, std::string reason) {
    std::vector<std::string> args{file, std::to_string(line), std::to_string(column), reason};
    return Error{ErrorKind::BadInput, place(file, line, column), std::move(reason), ErrorCode::DataFileFormat,
                 std::move(args)};
}

/// @p e with a more specific code and its arguments (ErrorCode documents them).
Error withCode(Error e, ErrorCode code, std::vector<std::string> args) {
    e.code = code;
    e.args = std::move(args);
    return e;
}

void lineAndColumnOf(const std::string& text, std::size_t offset, int& line, int& column) {
    line = 1 + static_cast<int>(
                   std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(offset), '\n'));
    const auto lastNl = text.rfind('\n', offset == 0 ? 0 : offset - 1);
    column = static_cast<int>(lastNl == std::string::npos || offset == 0 ? offset + 1 : offset - lastNl);
}

std::string trim(std::string_view s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string_view::npos) {
        return {};
    }
    const auto e = s.find_last_not_of(" \t\r");
    return std::string(s.substr(b, e - b + 1));
}

/// Empty and NaN (CONTRACT.md §1), and the other spellings of "no value" a spreadsheet or a
/// historian writes ("#N/A", "null", PI's "Bad" or "No Data"), as the plant-file reader reads them:
/// the same cell is missing in a contract file and in a `;` export, not refused in one.
bool isMissingToken(const std::string& s) {
    std::string_view state;
    return historian::isMissingCell(s, state);
}

bool parseDouble(const std::string& s, double& v) {
    const char* b = s.data();
    const char* e = s.data() + s.size();
    if (b != e && *b == '+') {
        ++b;
    }
    auto [ptr, ec] = std::from_chars(b, e, v);
    return ec == std::errc() && ptr == e;
}

/// A number written correctly but too large (or too small) for a double: said as such, not as text.
bool outOfDoubleRange(const std::string& s) {
    const char* b = s.data();
    const char* e = s.data() + s.size();
    if (b != e && *b == '+') {
        ++b;
    }
    double v = 0;
    auto [ptr, ec] = std::from_chars(b, e, v);
    return ec == std::errc::result_out_of_range && ptr == e;
}

/// State shared with libcsv's C callbacks while one file is parsed.
struct CsvContext {
    std::vector<RawRow> rows;
    std::vector<std::string> current;
    int currentLine = 0;
    int rowStartLine = -1;
};

extern "C" void onCsvField(void* s, std::size_t len, void* data) {
    auto* ctx = static_cast<CsvContext*>(data);
    ctx->current.emplace_back(s ? static_cast<const char*>(s) : "", s ? len : 0);
}

extern "C" void onCsvRowEnd(int, void* data) {
    auto* ctx = static_cast<CsvContext*>(data);
    ctx->rows.push_back({ctx->rowStartLine, std::move(ctx->current)});
    ctx->current.clear();
    ctx->rowStartLine = -1;
}

} // namespace

Status checkBatchTextEncoding(const std::string& rawText, const std::string& file) {
    if (rawText.empty()) {
        return badInput(file, 1, 1, "empty file");
    }
    // Encoding: UTF-16/32 byte-order marks, then strict UTF-8.
    const auto u = [&](std::size_t i) { return static_cast<unsigned char>(rawText[i]); };
    if (rawText.size() >= 2 && ((u(0) == 0xFF && u(1) == 0xFE) || (u(0) == 0xFE && u(1) == 0xFF))) {
        return badInput(
            file, 1, 1,
            "the file is UTF-16 encoded; save it as UTF-8 (loading it as a data set converts it)");
    }
    if (const auto bad = historian::firstInvalidUtf8(rawText); bad != std::string::npos) {
        int line = 0;
        int column = 0;
        lineAndColumnOf(rawText, bad, line, column);
        return badInput(
            file, line, column, "not valid UTF-8 (byte 0x" + [&] {
                char buf[3];
                std::snprintf(buf, sizeof buf, "%02X", u(bad));
                return std::string(buf);
            }() + "); save the file as UTF-8");
    }
    if (rawText.find('\0') != std::string::npos) {
        int line = 0;
        int column = 0;
        lineAndColumnOf(rawText, rawText.find('\0'), line, column);
        return badInput(file, line, column, "NUL byte in a text file");
    }
    return {};
}

Expected<Batch> parseBatchText(const std::string& rawText, const std::string& displayName,
                               const ReadOptions& options) {
    const std::string& file = displayName;
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    if (auto st = checkBatchTextEncoding(rawText, file); !st) {
        return st.error();
    }
    if (auto st = historian::checkLineLengths(rawText, file); !st) {
        return st.error();
    }
    std::string_view text(rawText);
    if (text.substr(0, 3) == "\xEF\xBB\xBF") {
        text.remove_prefix(3);
    }

    Batch batch;
    batch.sourcePath = displayName;
    batch.id = std::filesystem::path(displayName).stem().string();

    // Split lines ourselves so every message can name the line (libcsv does not count lines).
    std::vector<std::string_view> lines;
    for (std::size_t pos = 0; pos <= text.size();) {
        auto nl = text.find('\n', pos);
        if (nl == std::string_view::npos) {
            if (pos < text.size()) {
                lines.push_back(text.substr(pos));
            }
            break;
        }
        lines.push_back(text.substr(pos, nl - pos));
        pos = nl + 1;
    }

    std::size_t li = 0;
    for (; li < lines.size(); ++li) {
        const std::string t = trim(lines[li]);
        if (t.empty()) {
            continue;
        }
        if (t[0] == '#') {
            std::string keep(lines[li]);
            if (!keep.empty() && keep.back() == '\r') {
                keep.pop_back();
            }
            batch.metadataLines.push_back(keep);
            continue;
        }
        break;
    }
    if (li == lines.size()) {
        const bool onlyBlank = batch.metadataLines.empty();
        return badInput(file, static_cast<int>(lines.size()), 1,
                        onlyBlank ? "empty file" : "no header row after the metadata lines");
    }
    if (auto id = batch.metadata("batch"); !id.empty()) {
        batch.id = id;
    }

    // libcsv: strict quoting, strict end of file, empty unquoted fields as NULL.
    csv_parser parser;
    if (csv_init(&parser, CSV_STRICT | CSV_STRICT_FINI | CSV_EMPTY_IS_NULL) != 0) {
        return Error{ErrorKind::Numerical, file, "could not initialise the CSV parser"};
    }
    CsvContext ctx;
    const std::size_t headerIndex = li;
    for (; li < lines.size(); ++li) {
        ctx.currentLine = static_cast<int>(li) + 1;
        const std::string_view line = lines[li];
        const bool inRow = ctx.rowStartLine != -1;
        if (!inRow) {
            if (trim(line).empty()) {
                continue; // blank lines between rows carry nothing
            }
            ctx.rowStartLine = ctx.currentLine;
        }
        std::string withNl(line);
        withNl.push_back('\n');
        if (csv_parse(&parser, withNl.data(), withNl.size(), onCsvField, onCsvRowEnd, &ctx) !=
            withNl.size()) {
            const std::string why = csv_strerror(csv_error(&parser));
            csv_free(&parser);
            return badInput(file, ctx.currentLine, static_cast<int>(ctx.current.size()) + 1,
                            "malformed CSV (" + why + ")");
        }
    }
    if (csv_fini(&parser, onCsvField, onCsvRowEnd, &ctx) != 0) {
        const std::string why = csv_strerror(csv_error(&parser));
        csv_free(&parser);
        return badInput(file, ctx.rowStartLine > 0 ? ctx.rowStartLine : static_cast<int>(lines.size()), 1,
                        "malformed CSV at end of file (" + why + ")");
    }
    csv_free(&parser);
    if (ctx.rows.empty()) {
        return badInput(file, static_cast<int>(headerIndex) + 1, 1, "no header row");
    }

    // Header.
    const RawRow& header = ctx.rows.front();
    const std::string headerLine(lines[headerIndex]);
    if (header.fields.size() == 1) {
        for (const char d : {';', '\t', '|'}) {
            if (headerLine.find(d) != std::string::npos) {
                const std::string name = d == '\t' ? "tab" : std::string("'") + d + "'";
                return badInput(file, header.line, 1,
                                "wrong delimiter: the header is separated by " + name + ", expected ','");
            }
        }
    }
    {
        bool allNumeric = true;
        for (const auto& f : header.fields) {
            double v = 0;
            allNumeric = allNumeric && parseDouble(trim(f), v);
        }
        if (allNumeric) {
            return badInput(file, header.line, 1,
                            "no header row: the first row holds numbers, not column names");
        }
    }
    // A separator after the last header (a spreadsheet's trailing empty column): that column is
    // no column, as the plant-file reader takes it, provided no row puts a value under it.
    std::size_t nCols = header.fields.size();
    const bool trailingSeparator = nCols > 1 && trim(header.fields.back()).empty();
    if (trailingSeparator) {
        --nCols;
    }
    std::vector<int> numericIndexOfField(nCols, -1);
    std::vector<int> textIndexOfField(nCols, -1);
    std::set<std::string> seenFile;
    std::set<Column> seenContract;
    for (std::size_t c = 0; c < nCols; ++c) {
        const std::string name = trim(header.fields[c]);
        const int col = static_cast<int>(c) + 1;
        if (name.empty()) {
            return badInput(file, header.line, col, "empty column name in the header");
        }
        if (!seenFile.insert(name).second) {
            return badInput(file, header.line, col, "duplicate column '" + name + "'");
        }
        const std::string contract = options.mapping.contractNameFor(name);
        if (!contract.empty()) {
            const Column id = *columnByName(contract);
            if (!seenContract.insert(id).second) {
                return badInput(file, header.line, col,
                                "column '" + name + "' maps to '" + contract +
                                    "', which another column already gives");
            }
            numericIndexOfField[c] = static_cast<int>(batch.numeric.size());
            batch.numeric.push_back({id, name, {}, col});
            batch.fileOrder.push_back(numericIndexOfField[c]);
        } else {
            textIndexOfField[c] = static_cast<int>(batch.text.size());
            batch.text.push_back({name, {}});
            batch.fileOrder.push_back(-1 - textIndexOfField[c]);
        }
    }
    {
        std::vector<std::string> headers;
        for (const auto& f : header.fields) {
            headers.push_back(trim(f));
        }
        if (auto st = options.mapping.checkHeadersPresent(headers, file, header.line); !st) {
            return st.error();
        }
    }
    for (const auto& s : columnSpecs()) {
        if (s.required && !seenContract.count(s.id)) {
            std::string hint;
            if (const auto it = options.mapping.contractToFile.find(std::string(s.name));
                it != options.mapping.contractToFile.end()) {
                hint = " (the column mapping names it '" + it->second + "')";
            } else {
                for (const auto& t : batch.text) {
                    if (headerLooksLike(t.fileName, s.id)) {
                        hint = " (the file has '" + t.fileName + "': rename it to '" + std::string(s.name) +
                               "' or give a column mapping)";
                        break;
                    }
                }
            }
            return withCode(badInput(file, header.line, 1,
                                     "missing required column '" + std::string(s.name) + "' [" +
                                         std::string(s.unit) + ", " + std::string(s.meaning) + "]" + hint),
                            ErrorCode::MissingColumn, {file, std::string(s.name)});
        }
    }

    // Data rows.
    const std::size_t nRows = ctx.rows.size() - 1;
    if (nRows == 0) {
        Error e = badInput(file, header.line, 1, "the file has a header but no data rows");
        e.code = ErrorCode::NotEnoughData; // the plant-file reader's own guess must not replace it
        e.args = {"rows", "0"};
        return e;
    }
    for (auto& col : batch.numeric) {
        col.values.reserve(nRows);
    }
    batch.lineOfRow.reserve(nRows);
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (std::size_t r = 1; r < ctx.rows.size(); ++r) {
        const RawRow& row = ctx.rows[r];
        if (trailingSeparator && row.fields.size() == nCols + 1) {
            if (!trim(row.fields.back()).empty()) {
                return badInput(file, row.line, static_cast<int>(nCols) + 1,
                                "value '" + trim(row.fields.back()) +
                                    "' under no header (the header ends with a separator)");
            }
        } else if (row.fields.size() != nCols) {
            std::string reason = "expected " + std::to_string(nCols) + " fields as in the header, found " +
                                 std::to_string(row.fields.size());
            if (row.fields.size() == 1 && (row.fields[0].find(';') != std::string::npos ||
                                           row.fields[0].find('\t') != std::string::npos)) {
                reason += " (wrong delimiter?)";
            }
            return badInput(file, row.line, static_cast<int>(std::min(row.fields.size(), nCols)) + 1, reason);
        }
        for (std::size_t c = 0; c < nCols; ++c) {
            if (textIndexOfField[c] >= 0) {
                batch.text[static_cast<std::size_t>(textIndexOfField[c])].cells.push_back(row.fields[c]);
                continue;
            }
            auto& col = batch.numeric[static_cast<std::size_t>(numericIndexOfField[c])];
            const std::string cell = trim(row.fields[c]);
            double v = nan;
            if (isMissingToken(cell)) {
                batch.missing.push_back({row.line, static_cast<int>(c) + 1, std::string(spec(col.id).name)});
            } else if (!parseDouble(cell, v) && outOfDoubleRange(cell)) {
                return badInput(file, row.line, static_cast<int>(c) + 1,
                                "number '" + cell + "' in column '" + col.fileName +
                                    "' lies outside what a number can hold (sizes 1e-308 to 1.8e308): a unit "
                                    "or exponent error?");
            } else if (!parseDouble(cell, v)) {
                return withCode(badInput(file, row.line, static_cast<int>(c) + 1,
                                         "text '" + cell + "' in numeric column '" + col.fileName + "'"),
                                ErrorCode::TextInNumber,
                                {file, std::to_string(row.line), std::to_string(c + 1), cell, col.fileName});
            } else if (!std::isfinite(v)) {
                return badInput(file, row.line, static_cast<int>(c) + 1,
                                "infinite value '" + cell + "' in column '" + col.fileName + "'");
            } else {
                v = options.mapping.toContractUnit(col.id, v); // a plant's own unit, when mapped
            }
            col.values.push_back(v);
        }
        batch.lineOfRow.push_back(row.line);
    }

    // The time index: present in every row and strictly increasing.
    const auto* time = batch.values(Column::Time);
    int timeField = 1;
    for (std::size_t c = 0; c < nCols; ++c) {
        if (numericIndexOfField[c] >= 0 &&
            batch.numeric[static_cast<std::size_t>(numericIndexOfField[c])].id == Column::Time) {
            timeField = static_cast<int>(c) + 1;
        }
    }
    for (std::size_t r = 0; r < time->size(); ++r) {
        if (std::isnan((*time)[r])) {
            return badInput(file, batch.lineOfRow[r], timeField,
                            "missing time; the time index must be complete");
        }
        if (r > 0 && !((*time)[r] > (*time)[r - 1])) {
            return withCode(badInput(file, batch.lineOfRow[r], timeField,
                                     "time does not increase (" + trim(std::to_string((*time)[r - 1])) +
                                         " s then " + trim(std::to_string((*time)[r])) + " s)"),
                            ErrorCode::TimeNotIncreasing,
                            {file, std::to_string(batch.lineOfRow[r]), std::to_string(timeField)});
        }
    }
    // time_s in other units: rows a few hundredths of a second apart or less would be a historian
    // sampling a drying line faster than 20 Hz, which none does; the model would then integrate a
    // whole batch over a fraction of a second without a word (a fresh user's test: Excel serial
    // days under time_s calibrated with exit 0).
    if (time->size() >= 3) {
        const double medianStep = historian::medianPositiveStep(*time); // time increases: every step
        if (medianStep < 0.05) {
            const double first = time->front();
            const bool excelDays = first >= 20000 && first < 80000;
            const bool excelTimesOfDay = first >= 0 && time->back() < 1;
            char text[512];
            std::snprintf(text, sizeof text,
                          "time_s: rows are %.3g s apart (median), faster than any drying line's historian "
                          "samples: the column is not in seconds. %s",
                          medianStep,
                          excelDays ? "Its values (near 45,000) are Excel serial days: name the column "
                                      "'Timestamp' so that the reader recognises them, or map it "
                                      "({\"time_s\": {\"header\": \"time_s\", \"format\": \"excel_days\"}})"
                          : excelTimesOfDay
                              ? "Its values (0 to 1) are Excel times of day (fractions of a day): name the "
                                "column 'Time' so that the reader recognises them, or map it "
                                "({\"time_s\": {\"header\": \"time_s\", \"format\": \"excel_days\"}})"
                              : "Give its unit (a units row under the header: min or h) or its format in a "
                                "column mapping");
            return badInput(file, batch.lineOfRow[1], timeField, text);
        }
        // The other end: rows 1,000 s apart are milliseconds read as seconds (a fresh user's test
        // calibrated on them with exit 0 and intervals of NaN). Any step of 10 min or more leaves
        // nothing of the line's dynamics (a particle dries in about a minute) to calibrate on.
        if (medianStep >= 600) {
            char text[512];
            std::snprintf(text, sizeof text,
                          "time_s: rows are %.4g s apart (median), longer than the line takes to dry a "
                          "particle: %s",
                          medianStep,
                          std::abs(medianStep - 1000) < 50
                              ? "the column looks like milliseconds. Give it in seconds, or name it "
                                "'Timestamp' with its unit in a column mapping"
                              : "a record this coarse cannot show the line's dynamics; export it at 1 to "
                                "10 s");
            return badInput(file, batch.lineOfRow[1], timeField, text);
        }
    }
    return batch;
}

Expected<Batch> readBatchFile(const std::string& path, const ReadOptions& options) {
    auto text = historian::readFileWithLineLimit(path);
    if (!text) {
        return text.error();
    }
    return parseBatchText(*text, path, options);
}

namespace {

std::string lowerCase(std::string text) {
    std::transform(text.begin(), text.end(), text.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return text;
}

bool isSpreadsheet(const std::string& lowerExtension) {
    return lowerExtension == ".xlsx" || lowerExtension == ".xls" || lowerExtension == ".xlsm" ||
           lowerExtension == ".ods";
}

constexpr const char* kOnlyCsv = "DryTwin reads CSV text (a historian's export, or a workbook saved as "
                                 "\"CSV UTF-8\" or \"CSV (semicolon)\"), not workbooks";

} // namespace

LoadResult loadDataSet(const std::string& path, const ReadOptions& options, const Progress& progress) {
    namespace fs = std::filesystem;
    const auto start = std::chrono::steady_clock::now();
    LoadResult result;
    std::error_code ec;
    std::vector<std::string> files;
    if (fs::is_directory(path, ec)) {
        std::vector<std::string> notRead; // data a user may have meant to load, said rather than skipped
        for (const auto& entry : fs::directory_iterator(path, ec)) {
            if (!entry.is_regular_file()) {
                continue;
            }
            // B01.CSV from a Windows share is a batch file as much as b01.csv.
            const std::string extension = lowerCase(entry.path().extension().string());
            if (extension == ".csv") {
                files.push_back(entry.path().string());
            } else if (isSpreadsheet(extension) || extension == ".txt" || extension == ".tsv" ||
                       extension == ".dat") {
                notRead.push_back(entry.path().filename().string());
            }
        }
        std::sort(files.begin(), files.end());
        std::sort(notRead.begin(), notRead.end());
        if (files.empty()) {
            result.errors.push_back(
                {ErrorKind::BadInput, path,
                 "the folder holds no *.csv batch files" +
                     (notRead.empty() ? std::string()
                                      : " (not read: " + commaList(notRead) + "; " + kOnlyCsv + ")")});
        } else if (!notRead.empty()) {
            const std::string note = path + ": not read: " + commaList(notRead) + "; " + kOnlyCsv;
            result.notes.push_back(note);
            result.dataSet.notes.push_back(note);
        }
    } else if (fs::exists(path, ec)) {
        if (isSpreadsheet(lowerCase(fs::path(path).extension().string()))) {
            result.errors.push_back(
                {ErrorKind::BadInput, path, std::string("a spreadsheet workbook; ") + kOnlyCsv});
            reportProgress(progress, "load", 1.0);
            return result;
        }
        files.push_back(path);
    } else {
        result.errors.push_back(
            {ErrorKind::BadInput, path, "no such file or folder", ErrorCode::FileNotFound, {path}});
    }
    std::set<std::string> ids;
    for (std::size_t i = 0; i < files.size(); ++i) {
        if (reportProgress(progress, "load", static_cast<double>(i) / static_cast<double>(files.size()),
                           fs::path(files[i]).filename().string())) {
            result.cancelled = true;
            break;
        }
        // A long plant file (a historian export) may hold several production runs.
        const auto fileProgress = [&](const ProgressInfo& info) {
            if (!progress) {
                return ProgressAction::Continue;
            }
            const double f = (static_cast<double>(i) + info.fraction) / static_cast<double>(files.size());
            return progress(ProgressInfo{"load", f, info.detail});
        };
        auto read = readPlantFile(files[i], options, fileProgress);
        if (!read) {
            if (read.error().kind == ErrorKind::Cancelled) {
                result.cancelled = true;
                break;
            }
            result.errors.push_back(read.error());
            continue;
        }
        for (auto& note : read->notes) {
            result.notes.push_back(note);
            result.dataSet.notes.push_back(std::move(note));
        }
        for (auto& batch : read->runs) {
            if (!ids.insert(batch.id).second) {
                result.errors.push_back({ErrorKind::BadInput, files[i],
                                         "batch id '" + batch.id + "' is used by an earlier file or run"});
                continue;
            }
            result.dataSet.batches.push_back(std::move(batch));
        }
    }
    reportProgress(progress, "load", 1.0);
    result.elapsedSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return result;
}

} // namespace drytwin::data
