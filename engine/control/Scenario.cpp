#include "control/Scenario.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace drytwin::control {

namespace {

using nlohmann::json;

/// Line (1-based) of a byte offset.
int lineAt(const std::string& text, std::size_t offset) {
    offset = std::min(offset, text.size());
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(offset), '\n'));
}

/// Where a value sits in the text: the @p index-th occurrence of "key" after "section" (or from
/// the start). nlohmann::json keeps no positions; keys in a scenario are few and distinctive.
int lineOf(const std::string& text, const std::string& section, int index, const std::string& key) {
    std::size_t pos = 0;
    if (!section.empty()) {
        const auto s = text.find('"' + section + '"');
        if (s == std::string::npos) {
            return 1;
        }
        pos = s;
    }
    const std::string quoted = '"' + key + '"';
    for (int i = 0; i <= index; ++i) {
        const auto f = text.find(quoted, pos);
        if (f == std::string::npos) {
            return lineAt(text, pos);
        }
        pos = f + (i < index ? quoted.size() : 0);
    }
    return lineAt(text, pos);
}

struct Reader {
    const std::string& text;
    const std::string& place;

    Error error(const std::string& section, int index, const std::string& key,
                const std::string& reason) const {
        const std::string where = section.empty() ? key : section + "[" + std::to_string(index) + "]." + key;
        return Error{ErrorKind::BadInput, place + ":" + std::to_string(lineOf(text, section, index, key)),
                     where + ": " + reason};
    }

    /// A number within [lo, hi]; absent: the default.
    Expected<double> number(const json& j, const std::string& key, double fallback, double lo, double hi,
                            const std::string& section = {}, int index = 0, bool required = false) const {
        if (!j.contains(key)) {
            if (required) {
                return Error{ErrorKind::BadInput, place + ":" + std::to_string(lineAt(text, 0)),
                             (section.empty() ? key : section + "[" + std::to_string(index) + "]." + key) +
                                 ": missing"};
            }
            return fallback;
        }
        const json& v = j.at(key);
        if (!v.is_number()) {
            return error(section, index, key, "must be a number");
        }
        const double x = v.get<double>();
        if (!std::isfinite(x) || x < lo || x > hi) {
            std::ostringstream s;
            s << "must lie in [" << lo << ", " << hi << "], is " << x;
            return error(section, index, key, s.str());
        }
        return x;
    }

    Status onlyKeys(const json& j, const std::set<std::string>& known, const std::string& section,
                    int index) const {
        for (auto it = j.begin(); it != j.end(); ++it) {
            if (!known.count(it.key())) {
                return error(section, index, it.key(), "unknown key (docs/mpc.md lists the schema)");
            }
        }
        return {};
    }
};

#define DT_TRY_ASSIGN(target, expr)                                                                          \
    do {                                                                                                     \
        auto dtValue = (expr);                                                                               \
        if (!dtValue) {                                                                                      \
            return dtValue.error();                                                                          \
        }                                                                                                    \
        (target) = *dtValue;                                                                                 \
    } while (0)

} // namespace

double Scenario::setpointAt(double t) const {
    double sp = setpointPct;
    for (const auto& s : setpointSteps) {
        if (t >= s.atS) {
            sp = s.toPct;
        }
    }
    return sp;
}

Status Scenario::validate() const {
    if (lengthS < 10 || lengthS > 200000 || warmupS < 0 || warmupS > 20000) {
        return Error{ErrorKind::BadInput, "scenario " + name,
                     "length_s must lie in [10, 200000], warmup_s in [0, 20000]"};
    }
    if (controlIntervalS < 1 || controlIntervalS > 60) {
        return Error{ErrorKind::BadInput, "scenario " + name, "control_interval_s must lie in [1, 60]"};
    }
    for (std::size_t i = 1; i < setpointSteps.size(); ++i) {
        if (setpointSteps[i].atS < setpointSteps[i - 1].atS) {
            return Error{ErrorKind::BadInput, "scenario " + name, "setpoint_steps must be in time order"};
        }
    }
    return {};
}

Expected<Scenario> parseScenario(const std::string& text, const std::string& place) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        return Error{ErrorKind::BadInput,
                     place + ":" + std::to_string(lineAt(text, e.byte > 0 ? e.byte - 1 : 0)),
                     "not valid JSON (" + std::string(e.what()) + ")"};
    } catch (const json::exception& e) {
        // A number no double holds (1e400) is the parser's out_of_range, not a parse_error: it
        // ended the program (a trainer's session file closed the whole window).
        return Error{ErrorKind::BadInput, place, "not valid JSON (" + std::string(e.what()) + ")"};
    }
    if (!j.is_object()) {
        return Error{ErrorKind::BadInput, place + ":1", "a scenario is a JSON object"};
    }
    const Reader r{text, place};
    if (auto st = r.onlyKeys(j,
                             {"name", "description", "seed", "length_s", "warmup_s", "control_interval_s",
                              "initial", "band_pct", "fluctuation", "noise_scale", "unmeasured_drift",
                              "plant", "sensors", "setpoint_steps", "input_changes", "mechanisms"},
                             {}, 0);
        !st) {
        return st.error();
    }
    Scenario s;
    if (j.contains("name")) {
        if (!j["name"].is_string()) {
            return r.error({}, 0, "name", "must be a string");
        }
        s.name = j["name"].get<std::string>();
    }
    if (j.contains("description") && j["description"].is_string()) {
        s.description = j["description"].get<std::string>();
    }
    double v = 0;
    DT_TRY_ASSIGN(v, r.number(j, "seed", 1, 0, 4294967295.0));
    s.seed = static_cast<unsigned>(v);
    DT_TRY_ASSIGN(v, r.number(j, "length_s", 1000, 10, 200000));
    s.lengthS = static_cast<int>(v);
    DT_TRY_ASSIGN(v, r.number(j, "warmup_s", 300, 0, 20000));
    s.warmupS = static_cast<int>(v);
    DT_TRY_ASSIGN(v, r.number(j, "control_interval_s", 2, 1, 60));
    s.controlIntervalS = static_cast<int>(v);
    DT_TRY_ASSIGN(s.bandPct, r.number(j, "band_pct", 0.5, 0.01, 5));
    DT_TRY_ASSIGN(s.fluctuation, r.number(j, "fluctuation", 1, 0, 5));
    DT_TRY_ASSIGN(s.noiseScale, r.number(j, "noise_scale", 1, 0, 10));
    if (j.contains("plant")) {
        if (!j["plant"].is_string() || (j["plant"] != "distributed" && j["plant"] != "lumped")) {
            return r.error({}, 0, "plant", "must be \"distributed\" or \"lumped\"");
        }
        s.plant = j["plant"] == "distributed" ? plant::PlantKind::Distributed : plant::PlantKind::Lumped;
    }
    if (j.contains("sensors")) {
        if (!j["sensors"].is_string() || (j["sensors"] != "realistic" && j["sensors"] != "ideal")) {
            return r.error({}, 0, "sensors", "must be \"realistic\" or \"ideal\"");
        }
        s.sensors = j["sensors"] == "ideal" ? plant::SensorMode::Ideal : plant::SensorMode::Realistic;
    }
    if (j.contains("unmeasured_drift")) {
        if (!j["unmeasured_drift"].is_boolean()) {
            return r.error({}, 0, "unmeasured_drift", "must be true or false");
        }
        s.unmeasuredDrift = j["unmeasured_drift"].get<bool>();
    }
    if (j.contains("initial")) {
        const json& in = j["initial"];
        if (!in.is_object()) {
            return r.error({}, 0, "initial", "must be an object");
        }
        if (auto st = r.onlyKeys(
                in, {"setpoint_pct", "feed_kg_h", "x_in_pct", "t_in_c", "t_amb_c", "rh_pct", "air_speed_m_s"},
                {}, 0);
            !st) {
            return st.error();
        }
        DT_TRY_ASSIGN(s.setpointPct, r.number(in, "setpoint_pct", 13, 8, 20));
        DT_TRY_ASSIGN(s.feedKgH, r.number(in, "feed_kg_h", 6200, 3000, 9000));
        DT_TRY_ASSIGN(s.xInPct, r.number(in, "x_in_pct", 22, 15, 30));
        DT_TRY_ASSIGN(s.tInC, r.number(in, "t_in_c", 25, 5, 60));
        DT_TRY_ASSIGN(s.tAmbC, r.number(in, "t_amb_c", 22, 0, 45));
        DT_TRY_ASSIGN(s.rhPct, r.number(in, "rh_pct", 50, 5, 95));
        DT_TRY_ASSIGN(s.airSpeedMPerS, r.number(in, "air_speed_m_s", 16, 8, 25));
    }
    const double end = s.lengthS;
    if (j.contains("setpoint_steps")) {
        if (!j["setpoint_steps"].is_array()) {
            return r.error({}, 0, "setpoint_steps", "must be a list");
        }
        int i = 0;
        for (const json& e : j["setpoint_steps"]) {
            if (!e.is_object()) {
                return r.error({}, 0, "setpoint_steps", "entries must be objects");
            }
            if (auto st = r.onlyKeys(e, {"at_s", "to_pct"}, "setpoint_steps", i); !st) {
                return st.error();
            }
            SetpointStep step;
            DT_TRY_ASSIGN(step.atS, r.number(e, "at_s", 0, 0, end, "setpoint_steps", i, true));
            DT_TRY_ASSIGN(step.toPct, r.number(e, "to_pct", 0, 8, 20, "setpoint_steps", i, true));
            if (!s.setpointSteps.empty() && step.atS < s.setpointSteps.back().atS) {
                return r.error("setpoint_steps", i, "at_s", "steps must be in time order");
            }
            s.setpointSteps.push_back(step);
            ++i;
        }
    }
    if (j.contains("input_changes")) {
        if (!j["input_changes"].is_array()) {
            return r.error({}, 0, "input_changes", "must be a list");
        }
        int i = 0;
        for (const json& e : j["input_changes"]) {
            if (!e.is_object()) {
                return r.error({}, 0, "input_changes", "entries must be objects");
            }
            if (auto st = r.onlyKeys(e, {"input", "at_s", "duration_s", "to"}, "input_changes", i); !st) {
                return st.error();
            }
            InputChange c;
            const std::string input = e.value("input", std::string());
            double lo = 0, hi = 0;
            if (input == "feed_kg_h") {
                c.input = ScenarioInput::Feed;
                lo = 3000;
                hi = 9000;
            } else if (input == "x_in_pct") {
                c.input = ScenarioInput::InletMoisture;
                lo = 15;
                hi = 30;
            } else if (input == "t_amb_c") {
                c.input = ScenarioInput::Ambient;
                lo = 0;
                hi = 45;
            } else if (input == "rh_pct") {
                c.input = ScenarioInput::Humidity;
                lo = 5;
                hi = 95;
            } else {
                return r.error("input_changes", i, "input",
                               "must be one of feed_kg_h, x_in_pct, t_amb_c, rh_pct, is \"" + input + "\"");
            }
            DT_TRY_ASSIGN(c.atS, r.number(e, "at_s", 0, 0, end, "input_changes", i, true));
            DT_TRY_ASSIGN(c.durationS, r.number(e, "duration_s", 0, 0, end, "input_changes", i));
            DT_TRY_ASSIGN(c.to, r.number(e, "to", 0, lo, hi, "input_changes", i, true));
            s.inputChanges.push_back(c);
            ++i;
        }
    }
    if (j.contains("mechanisms")) {
        if (!j["mechanisms"].is_array()) {
            return r.error({}, 0, "mechanisms", "must be a list");
        }
        int i = 0;
        for (const json& e : j["mechanisms"]) {
            if (!e.is_object()) {
                return r.error({}, 0, "mechanisms", "entries must be objects");
            }
            if (auto st = r.onlyKeys(e, {"mechanism", "strength", "at_s"}, "mechanisms", i); !st) {
                return st.error();
            }
            HiddenMechanism m;
            const std::string name = e.value("mechanism", std::string());
            const auto id = plant::mechanismByName(name);
            if (!id) {
                return r.error("mechanisms", i, "mechanism",
                               "\"" + name + "\" is not a mechanism of CONTRACT.md §4");
            }
            m.mechanism = *id;
            const auto& inf = plant::info(*id);
            DT_TRY_ASSIGN(m.strength, r.number(e, "strength", 0, 0, inf.maxStrength, "mechanisms", i, true));
            DT_TRY_ASSIGN(m.atS, r.number(e, "at_s", 0, 0, end, "mechanisms", i));
            for (const auto& other : s.mechanisms) {
                if (other.mechanism == m.mechanism) {
                    return r.error("mechanisms", i, "mechanism", "\"" + name + "\" is listed twice");
                }
            }
            s.mechanisms.push_back(m);
            ++i;
        }
    }
    if (auto st = s.validate(); !st) {
        return st.error();
    }
    return s;
}

Expected<Scenario> loadScenario(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    if (!f) {
        return Error{
            ErrorKind::BadInput, path, "cannot open the scenario file", ErrorCode::FileNotFound, {path}};
    }
    std::ostringstream ss;
    ss << f.rdbuf();
    return parseScenario(ss.str(), path);
}

std::string_view Scenario::instrumentsName() const {
    if (sensors == plant::SensorMode::Ideal) {
        return "ideal";
    }
    const bool realistic = sensors == plant::SensorMode::Realistic ||
                           (sensors == plant::SensorMode::Default && plant == plant::PlantKind::Distributed);
    return realistic ? "realistic" : "builtin";
}

} // namespace drytwin::control
