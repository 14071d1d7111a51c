#include "io/ModelFile.h"

#include "common/AtomicFile.h"
#include "plant/Mechanisms.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <set>

namespace drytwin::io {

using nlohmann::json;
using properties::Param;

namespace {

using hybrid::HybridModel;

/// Keys this version writes; every other top-level key is kept as a foreign key.
constexpr const char* kKnownKeys[] = {
    "format",     "format_version",  "parameters",       "switches",           "winnower_form", "calibration",
    "mechanisms", "residual_models", hybrid::kPgrlCcKey, hybrid::kExtInputKey, hybrid::kLstmKey};

/// The paper's parameters; the mechanism extensions go under "mechanisms" (CONTRACT.md §2).
json parametersJson(const properties::ParameterSet& p) {
    json j = json::object();
    for (const auto& i : properties::parameterTable()) {
        if (!properties::mechanismOf(i.id)) {
            j[std::string(i.symbol)] = {{"value", p[i.id]}, {"unit", std::string(i.unit)}};
        }
    }
    return j;
}

const char* winnowerName(physics::WinnowerForm f) {
    return f == physics::WinnowerForm::Transient ? "transient" : "terminal";
}

} // namespace

std::string modelFingerprint(const HybridModel& m) {
    // FNV-1a (64 bit) of the model file's text. Hand-written because it is a change detector, not
    // a security measure, and the engine links no hash library (Qt's QCryptographicHash lies
    // outside it, ARCHITECTURE.md); the text is the file's, so a model written and read back keeps
    // its fingerprint.
    std::uint64_t hash = 14695981039346656037ULL;
    for (const unsigned char c : formatModelFile(m)) {
        hash = (hash ^ c) * 1099511628211ULL;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(hash));
    return hex;
}

std::string formatModelFile(const HybridModel& m) {
    json j = json::object();
    for (const auto& [key, text] : m.foreignKeys) {
        j[key] = json::parse(text);
    }
    j["format"] = "drytwin-model";
    j["format_version"] = kModelFormatVersion;
    j["parameters"] = parametersJson(m.parameters);
    j["switches"] = {{"clamp_water_activity", m.switches.clampWaterActivity},
                     {"latent_heat_correction", m.switches.latentHeatCorrection},
                     {"moisture_dependent_cp", m.switches.moistureDependentCp},
                     {"consistent_energy_balance", m.switches.consistentEnergyBalance}};
    j["winnower_form"] = winnowerName(m.winnower);
    if (m.calibration) {
        json c;
        for (const auto& e : m.calibration->estimates) {
            c["estimates"][e.symbol] = {
                {"value", e.value}, {"ci95", {e.ci95Low, e.ci95High}}, {"at_bound", e.atBound}};
            if (std::isfinite(e.standardErrorFisher)) {
                c["estimates"][e.symbol]["standard_error_fisher"] = e.standardErrorFisher;
            }
        }
        c["interval_method"] = m.calibration->intervalMethod;
        c["loss_before"] = m.calibration->lossBefore;
        c["loss_after"] = m.calibration->lossAfter;
        c["evaluations"] = m.calibration->evaluations;
        c["seed"] = m.calibration->seed;
        c["algorithm"] = m.calibration->algorithm;
        j["calibration"] = c;
    }
    // A mechanism is written when the model uses it or discovery left its interval.
    j["mechanisms"] = json::object();
    for (const properties::Param p : properties::mechanismParams()) {
        const std::string name(*properties::mechanismOf(p));
        const double value = m.parameters[p];
        const auto it = m.mechanisms.find(name);
        if (value == 0 && it == m.mechanisms.end()) {
            continue;
        }
        json entry = {{"value", value},
                      {"unit", std::string(properties::info(p).unit)},
                      {"parameter", std::string(properties::info(p).symbol)}};
        if (it != m.mechanisms.end()) {
            entry["ci95"] = {it->second.ci95Low, it->second.ci95High};
        }
        j["mechanisms"][name] = entry;
    }
    if (m.hasResidualModels()) {
        json r = json::object();
        if (m.pgrlCc) {
            r[hybrid::kPgrlCcKey] = json::parse(m.pgrlCc->toJson());
        }
        if (m.extInput) {
            r[hybrid::kExtInputKey] = json::parse(m.extInput->toJson());
        }
        if (m.lstm) {
            r[hybrid::kLstmKey] = json::parse(m.lstm->toJson());
        }
        j["residual_models"] = r;
    }
    return j.dump(2) + "\n";
}

Status writeModelFile(const HybridModel& model, const std::string& path) {
    return writeFileAtomically(path, formatModelFile(model));
}

namespace {
Expected<HybridModel> parseModelJson(const json& j, const std::string& name);
} // namespace

Expected<HybridModel> parseModelFile(const std::string& text, const std::string& name) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        return Error{ErrorKind::BadInput, name + ":byte " + std::to_string(e.byte),
                     std::string("invalid JSON: ") + e.what()};
    } catch (const json::exception& e) {
        // A number no double holds (1e400) is the parser's out_of_range, not a parse_error: it
        // ended the program (a trainer's session file closed the whole window).
        return Error{ErrorKind::BadInput, name, std::string("invalid JSON: ") + e.what()};
    }
    // A key of the wrong type (null where a number belongs ...) is an error naming the file, never
    // an exception across the engine's boundary.
    try {
        return parseModelJson(j, name);
    } catch (const json::exception& e) {
        return Error{ErrorKind::BadInput,
                     name,
                     std::string("a key has the wrong type: ") + e.what(),
                     ErrorCode::ModelFileInvalid,
                     {name, "", e.what()}};
    }
}

namespace {

/// A unit as written by hand or by DryTwin, reduced to what tells units apart: "W/(m2 K)",
/// "W/(m^2*K)" and "W/(m²·K)" are one unit; "kW/(m²·K)" is another.
std::string unitSpelling(const std::string& unit) {
    std::string out;
    for (std::size_t i = 0; i < unit.size(); ++i) {
        const auto rest = std::string_view(unit).substr(i);
        if (rest.rfind("²", 0) == 0 || rest.rfind("³", 0) == 0) {
            out += rest.rfind("²", 0) == 0 ? '2' : '3';
            i += std::string_view("²").size() - 1;
        } else if (rest.rfind("·", 0) == 0) {
            i += std::string_view("·").size() - 1;
        } else if (unit[i] != ' ' && unit[i] != '*' && unit[i] != '^') {
            out += unit[i];
        }
    }
    return out;
}

Expected<HybridModel> parseModelJson(const json& j, const std::string& name) {
    auto bad = [&](const std::string& key, const std::string& why) {
        return Error{
            ErrorKind::BadInput, name + ": " + key, why, ErrorCode::ModelFileInvalid, {name, key, why}};
    };
    if (!j.is_object() || j.value("format", "") != "drytwin-model") {
        return bad("format", "not a DryTwin model file (expected \"format\": \"drytwin-model\")");
    }
    if (!j.contains("format_version") || !j["format_version"].is_number_integer()) {
        return bad("format_version", "missing or not an integer");
    }
    if (j["format_version"].get<int>() > kModelFormatVersion) {
        return bad("format_version", "version " + std::to_string(j["format_version"].get<int>()) +
                                         " is newer than this DryTwin reads (" +
                                         std::to_string(kModelFormatVersion) + ")");
    }
    const int version = j["format_version"].get<int>();
    HybridModel m;
    std::set<properties::Param> present;
    if (j.contains("parameters")) {
        if (!j["parameters"].is_object()) {
            return bad("parameters", "must be an object keyed by parameter symbol");
        }
        for (const auto& [symbol, entry] : j["parameters"].items()) {
            const auto id = properties::paramBySymbol(symbol);
            if (!id) {
                return bad("parameters." + symbol, "unknown parameter symbol");
            }
            const json& v = entry.is_object() ? entry.value("value", json()) : entry;
            if (!v.is_number()) {
                return bad("parameters." + symbol, "\"value\" must be a number");
            }
            // A unit other than DryTwin's would be read as DryTwin's (72 kW as 72 W): refused.
            const auto& expected = properties::info(*id).unit;
            if (entry.is_object() && entry.contains("unit") &&
                (!entry["unit"].is_string() ||
                 unitSpelling(entry["unit"].get<std::string>()) != unitSpelling(std::string(expected)))) {
                return bad("parameters." + symbol + ".unit",
                           "is " + entry["unit"].dump() + "; DryTwin reads this parameter in " +
                               std::string(expected) + ": convert the value and write that unit");
            }
            m.parameters[*id] = v.get<double>();
            present.insert(*id);
        }
        // A parameter the file lacks takes its default; the user is told, unless it is a
        // mechanism's (absent: the mechanism is not in the model, which is what 0 means).
        std::string absent;
        std::size_t count = 0;
        for (const auto& i : properties::parameterTable()) {
            if (!present.count(i.id) && !i.fixed && !properties::mechanismOf(i.id)) {
                char text[160];
                std::snprintf(text, sizeof text, "%s%s %g %s", count ? ", " : "",
                              std::string(i.symbol).c_str(), i.defaultValue, std::string(i.unit).c_str());
                absent += text;
                ++count;
            }
        }
        if (count > 0) {
            m.readNotes.push_back(name + ": " + std::to_string(count) +
                                  " parameter(s) not in the file take " +
                                  (count == 1 ? "its default: " : "their defaults: ") + absent);
        }
    }
    if (auto st = m.parameters.validate(); !st) {
        return bad("parameters." + st.error().place, st.error().reason);
    }
    if (j.contains("switches")) {
        const json& s = j["switches"];
        m.switches.clampWaterActivity = s.value("clamp_water_activity", true);
        m.switches.latentHeatCorrection = s.value("latent_heat_correction", true);
        m.switches.moistureDependentCp = s.value("moisture_dependent_cp", true);
        // Files from before the switch existed were made with the paper's printed form.
        m.switches.consistentEnergyBalance = s.value("consistent_energy_balance", false);
    }
    const std::string form = j.value("winnower_form", "transient");
    if (form != "transient" && form != "terminal") {
        return bad("winnower_form", "must be \"transient\" or \"terminal\"");
    }
    m.winnower = form == "transient" ? physics::WinnowerForm::Transient : physics::WinnowerForm::Terminal;
    if (j.contains("calibration")) {
        const json& c = j["calibration"];
        m.calibration.emplace();
        if (c.contains("interval_method") && c["interval_method"].is_string()) {
            m.calibration->intervalMethod = c["interval_method"].get<std::string>();
        }
        if (c.contains("estimates")) {
            for (const auto& [symbol, e] : c["estimates"].items()) {
                hybrid::CalibrationRecord::Estimate est;
                est.symbol = symbol;
                est.value = e.value("value", 0.0);
                if (e.contains("ci95") && e["ci95"].is_array() && e["ci95"].size() == 2) {
                    // Unknown intervals are written as null (NaN in JSON has no other form).
                    const auto bound = [](const json& v) {
                        return v.is_number() ? v.get<double>() : std::nan("");
                    };
                    est.ci95Low = bound(e["ci95"][0]);
                    est.ci95High = bound(e["ci95"][1]);
                }
                est.atBound = e.value("at_bound", false);
                est.standardErrorFisher =
                    e.contains("standard_error_fisher") && e["standard_error_fisher"].is_number()
                        ? e["standard_error_fisher"].get<double>()
                        : std::nan("");
                m.calibration->estimates.push_back(est);
            }
        }
        m.calibration->lossBefore = c.value("loss_before", 0.0);
        m.calibration->lossAfter = c.value("loss_after", 0.0);
        m.calibration->evaluations = c.value("evaluations", 0);
        m.calibration->seed = c.value("seed", 0u);
        m.calibration->algorithm = c.value("algorithm", "");
    }
    if (j.contains("mechanisms")) {
        if (!j["mechanisms"].is_object()) {
            return bad("mechanisms", "must be an object keyed by mechanism name");
        }
        for (const auto& [mechanism, entry] : j["mechanisms"].items()) {
            const auto param = properties::mechanismParam(mechanism);
            if (!param) {
                return bad("mechanisms." + mechanism, "unknown mechanism (CONTRACT.md §4 lists the names)");
            }
            if (!entry.is_object() || !entry.value("value", json()).is_number()) {
                return bad("mechanisms." + mechanism,
                           "must be {\"value\": number, \"unit\": ..., \"ci95\": [lo, hi]}");
            }
            hybrid::MechanismValue v;
            v.value = entry["value"].get<double>();
            v.unit = std::string(properties::info(*param).unit);
            v.ci95Low = v.ci95High = v.value;
            if (entry.contains("ci95") && entry["ci95"].is_array() && entry["ci95"].size() == 2 &&
                entry["ci95"][0].is_number() && entry["ci95"][1].is_number()) {
                v.ci95Low = entry["ci95"][0].get<double>();
                v.ci95High = entry["ci95"][1].get<double>();
                m.mechanisms[mechanism] = v;
            }
            m.parameters[*param] = v.value;
        }
        if (auto st = m.parameters.validate(); !st) {
            return bad("mechanisms." + st.error().place, st.error().reason);
        }
    }
    // Version 1 kept the learnt models at the top level; version 2 under "residual_models".
    const json* stored = &j;
    if (version >= 2 && j.contains("residual_models")) {
        if (!j["residual_models"].is_object()) {
            return bad("residual_models", "must be an object keyed by model");
        }
        stored = &j["residual_models"];
    }
    const std::string prefix = stored == &j ? "" : "residual_models.";
    for (const char* key : {hybrid::kPgrlCcKey, hybrid::kExtInputKey}) {
        if (!stored->contains(key)) {
            continue;
        }
        auto rm = residual::ResidualModel::fromJson((*stored)[key].dump());
        if (!rm) {
            return bad(prefix + key, rm.error().reason);
        }
        auto shared = std::make_shared<const residual::ResidualModel>(std::move(*rm));
        (std::string(key) == hybrid::kPgrlCcKey ? m.pgrlCc : m.extInput) = std::move(shared);
    }
    if (stored->contains(hybrid::kLstmKey)) {
        auto lstm = baselines::LstmBaseline::fromJson((*stored)[hybrid::kLstmKey].dump());
        if (!lstm) {
            return bad(prefix + hybrid::kLstmKey, lstm.error().reason);
        }
        m.lstm = std::make_shared<const baselines::LstmBaseline>(std::move(*lstm));
    }
    for (const auto& [key, value] : j.items()) {
        if (std::find(std::begin(kKnownKeys), std::end(kKnownKeys), key) == std::end(kKnownKeys)) {
            m.foreignKeys[key] = value.dump();
        }
    }
    return m;
}

} // namespace

Expected<HybridModel> readModelFile(const std::string& path) {
    auto text = readWholeFile(path);
    if (!text) {
        return text.error();
    }
    return parseModelFile(*text, path);
}

std::string truthJson(const plant::PlantOptions& options, const plant::PlantResult& result) {
    json j;
    j["parameters"] = parametersJson(result.truth);
    j["effects"] = json::object();
    for (const auto& [m, s] : result.effects) {
        if (s > 0) {
            j["effects"][std::string(plant::info(m).name)] = s;
        }
    }
    // When each mechanism sets in, seconds from every batch's start (absent: from the start).
    j["effect_onsets_s"] = json::object();
    for (const auto& [m, onset] : options.effectOnsetS) {
        if (result.effects.count(m) && result.effects.at(m) > 0) {
            j["effect_onsets_s"][std::string(plant::info(m).name)] = onset;
        }
    }
    j["seed"] = options.seed;
    j["unmeasured_drift"] = options.unmeasuredDrift;
    j["plant"] = std::string(plant::plantKindName(options.plant));
    json sensors;
    const bool realistic = options.realisticSensors();
    sensors["mode"] = realistic                                     ? "realistic"
                      : options.sensors == plant::SensorMode::Ideal ? "ideal"
                                                                    : "lumped_builtin";
    if (realistic) {
        json channels = json::object();
        const auto& specs = plant::realisticSensors();
        for (std::size_t c = 0; c < specs.size(); ++c) {
            const auto& sp = specs[c];
            const auto& n = result.sensorFaultCounts[c];
            channels[std::string(sp.column)] = {{"noise_sd", sp.noiseSd},
                                                {"noise_correlation_s", sp.noiseCorrelationS},
                                                {"relative_noise", sp.relativeNoise},
                                                {"lag_s", sp.lagS},
                                                {"quantum", sp.quantum},
                                                {"spike_size", sp.spikeSize},
                                                {"spikes", n.spikes},
                                                {"stuck", n.stuck},
                                                {"dropouts", n.dropouts}};
        }
        sensors["channels"] = channels;
        sensors["fault_rates_per_hour"] = {{"spikes", options.sensorFaults.spikesPerHour},
                                           {"stuck", options.sensorFaults.stuckPerHour},
                                           {"dropouts", options.sensorFaults.dropoutsPerHour}};
    } else if (options.sensors != plant::SensorMode::Ideal) {
        sensors["noise_scale"] = options.noiseScale;
    }
    j["sensors"] = sensors;
    return j.dump(2) + "\n";
}

} // namespace drytwin::io
