#include "io/ModelFile.h"

#include "common/AtomicFile.h"

#include <nlohmann/json.hpp>

namespace drytwin::io {

using nlohmann::json;
using properties::Param;

namespace {

json parametersJson(const properties::ParameterSet& p) {
    json j = json::object();
    for (const auto& i : properties::parameterTable()) {
        j[std::string(i.symbol)] = {{"value", p[i.id]}, {"unit", std::string(i.unit)}};
    }
    return j;
}

const char* winnowerName(physics::WinnowerForm f) {
    return f == physics::WinnowerForm::Transient ? "transient" : "terminal";
}

} // namespace

std::string formatModelFile(const ModelFile& m) {
    json j = json::parse(m.extraJson.empty() ? "{}" : m.extraJson);
    j["format"] = "drytwin-model";
    j["format_version"] = kModelFormatVersion;
    j["parameters"] = parametersJson(m.parameters);
    j["switches"] = {{"clamp_water_activity", m.switches.clampWaterActivity},
                     {"latent_heat_correction", m.switches.latentHeatCorrection},
                     {"moisture_dependent_cp", m.switches.moistureDependentCp}};
    j["winnower_form"] = winnowerName(m.winnower);
    if (m.hasCalibration) {
        json c;
        for (const auto& e : m.calibration.estimates) {
            c["estimates"][e.symbol] = {
                {"value", e.value}, {"ci95", {e.ci95Low, e.ci95High}}, {"at_bound", e.atBound}};
        }
        c["loss_before"] = m.calibration.lossBefore;
        c["loss_after"] = m.calibration.lossAfter;
        c["evaluations"] = m.calibration.evaluations;
        c["seed"] = m.calibration.seed;
        c["algorithm"] = m.calibration.algorithm;
        j["calibration"] = c;
    }
    return j.dump(2) + "\n";
}

Status writeModelFile(const ModelFile& model, const std::string& path) {
    return writeFileAtomically(path, formatModelFile(model));
}

Expected<ModelFile> parseModelFile(const std::string& text, const std::string& name) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        return Error{ErrorKind::BadInput, name + ":byte " + std::to_string(e.byte),
                     std::string("invalid JSON: ") + e.what()};
    }
    auto bad = [&](const std::string& key, const std::string& why) {
        return Error{ErrorKind::BadInput, name + ": " + key, why};
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
    ModelFile m;
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
            m.parameters[*id] = v.get<double>();
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
    }
    const std::string form = j.value("winnower_form", "transient");
    if (form != "transient" && form != "terminal") {
        return bad("winnower_form", "must be \"transient\" or \"terminal\"");
    }
    m.winnower = form == "transient" ? physics::WinnowerForm::Transient : physics::WinnowerForm::Terminal;
    if (j.contains("calibration")) {
        const json& c = j["calibration"];
        m.hasCalibration = true;
        if (c.contains("estimates")) {
            for (const auto& [symbol, e] : c["estimates"].items()) {
                CalibrationRecord::Estimate est;
                est.symbol = symbol;
                est.value = e.value("value", 0.0);
                if (e.contains("ci95") && e["ci95"].is_array() && e["ci95"].size() == 2) {
                    est.ci95Low = e["ci95"][0].get<double>();
                    est.ci95High = e["ci95"][1].get<double>();
                }
                est.atBound = e.value("at_bound", false);
                m.calibration.estimates.push_back(est);
            }
        }
        m.calibration.lossBefore = c.value("loss_before", 0.0);
        m.calibration.lossAfter = c.value("loss_after", 0.0);
        m.calibration.evaluations = c.value("evaluations", 0);
        m.calibration.seed = c.value("seed", 0u);
        m.calibration.algorithm = c.value("algorithm", "");
    }
    json extra = j;
    for (const char* k :
         {"format", "format_version", "parameters", "switches", "winnower_form", "calibration"}) {
        extra.erase(k);
    }
    m.extraJson = extra.dump();
    return m;
}

Expected<ModelFile> readModelFile(const std::string& path) {
    auto text = readWholeFile(path);
    if (!text) {
        return text.error();
    }
    return parseModelFile(*text, path);
}

std::string formatTruth(const properties::ParameterSet& truth,
                        const std::map<plant::Mechanism, double>& effects, unsigned seed,
                        bool unmeasuredDrift) {
    json j;
    j["parameters"] = parametersJson(truth);
    j["effects"] = json::object();
    for (const auto& [m, s] : effects) {
        if (s > 0) {
            j["effects"][std::string(plant::info(m).name)] = s;
        }
    }
    j["seed"] = seed;
    j["unmeasured_drift"] = unmeasuredDrift;
    return j.dump(2) + "\n";
}

} // namespace drytwin::io
