#include "data/MappingGuess.h"

#include "data/historian/NarrowLayout.h"

#include "data/historian/CsvLines.h"
#include "data/historian/NumberFormat.h"
#include "data/historian/PlaceInFile.h"
#include "data/historian/TextDecoding.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>

namespace drytwin::data {

namespace {

/// What a contract column's header and values usually look like on a drying line.
struct Profile {
    Column column;
    std::vector<std::string> words; ///< lower-case words of its header
    std::vector<std::string> isa;   ///< ISA 5.1 letters of its transmitter (TT temperature, MT moisture …)
    double low, high;               ///< where its values live, in the contract's unit
};

const std::vector<Profile>& profiles() {
    static const std::vector<Profile> p{
        {Column::THotSp, {"sp", "setpoint", "set", "sollwert", "target"}, {"TC", "TIC"}, 100, 230},
        {Column::THot,
         {"hot", "hdt", "air", "hotair", "heissluft", "inletair", "gas"},
         {"TT", "TI"},
         100,
         230},
        {Column::AirSpeed, {"air", "speed", "velocity", "vel", "fan"}, {"ST", "FT", "SI"}, 4, 35},
        {Column::Feed,
         {"feed", "flow", "weigh", "belt", "mass", "rate", "throughput"},
         {"WT", "WI", "FT", "FI"},
         500,
         30000},
        {Column::XIn,
         {"in", "inlet", "xin", "wet", "feed", "infeed", "nir", "moisture"},
         {"MT", "MI", "AT"},
         14,
         40},
        {Column::TIn, {"in", "inlet", "tin", "feed", "infeed"}, {"TT", "TI"}, 0, 45},
        {Column::TAmb, {"amb", "ambient", "hall", "room", "env", "outside"}, {"TT", "TI"}, -15, 45},
        {Column::RHAmb,
         {"rh", "hum", "humidity", "hall", "amb", "ambient", "room"},
         {"MT", "HT", "AT", "MI"},
         3,
         100},
        {Column::XHdt, {"hdt", "tube", "dryer", "mid", "xhdt", "nir", "moisture"}, {"MT", "MI", "AT"}, 6, 22},
        {Column::THdt, {"hdt", "tube", "dryer", "mid", "thdt"}, {"TT", "TI"}, 30, 100},
        {Column::XOut,
         {"out", "outlet", "xout", "product", "final", "win", "winnower", "exit", "nir", "moisture"},
         {"MT", "MI", "AT"},
         6,
         20},
        {Column::TOut,
         {"out", "outlet", "product", "final", "win", "winnower", "exit", "tout"},
         {"TT", "TI"},
         25,
         90},
    };
    return p;
}

/// Words that say the column is a moisture reading: an NIR analyser (near-infrared) or a moisture
/// meter measures the material's water content, never a temperature ("NIR_IN.PV" was taken for the
/// inlet material temperature, its values lying in both ranges: issue #72 item 6).
bool isMoistureWord(const std::string& word) {
    static const std::set<std::string> moisture{"nir", "moisture", "moist", "feuchte"};
    return moisture.count(word) > 0;
}

bool measuresMoisture(Column c) {
    return c == Column::XIn || c == Column::XHdt || c == Column::XOut;
}

/// Lower-case words of a header and the ISA letters of its tag ("HDT_TT101.PV" → hdt, tt101, pv; TT).
void wordsOf(const std::string& header, std::vector<std::string>& words, std::string& isa) {
    std::string w;
    const auto flush = [&] {
        if (w.empty()) {
            return;
        }
        std::string letters;
        for (char c : w) {
            if (std::isalpha(static_cast<unsigned char>(c))) {
                letters.push_back(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
            } else {
                break;
            }
        }
        // A tag word: two or three letters then digits (TT101, MT302, TIC12).
        if (letters.size() >= 2 && letters.size() <= 3 && letters.size() < w.size() &&
            std::isdigit(static_cast<unsigned char>(w[letters.size()]))) {
            isa = letters;
        }
        std::string lw = w;
        std::transform(lw.begin(), lw.end(), lw.begin(), [](unsigned char c) { return std::tolower(c); });
        words.push_back(lw);
        // Letters before the digits of a word are a word too ("XIN2" → "xin").
        std::string lead;
        for (char c : lw) {
            if (!std::isalpha(static_cast<unsigned char>(c))) {
                break;
            }
            lead.push_back(c);
        }
        if (!lead.empty() && lead != lw) {
            words.push_back(lead);
        }
        w.clear();
    };
    for (std::size_t i = 0; i < header.size(); ++i) {
        const char c = header[i];
        if (std::isalnum(static_cast<unsigned char>(c))) {
            // camelCase splits too: "HotAir" → hot, air.
            if (!w.empty() && std::isupper(static_cast<unsigned char>(c)) &&
                std::islower(static_cast<unsigned char>(w.back()))) {
                flush();
            }
            w.push_back(c);
        } else {
            flush();
        }
    }
    flush();
}

struct ColumnValues {
    std::vector<double> numbers;
    std::size_t cells = 0;
    /// Share of the values in [low, high] and their mean: a line stop's zeros or a spike do not
    /// hide where a column lives.
    double shareIn(double low, double high, double& mean) const {
        std::size_t in = 0;
        double sum = 0;
        for (double v : numbers) {
            if (v >= low && v <= high) {
                ++in;
                sum += v;
            }
        }
        mean = in ? sum / static_cast<double>(in) : 0;
        return numbers.empty() ? 0 : static_cast<double>(in) / static_cast<double>(numbers.size());
    }
};

} // namespace

Expected<MappingGuess> guessMapping(const std::string& raw, const std::string& file) {
    MappingGuess g;
    auto decoded = historian::decodeText(raw, file);
    if (!decoded) {
        return decoded.error();
    }
    // A tag/value export is guessed on the table it stands for: its tags are the headers.
    auto narrow =
        historian::pivotNarrowExport(decoded->text(raw), file, RunSplitOptions{}.maxInterpolatedGapS);
    if (!narrow) {
        return narrow.error();
    }
    const std::string& text = *narrow ? (*narrow)->wideText : decoded->text(raw);
    auto shape = sniffPlantText(text, file, {});
    if (!shape) {
        return shape.error();
    }
    g.shape = *shape;
    const auto& headers = g.shape.headers;
    // Values of the first rows of every column (the sniffer already knows the delimiter).
    std::vector<ColumnValues> values(headers.size());
    {
        historian::LineCursor lines(text);
        historian::CsvLineSplitter split(g.shape.delimiter);
        std::string_view line;
        int seenHeader = 0, rows = 0;
        bool skippedUnits = !g.shape.unitsRow;
        std::vector<historian::DecimalMarkEvidence> marks(headers.size());
        std::vector<std::vector<double>> read(headers.size());
        while (rows < 2000 && lines.next(line)) {
            const auto t = historian::trimmed(line);
            if (t.empty() || (!seenHeader && t[0] == '#')) {
                continue;
            }
            if (!seenHeader) {
                seenHeader = 1;
                continue;
            }
            if (!skippedUnits) {
                skippedUnits = true;
                continue;
            }
            if (!split.split(line)) {
                continue;
            }
            ++rows;
            for (std::size_t c = 0; c < headers.size() && c < split.fields().size(); ++c) {
                ++values[c].cells;
                const auto n = historian::readNumberCell(split.fields()[c]);
                if (n.isNumber) {
                    marks[c].add(n, static_cast<std::uint32_t>(read[c].size()), lines.lineNumber(),
                                 split.fields()[c]);
                    read[c].push_back(n.value);
                }
            }
        }
        // The number format as the reader decides it, so that "6.497" kg/h reads 6497 here too.
        std::vector<historian::ColumnMarks> all;
        for (std::size_t c = 0; c < headers.size(); ++c) {
            all.push_back({&marks[c], headers[c], static_cast<int>(c) + 1});
        }
        const auto d = historian::decideDecimalMark(all, 0, g.shape.delimiter, file);
        for (std::size_t c = 0; c < headers.size(); ++c) {
            historian::applyDecimalMark(marks[c], d.mark, read[c]);
            values[c].numbers = std::move(read[c]);
        }
    }
    // Score every header against every contract column: its words, its tag letters, its range.
    struct Pair {
        double score;
        std::size_t header;
        const Profile* profile;
        std::string why;
    };
    std::vector<Pair> pairs;
    for (std::size_t c = 0; c < headers.size(); ++c) {
        if (headers[c] == g.shape.timeHeader) {
            continue;
        }
        const auto& v = values[c];
        if (v.numbers.empty() || v.numbers.size() * 10 < v.cells * 8) {
            continue; // a text column (a batch id, a status)
        }
        std::vector<std::string> words;
        std::string isa;
        wordsOf(headers[c], words, isa);
        for (const auto& p : profiles()) {
            if (headers[c] == spec(p.column).name) {
                pairs.push_back({100, c, &p, "the contract's own name"});
                continue;
            }
            double mean = 0;
            if (v.shareIn(p.low, p.high, mean) < 0.8) {
                continue;
            }
            double score = 1;
            char range[64];
            std::snprintf(range, sizeof range, "values in %g–%g", p.low, p.high);
            std::string why = range;
            int wordHits = 0;
            for (const auto& w : words) {
                wordHits += std::find(p.words.begin(), p.words.end(), w) != p.words.end();
            }
            if (wordHits > 0) {
                score += 2.0 * std::min(wordHits, 2);
                why += ", name";
            }
            // A moisture analyser's column is no temperature, flow or humidity, whatever its range.
            if (!measuresMoisture(p.column) &&
                std::any_of(words.begin(), words.end(),
                            [](const std::string& w) { return isMoistureWord(w); })) {
                score -= 3;
            }
            if (!isa.empty()) {
                const bool isaHit = std::find(p.isa.begin(), p.isa.end(), isa) != p.isa.end();
                score += isaHit ? 2 : -3;
                if (isaHit) {
                    why += ", tag " + isa;
                }
            }
            // Narrow typical ranges win among columns that fit several: the mean near the middle.
            const double mid = 0.5 * (p.low + p.high);
            score += 0.5 * (1 - std::min(1.0, std::abs(mean - mid) / (0.5 * (p.high - p.low))));
            if (score > 1.2) {
                pairs.push_back({score, c, &p, why});
            }
        }
    }
    std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.score > b.score; });
    std::set<std::size_t> usedHeaders;
    std::set<Column> usedColumns;
    for (const auto& p : pairs) {
        if (usedHeaders.count(p.header) || usedColumns.count(p.profile->column)) {
            continue;
        }
        usedHeaders.insert(p.header);
        usedColumns.insert(p.profile->column);
        const std::string name(spec(p.profile->column).name);
        g.mapping.contractToFile[name] = headers[p.header];
        g.reasons[name] = p.why;
    }
    g.mapping.contractToFile["time_s"] = g.shape.timeHeader;
    g.reasons["time_s"] = "time stamps: " + timeFormatName(g.shape.timeFormat);
    if (g.shape.timeFormat != TimeFormat::Seconds) {
        g.mapping.timeFormat = timeFormatName(g.shape.timeFormat);
    }
    for (std::size_t c = 0; c < headers.size(); ++c) {
        if (!usedHeaders.count(c) && headers[c] != g.shape.timeHeader) {
            g.unused.push_back(headers[c]);
        }
    }
    return g;
}

std::string mappingJson(const ColumnMapping& m) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (const auto& s : columnSpecs()) {
        const std::string name(s.name);
        const auto it = m.contractToFile.find(name);
        if (it == m.contractToFile.end()) {
            continue;
        }
        const auto unit = m.contractToUnit.find(name);
        const bool hasFormat = s.id == Column::Time && !m.timeFormat.empty();
        if (unit == m.contractToUnit.end() && !hasFormat) {
            j[name] = it->second;
            continue;
        }
        nlohmann::ordered_json o{{"header", it->second}};
        if (unit != m.contractToUnit.end()) {
            o["unit"] = unit->second;
        }
        if (hasFormat) {
            o["format"] = m.timeFormat;
        }
        j[name] = o;
    }
    if (!m.batchIdHeader.empty()) {
        j["batch_id"] = {{"header", m.batchIdHeader}};
    }
    if (m.decimalMark != 0) {
        j["decimal_mark"] = std::string(1, m.decimalMark);
    }
    const RunSplitOptions defaults;
    const auto& r = m.runs;
    if (r.stepS != defaults.stepS || r.lineStopFeedKgPerHour != defaults.lineStopFeedKgPerHour ||
        r.minStopS != defaults.minStopS || r.maxInterpolatedGapS != defaults.maxInterpolatedGapS ||
        r.minRunS != defaults.minRunS) {
        j["runs"] = {{"step_s", r.stepS},
                     {"line_stop_feed_kg_h", r.lineStopFeedKgPerHour},
                     {"min_stop_s", r.minStopS},
                     {"max_interpolated_gap_s", r.maxInterpolatedGapS},
                     {"min_run_s", r.minRunS}};
    }
    return j.dump(2) + "\n";
}

} // namespace drytwin::data
