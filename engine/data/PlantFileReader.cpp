// Plant files as historians export them (CONTRACT.md §1): time stamps, `;` or tab delimiters,
// decimal commas, a units row, tag names through the mapping, one long file cut into production
// runs. The text is split into lines once and each field parsed in place; libcsv parses lines that
// hold quotes (the rest split on the delimiter directly, which is what keeps a month at 1 s fast).
#include "data/PlantFileReader.h"

#include "common/AtomicFile.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <csv.h>
#include <ctime>
#include <filesystem>
#include <limits>
#include <map>
#include <set>

namespace drytwin::data {

namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();

std::string place(const std::string& file, int line, int column) {
    return file + ":" + std::to_string(line) + ":" + std::to_string(column);
}

Error badInput(const std::string& file, int line, int column, std::string reason,
               ErrorCode code = ErrorCode::DataFileFormat) {
    std::vector<std::string> args{file, std::to_string(line), std::to_string(column), reason};
    return Error{ErrorKind::BadInput, place(file, line, column), std::move(reason), code, std::move(args)};
}

std::string_view trimView(std::string_view s) {
    const auto b = s.find_first_not_of(" \t\r");
    if (b == std::string_view::npos) {
        return {};
    }
    const auto e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

std::string lower(std::string_view s) {
    std::string l(s);
    std::transform(l.begin(), l.end(), l.begin(), [](unsigned char c) { return std::tolower(c); });
    return l;
}

/// Fields of one line. Lines without a quote are split on the delimiter; lines with one go
/// through libcsv (quoted fields, doubled quotes).
struct LineSplitter {
    char delimiter = ',';
    std::vector<std::string_view> fields;
    std::vector<std::string> owned; // libcsv's unquoted copies
    csv_parser parser{};
    bool initialised = false;

    ~LineSplitter() {
        if (initialised) {
            csv_free(&parser);
        }
    }
    static void onField(void* s, std::size_t len, void* data) {
        auto* self = static_cast<LineSplitter*>(data);
        self->owned.emplace_back(s ? static_cast<const char*>(s) : "", s ? len : 0);
    }
    static void onRow(int, void*) {}

    bool split(std::string_view line) {
        fields.clear();
        if (!line.empty() && line.back() == '\r') {
            line.remove_suffix(1);
        }
        if (line.find('"') == std::string_view::npos) {
            std::size_t pos = 0;
            while (true) {
                const auto d = line.find(delimiter, pos);
                fields.push_back(
                    line.substr(pos, d == std::string_view::npos ? std::string_view::npos : d - pos));
                if (d == std::string_view::npos) {
                    break;
                }
                pos = d + 1;
            }
            return true;
        }
        if (!initialised) {
            if (csv_init(&parser, CSV_STRICT | CSV_STRICT_FINI) != 0) {
                return false;
            }
            initialised = true;
        }
        csv_set_delim(&parser, static_cast<unsigned char>(delimiter));
        owned.clear();
        if (csv_parse(&parser, line.data(), line.size(), onField, onRow, this) != line.size() ||
            csv_fini(&parser, onField, onRow, this) != 0) {
            return false;
        }
        for (const auto& o : owned) {
            fields.emplace_back(o);
        }
        return true;
    }
};

/// The delimiter of a header line: the most frequent of ',', ';' and tab outside quotes.
char detectDelimiter(std::string_view header) {
    int counts[3] = {0, 0, 0};
    bool quoted = false;
    for (char c : header) {
        if (c == '"') {
            quoted = !quoted;
        } else if (!quoted) {
            counts[0] += c == ',';
            counts[1] += c == ';';
            counts[2] += c == '\t';
        }
    }
    if (counts[1] > counts[0] && counts[1] >= counts[2]) {
        return ';';
    }
    if (counts[2] > counts[0] && counts[2] > counts[1]) {
        return '\t';
    }
    return ',';
}

bool parseNumber(std::string_view s, bool decimalComma, double& v) {
    s = trimView(s);
    if (s.empty()) {
        return false;
    }
    if (s.front() == '+') {
        s.remove_prefix(1);
    }
    char buf[64];
    if (decimalComma && s.find(',') != std::string_view::npos && s.size() < sizeof buf) {
        std::copy(s.begin(), s.end(), buf);
        std::replace(buf, buf + s.size(), ',', '.');
        s = std::string_view(buf, s.size());
    }
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    return ec == std::errc() && ptr == s.data() + s.size() && std::isfinite(v);
}

bool isMissing(std::string_view s) {
    s = trimView(s);
    if (s.empty()) {
        return true;
    }
    const std::string l = lower(s);
    return l == "nan" || l == "null" || l == "n/a" || l == "#n/a" || l == "bad" || l == "i/o timeout";
}

bool digits(std::string_view s, std::size_t pos, std::size_t n, int& v) {
    if (pos + n > s.size()) {
        return false;
    }
    v = 0;
    for (std::size_t i = pos; i < pos + n; ++i) {
        if (s[i] < '0' || s[i] > '9') {
            return false;
        }
        v = v * 10 + (s[i] - '0');
    }
    return true;
}

/// Seconds since 1970-01-01 of a calendar date and time of day, by the C library's timegm (a
/// date that timegm would roll over, such as 31 June, is rejected). The last date is cached:
/// a historian file holds 86,400 rows per date.
bool civilSeconds(int y, int mo, int d, int h, int mi, double sec, double& out) {
    thread_local int cachedY = -1, cachedMo = -1, cachedD = -1;
    thread_local double cachedDay = 0;
    if (y != cachedY || mo != cachedMo || d != cachedD) {
        if (mo < 1 || mo > 12 || d < 1 || d > 31) {
            return false;
        }
        std::tm tm{};
        tm.tm_year = y - 1900;
        tm.tm_mon = mo - 1;
        tm.tm_mday = d;
        const time_t t = timegm(&tm);
        std::tm back{};
        if (t == static_cast<time_t>(-1) || !gmtime_r(&t, &back) || back.tm_mday != d ||
            back.tm_mon != mo - 1) {
            return false;
        }
        cachedY = y;
        cachedMo = mo;
        cachedD = d;
        cachedDay = static_cast<double>(t);
    }
    if (h > 24 || mi > 59 || sec >= 61) {
        return false;
    }
    out = cachedDay + h * 3600.0 + mi * 60.0 + sec;
    return true;
}

/// "hh:mm[:ss[.fff]]" from @p pos; @p end is set past it.
bool timeOfDay(std::string_view s, std::size_t pos, int& h, int& mi, double& sec, std::size_t& end) {
    if (!digits(s, pos, 2, h) || pos + 2 >= s.size() || s[pos + 2] != ':' || !digits(s, pos + 3, 2, mi)) {
        return false;
    }
    end = pos + 5;
    sec = 0;
    int whole = 0;
    if (end < s.size() && s[end] == ':') {
        if (!digits(s, end + 1, 2, whole)) {
            return false;
        }
        sec = whole;
        end += 3;
        if (end < s.size() && (s[end] == '.' || s[end] == ',')) {
            std::size_t f = end + 1;
            double scale = 0.1;
            while (f < s.size() && s[f] >= '0' && s[f] <= '9') {
                sec += (s[f] - '0') * scale;
                scale /= 10;
                ++f;
            }
            end = f;
        }
    }
    return true;
}

} // namespace

std::string timeFormatName(TimeFormat f) {
    switch (f) {
    case TimeFormat::Seconds:
        return "seconds";
    case TimeFormat::Iso8601:
        return "iso8601";
    case TimeFormat::YmdSlash:
        return "Y/m/d";
    case TimeFormat::DmyDot:
        return "d.m.Y";
    case TimeFormat::DmySlash:
        return "d/m/Y";
    case TimeFormat::MdySlash:
        return "m/d/Y";
    case TimeFormat::ExcelDays:
        return "excel_days";
    case TimeFormat::EpochSeconds:
        return "epoch_s";
    case TimeFormat::EpochMillis:
        return "epoch_ms";
    }
    return "seconds";
}

std::optional<TimeFormat> timeFormatByName(const std::string& name) {
    for (TimeFormat f : {TimeFormat::Seconds, TimeFormat::Iso8601, TimeFormat::YmdSlash, TimeFormat::DmyDot,
                         TimeFormat::DmySlash, TimeFormat::MdySlash, TimeFormat::ExcelDays,
                         TimeFormat::EpochSeconds, TimeFormat::EpochMillis}) {
        if (timeFormatName(f) == name) {
            return f;
        }
    }
    return std::nullopt;
}

bool parseTimeCell(std::string_view cell, TimeFormat format, double& seconds) {
    const std::string_view s = trimView(cell);
    int y = 0, mo = 0, d = 0, h = 0, mi = 0;
    double sec = 0;
    std::size_t end = 0;
    switch (format) {
    case TimeFormat::Seconds:
    case TimeFormat::EpochSeconds:
        return parseNumber(s, true, seconds);
    case TimeFormat::EpochMillis:
        if (!parseNumber(s, true, seconds)) {
            return false;
        }
        seconds /= 1000.0;
        return true;
    case TimeFormat::ExcelDays: {
        double days = 0;
        if (!parseNumber(s, true, days) || days < 1 || days > 2958465) {
            return false;
        }
        // Excel's day 25569 is 1970-01-01 (its calendar counts from 1899-12-30).
        // To 10 ms: ten significant digits of a day resolve a millisecond, not better.
        seconds = std::round((days - 25569.0) * 86400.0 * 100.0) / 100.0;
        return true;
    }
    case TimeFormat::Iso8601: {
        if (!digits(s, 0, 4, y) || s.size() < 16 || s[4] != '-' || !digits(s, 5, 2, mo) || s[7] != '-' ||
            !digits(s, 8, 2, d) || (s[10] != 'T' && s[10] != ' ') || !timeOfDay(s, 11, h, mi, sec, end) ||
            !civilSeconds(y, mo, d, h, mi, sec, seconds)) {
            return false;
        }
        if (end == s.size()) {
            return true; // naive local time
        }
        if (s[end] == 'Z' && end + 1 == s.size()) {
            return true;
        }
        if (s[end] == '+' || s[end] == '-') {
            int oh = 0, om = 0;
            const bool colon = end + 3 < s.size() && s[end + 3] == ':';
            if (!digits(s, end + 1, 2, oh) || !digits(s, end + (colon ? 4 : 3), 2, om) ||
                end + (colon ? 6 : 5) != s.size()) {
                return false;
            }
            const double offset = (oh * 3600.0 + om * 60.0) * (s[end] == '+' ? 1 : -1);
            seconds -= offset; // to UTC
            return true;
        }
        return false;
    }
    case TimeFormat::YmdSlash:
        return digits(s, 0, 4, y) && s.size() >= 16 && s[4] == '/' && digits(s, 5, 2, mo) && s[7] == '/' &&
               digits(s, 8, 2, d) && s[10] == ' ' && timeOfDay(s, 11, h, mi, sec, end) && end == s.size() &&
               civilSeconds(y, mo, d, h, mi, sec, seconds);
    case TimeFormat::DmyDot:
    case TimeFormat::DmySlash:
    case TimeFormat::MdySlash: {
        const char sep = format == TimeFormat::DmyDot ? '.' : '/';
        int a = 0, b = 0;
        if (!digits(s, 0, 2, a) || s.size() < 16 || s[2] != sep || !digits(s, 3, 2, b) || s[5] != sep ||
            !digits(s, 6, 4, y) || s[10] != ' ' || !timeOfDay(s, 11, h, mi, sec, end) || end != s.size()) {
            return false;
        }
        d = format == TimeFormat::MdySlash ? b : a;
        mo = format == TimeFormat::MdySlash ? a : b;
        return civilSeconds(y, mo, d, h, mi, sec, seconds);
    }
    }
    return false;
}

namespace {

/// The format of a time column from its first cells; nullopt with @p why when none fits.
std::optional<TimeFormat> detectTimeFormat(const std::vector<std::string_view>& cells, bool namedLikeTime,
                                           std::string& why) {
    if (cells.empty()) {
        why = "no time stamps";
        return std::nullopt;
    }
    const std::string_view first = trimView(cells.front());
    const auto fits = [&](TimeFormat f) {
        double v = 0;
        return parseTimeCell(first, f, v);
    };
    // The first stamp decides (a bad stamp further down is then reported at its own line); only
    // day/month against month/day needs all the first rows.
    if (first.size() >= 10 && first[4] == '-' && fits(TimeFormat::Iso8601)) {
        return TimeFormat::Iso8601;
    }
    if (first.size() >= 10 && first[4] == '/' && fits(TimeFormat::YmdSlash)) {
        return TimeFormat::YmdSlash;
    }
    if (first.size() >= 10 && first[2] == '.' && fits(TimeFormat::DmyDot)) {
        return TimeFormat::DmyDot;
    }
    if (first.size() >= 10 && first[2] == '/') {
        const auto all = [&](TimeFormat f) {
            double v = 0;
            return std::all_of(cells.begin(), cells.end(),
                               [&](auto c) { return isMissing(c) || parseTimeCell(c, f, v); });
        };
        const bool dmy = all(TimeFormat::DmySlash);
        const bool mdy = all(TimeFormat::MdySlash);
        if (dmy && mdy) {
            why = "the dates could be day/month or month/day; name the format in the mapping "
                  "(\"time_s\": {\"header\": …, \"format\": \"d/m/Y\"} or \"m/d/Y\")";
            return std::nullopt;
        }
        if (dmy || mdy) {
            return dmy ? TimeFormat::DmySlash : TimeFormat::MdySlash;
        }
    }
    double v = 0;
    if (parseNumber(first, true, v)) {
        if (v >= 1e11) {
            return TimeFormat::EpochMillis;
        }
        if (v >= 1e8) {
            return TimeFormat::EpochSeconds;
        }
        // Excel's serial days of 1955–2119 with a fraction, in a column named like a date.
        if (namedLikeTime && v >= 20000 && v < 80000 && std::floor(v) != v) {
            return TimeFormat::ExcelDays;
        }
        return TimeFormat::Seconds;
    }
    why = "'" + std::string(first) +
          "' is not a time stamp DryTwin knows (ISO 8601, Y/m/d, d.m.Y, d/m/Y, m/d/Y, " +
          "Excel serial days, Unix seconds)";
    return std::nullopt;
}

bool namedLikeTime(const std::string& header) {
    const std::string l = lower(header);
    for (const char* k : {"timestamp", "time", "date", "zeit", "datum", "时间", "日期"}) {
        if (l.find(k) != std::string::npos) {
            return true;
        }
    }
    return false;
}

/// A units-row cell in the unit names of ColumnMapping (unitsFor); empty when not recognised.
std::string normalisedUnit(std::string_view raw, Column column) {
    std::string u;
    for (char c : trimView(raw)) {
        if (c != '[' && c != ']' && c != '(' && c != ')' && c != ' ') {
            u.push_back(c);
        }
    }
    const std::string l = lower(u);
    if (l.empty()) {
        return {};
    }
    if (l == "°c" || l == "degc" || l == "c" || l == "℃") {
        return "degC";
    }
    if (l == "°f" || l == "degf" || l == "f") {
        return "degF";
    }
    if (u == "K") {
        return "K";
    }
    if (l == "kg/h" || l == "kg/hr") {
        return "kg/h";
    }
    if (l == "t/h") {
        return "t/h";
    }
    if (l == "kg/s" || l == "kg/min" || l == "m/s" || l == "s" || l == "min") {
        return l;
    }
    if (l == "%db" || l == "%d.b.") {
        return "% db";
    }
    if (l == "%" || l == "%wb" || l == "%rh" || l == "%w.b.") {
        return spec(column).unit == "%" ? "%" : (l == "%rh" ? "" : "% wb");
    }
    return {};
}

struct Row {
    double t = 0;
    int line = 0;
    int batch = -1; ///< index into the batch ids
};

/// A run of rows [begin, end) and why it ended.
struct Span {
    std::size_t begin = 0, end = 0;
    std::string reason;
};

/// Cuts the rows into runs: at line stops (the feed below its threshold for at least the minimum
/// stop; the stop's rows belong to no run), clock jumps, batch-id changes and gaps in time.
std::vector<Span> cutIntoRuns(const std::vector<Row>& rows, const std::vector<double>* feed,
                              const std::vector<std::size_t>& clockJumpBefore, const RunSplitOptions& runs) {
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
    std::vector<Span> spans;
    std::size_t jump = 0;
    for (std::size_t i = 0; i < n;) {
        if (inStop[i]) {
            ++i;
            continue;
        }
        Span s{i, i + 1, "end of file"};
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

/// A value column of a plant file: its contract column (if mapped), unit and values as read.
struct ValueColumn {
    std::optional<Column> contract;
    std::string header;
    std::string unit; ///< the file's unit for a contract column ("" = the contract's)
    std::size_t field = 0;
    bool numeric = true;
    std::vector<double> values;
    ColumnMapping conversion; ///< converts from unit to the contract's
};

/// Puts each run onto the step's grid (linear interpolation between samples, counted; missing
/// cells kept missing) and names it; runs shorter than the minimum are left out with a note.
void resampleRuns(const std::vector<Span>& spans, const std::vector<Row>& rows,
                  std::vector<ValueColumn>& columns, const std::vector<std::string>& batchIds,
                  const std::vector<std::string>& metadata, const FileShape& shape, const std::string& file,
                  const RunSplitOptions& runs, PlantFileRuns& result) {
    const std::string stem = std::filesystem::path(file).stem().string();
    std::map<std::string, int> idUses;
    int runNumber = 0;
    const auto isoOf = [&](double t) {
        if (shape.timeFormat == TimeFormat::Seconds) {
            char buf[48];
            std::snprintf(buf, sizeof buf, "t = %.3f s", t);
            return std::string(buf);
        }
        const auto whole = static_cast<time_t>(std::floor(t));
        std::tm tm{};
        gmtime_r(&whole, &tm);
        char buf[48];
        std::snprintf(buf, sizeof buf, "%04d-%02d-%02dT%02d:%02d:%02d", tm.tm_year + 1900, tm.tm_mon + 1,
                      tm.tm_mday, tm.tm_hour, tm.tm_min, tm.tm_sec);
        return std::string(buf);
    };
    // Every run's grid first, then column by column into all runs, each source column freed
    // once used: the numbers of a month at 1 s are held once and a column more, not twice.
    struct Grid {
        std::vector<std::size_t> before; // the sample at or before each grid row
        std::vector<double> weight;      // 0: on that sample; else the share towards the next
    };
    std::vector<Grid> grids;
    for (const auto& s : spans) {
        const double t0 = rows[s.begin].t;
        const double span = rows[s.end - 1].t - t0;
        if (span + runs.stepS < runs.minRunS) {
            result.notes.push_back(place(file, rows[s.begin].line, 1) + "-" +
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
        src.startTimestamp = isoOf(t0);
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
        b.numeric.push_back({Column::Time, shape.timeHeader, std::move(time)});
        b.fileOrder.push_back(0);
        b.run = src;
        result.runs.push_back(std::move(b));
        grids.push_back(std::move(g));
    }
    for (auto& c : columns) {
        if (!c.numeric || !c.contract) {
            std::vector<double>().swap(c.values);
            continue; // extra columns of a historian export are not part of a run
        }
        for (std::size_t r = 0; r < result.runs.size(); ++r) {
            Batch& b = result.runs[r];
            const Grid& g = grids[r];
            RunSource& src = *b.run;
            std::vector<double> v(g.before.size(), kNan);
            for (std::size_t k = 0; k < v.size(); ++k) {
                const std::size_t i = g.before[k];
                const double a = c.values[i];
                if (g.weight[k] == 0.0) {
                    v[k] = a;
                    if (std::isnan(a)) {
                        b.missing.push_back({rows[i].line, static_cast<int>(c.field) + 1,
                                             std::string(spec(*c.contract).name)});
                    }
                    continue;
                }
                const double z = c.values[i + 1];
                if (std::isfinite(a) && std::isfinite(z)) {
                    v[k] = a + g.weight[k] * (z - a);
                    ++src.interpolatedCells;
                } else {
                    ++src.gapCells;
                    b.missing.push_back(
                        {rows[i].line, static_cast<int>(c.field) + 1, std::string(spec(*c.contract).name)});
                }
            }
            b.fileOrder.push_back(static_cast<int>(b.numeric.size()));
            b.numeric.push_back({*c.contract, c.header, std::move(v)});
        }
        std::vector<double>().swap(c.values);
    }
}

} // namespace

Expected<FileShape> sniffPlantText(const std::string& text, const std::string& file,
                                   const ColumnMapping& mapping) {
    FileShape shape;
    std::size_t pos = 0;
    int lineNo = 0;
    std::string_view header;
    const std::string_view all(text);
    std::size_t headerEnd = 0;
    while (pos < all.size()) {
        const auto nl = all.find('\n', pos);
        const std::string_view line =
            all.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
        ++lineNo;
        pos = nl == std::string_view::npos ? all.size() : nl + 1;
        const auto t = trimView(line);
        if (t.empty() || t.front() == '#') {
            continue;
        }
        header = line;
        headerEnd = pos;
        shape.headerLine = lineNo;
        break;
    }
    if (header.empty()) {
        return badInput(file, std::max(lineNo, 1), 1, "no header row");
    }
    if (header.substr(0, 3) == "\xEF\xBB\xBF") {
        header.remove_prefix(3);
    }
    shape.delimiter = detectDelimiter(header);
    LineSplitter split;
    split.delimiter = shape.delimiter;
    if (!split.split(header)) {
        return badInput(file, lineNo, 1, "malformed header row");
    }
    for (auto f : split.fields) {
        shape.headers.emplace_back(trimView(f));
    }
    // The time column: the mapping's, else time_s, else one named like a time.
    std::size_t timeIndex = shape.headers.size();
    const auto mapped = mapping.contractToFile.find("time_s");
    for (std::size_t c = 0; c < shape.headers.size(); ++c) {
        const bool isMapped = mapped != mapping.contractToFile.end() && shape.headers[c] == mapped->second;
        if (isMapped || (mapped == mapping.contractToFile.end() && shape.headers[c] == "time_s")) {
            timeIndex = c;
            break;
        }
    }
    if (timeIndex == shape.headers.size() && mapped == mapping.contractToFile.end()) {
        for (std::size_t c = 0; c < shape.headers.size(); ++c) {
            if (namedLikeTime(shape.headers[c]) && mapping.contractNameFor(shape.headers[c]).empty()) {
                timeIndex = c;
                break;
            }
        }
    }
    if (timeIndex == shape.headers.size()) {
        return badInput(file, lineNo, 1,
                        mapped != mapping.contractToFile.end()
                            ? "the mapping's time column '" + mapped->second + "' is not in the header"
                            : "no time column: neither 'time_s' nor a column named like a time stamp "
                              "(Timestamp, Time, Date); name it in the mapping (\"time_s\": {\"header\": …})",
                        ErrorCode::MissingColumn);
    }
    shape.timeHeader = shape.headers[timeIndex];
    // The first data lines: a units row, decimal commas, the time format.
    std::vector<std::string> firstCells;
    bool commaDecimals = false, dotDecimals = false;
    int dataSeen = 0;
    int row = lineNo;
    std::vector<std::string> firstRowFields;
    for (std::size_t p = headerEnd; p < all.size() && dataSeen < 200;) {
        const auto nl = all.find('\n', p);
        const std::string_view line =
            all.substr(p, nl == std::string_view::npos ? std::string_view::npos : nl - p);
        p = nl == std::string_view::npos ? all.size() : nl + 1;
        ++row;
        if (trimView(line).empty()) {
            continue;
        }
        if (!split.split(line)) {
            return badInput(file, row, 1, "malformed CSV line");
        }
        if (dataSeen == 0 && row == lineNo + 1) {
            // A units row: no time stamp and no number in the value columns, but text.
            int text = 0, numbers = 0;
            for (std::size_t c = 0; c < split.fields.size(); ++c) {
                double v = 0;
                if (c == timeIndex || trimView(split.fields[c]).empty()) {
                    continue;
                }
                if (parseNumber(split.fields[c], true, v)) {
                    ++numbers;
                } else {
                    ++text;
                }
            }
            double tv = 0;
            const bool timeLooksLikeStamp = timeIndex < split.fields.size() &&
                                            (parseNumber(split.fields[timeIndex], true, tv) ||
                                             parseTimeCell(split.fields[timeIndex], TimeFormat::Iso8601, tv));
            if (text > 0 && numbers == 0 && !timeLooksLikeStamp) {
                shape.unitsRow = true;
                for (auto f : split.fields) {
                    shape.units.emplace_back(trimView(f));
                }
                continue;
            }
        }
        ++dataSeen;
        if (timeIndex < split.fields.size()) {
            firstCells.emplace_back(split.fields[timeIndex]);
        }
        for (std::size_t c = 0; c < split.fields.size(); ++c) {
            if (c == timeIndex) {
                continue;
            }
            const auto f = trimView(split.fields[c]);
            const bool hasComma = f.find(',') != std::string_view::npos;
            const bool hasDot = f.find('.') != std::string_view::npos;
            double v = 0;
            if (parseNumber(f, true, v)) {
                commaDecimals = commaDecimals || (hasComma && !hasDot);
                dotDecimals = dotDecimals || (hasDot && !hasComma);
            }
        }
    }
    shape.decimalComma = shape.delimiter != ',' && commaDecimals && !dotDecimals;
    std::vector<std::string_view> views(firstCells.begin(), firstCells.end());
    if (!mapping.timeFormat.empty()) {
        shape.timeFormat = *timeFormatByName(mapping.timeFormat); // ColumnMapping::validate checked it
    } else {
        std::string why;
        const auto f = detectTimeFormat(views, namedLikeTime(shape.timeHeader), why);
        if (!f) {
            return badInput(file, lineNo + 1 + (shape.unitsRow ? 1 : 0), static_cast<int>(timeIndex) + 1,
                            "time column '" + shape.timeHeader + "': " + why);
        }
        shape.timeFormat = *f;
    }
    // Relative seconds, commas and no units row is the contract's own form, whatever the time
    // column is called (the mapping renames it): one batch, read as before.
    shape.historian = shape.delimiter != ',' || shape.decimalComma || shape.unitsRow ||
                      shape.timeFormat != TimeFormat::Seconds || !mapping.batchIdHeader.empty();
    return shape;
}

Expected<PlantFileRuns> parsePlantText(const std::string& text, const std::string& file,
                                       const ReadOptions& options, const Progress& progress) {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    auto sniffed = sniffPlantText(text, file, options.mapping);
    if (!sniffed) {
        // Neither shape fits: an encoding problem first, then whichever reader knows more. The
        // batch reader accepts what it can; otherwise the plant-file reader's reason (time column,
        // format) is the one a historian export needs.
        if (auto st = checkBatchTextEncoding(text, file); !st) {
            return st.error();
        }
        auto one = parseBatchText(text, file, options);
        if (!one) {
            return sniffed.error().code == ErrorCode::MissingColumn ? one.error() : sniffed.error();
        }
        PlantFileRuns r;
        r.runs.push_back(std::move(*one));
        return r;
    }
    PlantFileRuns result;
    result.shape = *sniffed;
    const FileShape& shape = result.shape;
    if (!shape.historian) {
        auto one = parseBatchText(text, file, options);
        if (!one) {
            return one.error();
        }
        result.runs.push_back(std::move(*one));
        return result;
    }
    if (auto st = checkBatchTextEncoding(text, file); !st) {
        return st.error();
    }
    const ColumnMapping& mapping = options.mapping;
    const RunSplitOptions& runs = mapping.runs;

    // Columns: the time, the batch id, contract columns (mapped or by name), other numeric ones.
    const std::size_t nCols = shape.headers.size();
    std::size_t timeIndex = 0, batchIndex = nCols;
    std::vector<ValueColumn> columns;
    std::set<Column> seen;
    for (std::size_t c = 0; c < nCols; ++c) {
        const std::string& h = shape.headers[c];
        if (h == shape.timeHeader) {
            timeIndex = c;
            continue;
        }
        if (!mapping.batchIdHeader.empty() && h == mapping.batchIdHeader) {
            batchIndex = c;
            continue;
        }
        ValueColumn v;
        v.header = h;
        v.field = c;
        const std::string contract = mapping.contractNameFor(h);
        if (!contract.empty() && contract != "time_s") {
            v.contract = columnByName(contract);
            if (!seen.insert(*v.contract).second) {
                return badInput(file, shape.headerLine, static_cast<int>(c) + 1,
                                "column '" + h + "' maps to '" + contract +
                                    "', which another column already gives");
            }
            if (const auto u = mapping.contractToUnit.find(contract); u != mapping.contractToUnit.end()) {
                v.unit = u->second;
            } else if (shape.unitsRow && c < shape.units.size() && !shape.units[c].empty()) {
                v.unit = normalisedUnit(shape.units[c], *v.contract);
                const auto known = unitsFor(*v.contract);
                if (v.unit.empty() || std::find(known.begin(), known.end(), v.unit) == known.end()) {
                    std::string list;
                    for (const auto& k : known) {
                        list += (list.empty() ? "" : ", ") + k;
                    }
                    return badInput(file, shape.headerLine + 1, static_cast<int>(c) + 1,
                                    "unit '" + shape.units[c] + "' of column '" + h + "' (" + contract +
                                        ") is not one of " + list);
                }
            }
        }
        if (v.contract && !v.unit.empty()) {
            v.conversion.contractToUnit[std::string(spec(*v.contract).name)] = v.unit;
        }
        columns.push_back(std::move(v));
    }
    if (!mapping.batchIdHeader.empty() && batchIndex == nCols) {
        return badInput(file, shape.headerLine, 1,
                        "the mapping's batch column '" + mapping.batchIdHeader + "' is not in the header",
                        ErrorCode::MissingColumn);
    }
    for (const auto& s : columnSpecs()) {
        if (s.required && s.id != Column::Time && !seen.count(s.id)) {
            std::string hint;
            if (const auto it = mapping.contractToFile.find(std::string(s.name));
                it != mapping.contractToFile.end()) {
                hint = " (the column mapping names it '" + it->second + "')";
            } else {
                hint = " (map the file's tag to it: --mapping, or the column-mapping dialog)";
            }
            Error e = badInput(file, shape.headerLine, 1,
                               "missing required column '" + std::string(s.name) + "' [" +
                                   std::string(s.unit) + ", " + std::string(s.meaning) + "]" + hint,
                               ErrorCode::MissingColumn);
            e.args = {file, std::string(s.name)};
            return e;
        }
    }
    const double timeScale = [&] {
        if (shape.timeFormat != TimeFormat::Seconds) {
            return 1.0;
        }
        if (const auto u = mapping.contractToUnit.find("time_s");
            u != mapping.contractToUnit.end() && u->second == "min") {
            return 60.0;
        }
        if (shape.unitsRow && timeIndex < shape.units.size() &&
            normalisedUnit(shape.units[timeIndex], Column::Time) == "min") {
            return 60.0;
        }
        return 1.0;
    }();

    // One pass over the lines.
    std::vector<Row> rows;
    std::vector<std::string> batchIds;
    std::map<std::string, int> batchIdIndex;
    std::vector<std::size_t> clockJumpBefore; // row indices where the clock went back
    std::vector<MissingCell> missing;
    std::vector<std::string> metadata;
    LineSplitter split;
    split.delimiter = shape.delimiter;
    const std::string_view all(text);
    std::size_t pos = 0;
    int lineNo = 0;
    bool headerDone = false, unitsDone = !shape.unitsRow;
    std::size_t duplicates = 0;
    int firstDuplicateLine = 0;
    std::size_t nextProgress = 0;
    rows.reserve(text.size() / 64);
    for (auto& c : columns) {
        c.values.reserve(text.size() / 64);
    }
    while (pos < all.size()) {
        if (pos >= nextProgress) {
            nextProgress = pos + (1u << 20);
            if (reportProgress(progress, "load",
                               0.9 * static_cast<double>(pos) / static_cast<double>(all.size()),
                               std::filesystem::path(file).filename().string())) {
                return cancelledError("load");
            }
        }
        const auto nl = all.find('\n', pos);
        std::string_view line =
            all.substr(pos, nl == std::string_view::npos ? std::string_view::npos : nl - pos);
        pos = nl == std::string_view::npos ? all.size() : nl + 1;
        ++lineNo;
        const auto trimmed = trimView(line);
        if (trimmed.empty()) {
            continue;
        }
        if (!headerDone) {
            if (trimmed.front() == '#') {
                metadata.emplace_back(trimmed);
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
            return badInput(file, lineNo, 1, "malformed CSV (an unclosed quote?)");
        }
        if (split.fields.size() != nCols) {
            return badInput(file, lineNo, static_cast<int>(std::min(split.fields.size(), nCols)) + 1,
                            "expected " + std::to_string(nCols) + " fields as in the header, found " +
                                std::to_string(split.fields.size()));
        }
        Row r;
        r.line = lineNo;
        if (!parseTimeCell(split.fields[timeIndex], shape.timeFormat, r.t)) {
            return badInput(file, lineNo, static_cast<int>(timeIndex) + 1,
                            "bad time stamp '" + std::string(trimView(split.fields[timeIndex])) +
                                "' (the column is " + timeFormatName(shape.timeFormat) + ")");
        }
        r.t *= timeScale;
        if (!rows.empty()) {
            const double prev = rows.back().t;
            if (r.t == prev) {
                if (duplicates++ == 0) {
                    firstDuplicateLine = lineNo;
                }
                continue; // the first row with a stamp is kept; the duplicate is reported
            }
            if (r.t < prev) {
                result.notes.push_back(
                    place(file, lineNo, static_cast<int>(timeIndex) + 1) + ": the clock goes back " +
                    std::to_string(static_cast<long>(std::lround(prev - r.t))) +
                    " s (a daylight-saving change or a clock reset?); the run ends here and a new "
                    "one starts, nothing is reordered");
                clockJumpBefore.push_back(rows.size());
            }
        }
        if (batchIndex < nCols) {
            const std::string id(trimView(split.fields[batchIndex]));
            auto [it, inserted] = batchIdIndex.emplace(id, static_cast<int>(batchIds.size()));
            if (inserted) {
                batchIds.push_back(id);
            }
            r.batch = it->second;
        }
        for (auto& c : columns) {
            const std::string_view cell = split.fields[c.field];
            double v = kNan;
            if (isMissing(cell)) {
                if (c.contract) {
                    missing.push_back(
                        {lineNo, static_cast<int>(c.field) + 1, std::string(spec(*c.contract).name)});
                }
            } else if (!parseNumber(cell, shape.decimalComma, v)) {
                if (c.contract) {
                    Error e = badInput(file, lineNo, static_cast<int>(c.field) + 1,
                                       "text '" + std::string(trimView(cell)) + "' in numeric column '" +
                                           c.header + "'",
                                       ErrorCode::TextInNumber);
                    e.args = {file, std::to_string(lineNo), std::to_string(c.field + 1),
                              std::string(trimView(cell)), c.header};
                    return e;
                }
                c.numeric = false; // a text column that is no contract column: not kept in runs
                v = kNan;
            } else if (c.contract && !c.unit.empty()) {
                v = c.conversion.toContractUnit(*c.contract, v);
            }
            c.values.push_back(v);
        }
        rows.push_back(r);
    }
    if (duplicates > 0) {
        result.notes.push_back(
            place(file, firstDuplicateLine, static_cast<int>(timeIndex) + 1) + ": " +
            std::to_string(duplicates) +
            " row(s) repeat the time stamp of the row before (first here); each duplicate is left "
            "out, the first row with the stamp kept");
    }
    for (const auto& c : columns) {
        if (!c.numeric) {
            result.notes.push_back(file + ": column '" + c.header +
                                   "' holds text; it is not kept in the runs");
        }
    }
    if (rows.empty()) {
        return badInput(file, lineNo, 1, "the file has a header but no data rows");
    }

    // Where runs end: clock jumps, batch-id changes, gaps, line stops.
    const std::vector<double>* feed = nullptr;
    for (const auto& c : columns) {
        if (c.contract == Column::Feed) {
            feed = &c.values;
        }
    }
    const std::vector<Span> spans = cutIntoRuns(rows, feed, clockJumpBefore, runs);

    // Each run onto the step's grid.
    resampleRuns(spans, rows, columns, batchIds, metadata, shape, file, runs, result);
    if (result.runs.empty()) {
        return badInput(file, rows.front().line, 1,
                        "no production run: every stretch of the file is a line stop or shorter than " +
                            std::to_string(static_cast<long>(runs.minRunS)) + " s");
    }
    reportProgress(progress, "load", 1.0);
    return result;
}

Expected<PlantFileRuns> readPlantFile(const std::string& path, const ReadOptions& options,
                                      const Progress& progress) {
    auto text = readWholeFile(path);
    if (!text) {
        return text.error();
    }
    return parsePlantText(*text, path, options, progress);
}

} // namespace drytwin::data
