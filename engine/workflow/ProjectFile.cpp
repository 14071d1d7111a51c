#include "workflow/ProjectFile.h"

#include "common/AtomicFile.h"

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>

namespace drytwin::workflow {

namespace {

namespace fs = std::filesystem;
using nlohmann::json;

std::string text(const json& from, const std::string& key) {
    const auto it = from.find(key);
    return it != from.end() && it->is_string() ? it->get<std::string>() : std::string();
}

} // namespace

Expected<ProjectPaths> readProjectPaths(const std::string& projectPath) {
    const auto all = readWholeFile(projectPath);
    if (!all) {
        return all.error();
    }
    json o;
    try {
        o = json::parse(*all);
    } catch (const json::parse_error& e) {
        // A JSON object that breaks off or goes wrong (a full disk, a copy interrupted, an edit):
        // damaged, not a file of another kind.
        const auto first = all->find_first_not_of(" \t\r\n");
        const bool cutShort = first != std::string::npos && (*all)[first] == '{';
        return Error{ErrorKind::BadInput, projectPath,
                     cutShort ? "the project file is damaged or cut short (not valid JSON at byte " +
                                    std::to_string(e.byte) + ")"
                              : "not a DryTwin project (not JSON)"};
    } catch (const json::exception& e) {
        // A number no double holds (1e400) is the parser's out_of_range, not a parse_error: it
        // ended the program (a trainer's session file closed the whole window).
        return Error{ErrorKind::BadInput, projectPath,
                     "the project file is damaged (" + std::string(e.what()) + ")"};
    }
    if (!o.is_object() || text(o, "format") != "drytwin-project") {
        return Error{ErrorKind::BadInput, projectPath,
                     "not a DryTwin project (no \"format\": \"drytwin-project\")"};
    }
    const fs::path base = fs::absolute(fs::path(projectPath)).parent_path();
    const auto resolve = [&base](const json& from, const std::string& key) {
        const std::string relative = text(from, key);
        if (relative.empty()) {
            return std::string();
        }
        fs::path here = (base / relative).lexically_normal();
        // "." (the data beside the project) normalises to "folder/": without its trailing
        // separator, so that the folder keeps its name ("demo (3 batches)", not " (3 batches)").
        if (!here.has_filename() && here.has_parent_path() && here != here.root_path()) {
            here = here.parent_path();
        }
        const std::string saved = text(from, key + "_absolute");
        std::error_code ec;
        return fs::exists(here, ec) || saved.empty() || !fs::exists(saved, ec) ? here.string() : saved;
    };
    ProjectPaths p;
    p.data = resolve(o, "data_path");
    p.mapping = resolve(o, "mapping_path");
    p.model = resolve(o, "model_path");
    p.results = resolve(o, "results_path");
    p.reference = resolve(o, "reference_path");
    p.dataFingerprint = text(o, "data_fingerprint");
    if (const auto sets = o.find("data_sets"); sets != o.end() && sets->is_array()) {
        for (const auto& e : *sets) {
            if (e.is_object() && !resolve(e, "path").empty()) {
                const auto batches = e.find("batches");
                p.dataSets.push_back(
                    {text(e, "label"), resolve(e, "path"), resolve(e, "mapping_path"),
                     resolve(e, "results_path"),
                     batches != e.end() && batches->is_number_integer() ? batches->get<int>() : -1,
                     resolve(e, "suggested_reference")});
            }
        }
    }
    return p;
}

namespace {

constexpr const char* kValuesTag = " values:";

/// FNV-1a, 64 bit: a digest that is the same on every machine and build (std::hash is not), to
/// recognise changed data, not to resist tampering; a cryptographic hash library is not needed.
class Fnv1a {
public:
    void add(const std::string& text) {
        for (const unsigned char c : text) {
            m_state = (m_state ^ c) * 1099511628211ULL;
        }
        m_state = (m_state ^ 0xffU) * 1099511628211ULL; // a separator, so "ab","c" ≠ "a","bc"
    }
    void add(double value) {
        char buffer[32];
        std::snprintf(buffer, sizeof buffer, "%.17g", value);
        add(std::string(buffer));
    }
    std::string hex() const {
        char buffer[17];
        std::snprintf(buffer, sizeof buffer, "%016llx", static_cast<unsigned long long>(m_state));
        return buffer;
    }

private:
    std::uint64_t m_state = 14695981039346656037ULL;
};

std::string batchesAndRows(const std::string& fingerprint) {
    return fingerprint.substr(0, fingerprint.find(kValuesTag));
}

} // namespace

std::string dataFingerprint(const data::DataSetSummary& summary) {
    std::string out;
    // The values enter through what the summary keeps of them: each column's range, mean and gaps
    // in file units and each batch's time span, all at full precision; one value edited in a file
    // moves its column's mean.
    Fnv1a values;
    for (const auto& b : summary.batches) {
        out += (out.empty() ? "" : " ") + b.id + ":" + std::to_string(b.rows);
        values.add(b.id);
        values.add(b.startS);
        values.add(b.endS);
        values.add(static_cast<double>(b.missing));
        values.add(static_cast<double>(b.droppedByCleaning));
    }
    for (const auto& c : summary.columns) {
        values.add(c.name);
        values.add(c.unit);
        if (c.present) {
            values.add(c.min);
            values.add(c.max);
            values.add(c.mean);
            values.add(static_cast<double>(c.missing));
        }
    }
    return out + kValuesTag + values.hex();
}

std::optional<DataChange> dataChangeSince(const std::string& saved, const std::string& now) {
    const bool savedHasValues = saved.find(kValuesTag) != std::string::npos;
    if (savedHasValues ? saved == now : saved == batchesAndRows(now)) {
        return std::nullopt;
    }
    DataChange change{batchesAndRows(saved), batchesAndRows(now), false};
    change.valuesOnly = change.batchesThen == change.batchesNow;
    return change;
}

std::string DataChange::describe() const {
    if (valuesOnly) {
        return "the same batches and rows (" + batchesNow +
               ") hold other values than when the results were made";
    }
    return "batches and rows then: " + (batchesThen.empty() ? "none" : batchesThen) +
           "; now: " + (batchesNow.empty() ? "none" : batchesNow);
}

std::vector<std::string> stepsMissingForReport(const LatestResults& latest) {
    std::vector<std::string> missing;
    bool learnt = latest.train.has_value();
    if (latest.evaluate) {
        for (const auto& m : latest.evaluate->evaluation.models) {
            learnt = learnt || m.name == "pgrl_cc";
        }
    }
    const std::pair<bool, const char*> steps[] = {
        {latest.calibrate.has_value(), "calibrate"}, {learnt, "train"},
        {latest.evaluate.has_value(), "evaluate"},   {latest.ablation.has_value(), "ablation"},
        {latest.discover.has_value(), "discover"},   {latest.mpc.has_value(), "mpc"}};
    for (const auto& [done, name] : steps) {
        if (!done) {
            missing.emplace_back(name);
        }
    }
    return missing;
}

Expected<PipelineResult> reportInputs(const LatestResults& latest, const data::DataSetSummary& inspect) {
    if (const auto missing = stepsMissingForReport(latest); !missing.empty()) {
        std::string list;
        for (const auto& m : missing) {
            list += (list.empty() ? "" : ", ") + m;
        }
        return Error{ErrorKind::Usage, "report",
                     "the report needs every step's result; still to run: " + list};
    }
    PipelineResult r;
    r.inspect = inspect;
    r.calibrate = *latest.calibrate;
    if (latest.train) {
        r.train = *latest.train;
    }
    r.evaluate = *latest.evaluate;
    r.ablation = *latest.ablation;
    r.discover = *latest.discover;
    r.mpc = *latest.mpc;
    return r;
}

} // namespace drytwin::workflow
