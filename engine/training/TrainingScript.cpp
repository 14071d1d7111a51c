#include "training/TrainingScript.h"

#include "common/AtomicFile.h"
#include "common/TextList.h"
#include "control/BundledScenarios.h"
#include "data/BatchWriter.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

namespace drytwin::training {

namespace {

using nlohmann::json;

Error eventError(const std::string& place, std::size_t i, const std::string& key, const std::string& reason) {
    return Error{ErrorKind::BadInput, place, "events[" + std::to_string(i) + "]." + key + ": " + reason};
}

Expected<double> eventNumber(const json& e, const std::string& key, const std::string& place, std::size_t i) {
    if (!e.contains(key)) {
        return eventError(place, i, key, "missing");
    }
    if (!e[key].is_number() || !std::isfinite(e[key].get<double>())) {
        return eventError(place, i, key, "must be a number");
    }
    return e[key].get<double>();
}

Expected<std::string> eventText(const json& e, const std::string& key, const std::string& place,
                                std::size_t i) {
    if (!e.contains(key) || !e[key].is_string() || e[key].get<std::string>().empty()) {
        return eventError(place, i, key, "must be a non-empty string");
    }
    return e[key].get<std::string>();
}

json eventJson(const SessionEvent& e) {
    json j{{"at_s", e.atS}, {"type", eventTypeName(e.type)}};
    switch (e.type) {
    case EventType::Setpoint:
        j["value_pct"] = e.value;
        break;
    case EventType::Controller:
        j["controller"] = e.text;
        break;
    case EventType::Fault:
        j["cause"] = e.text;
        j["strength"] = e.value;
        j["onset_s"] = e.onsetS;
        break;
    case EventType::Snapshot:
    case EventType::Restore:
        j["label"] = e.text;
        break;
    case EventType::Answer:
        j["cause"] = e.text;
        break;
    case EventType::Freeze:
    case EventType::Resume:
        break;
    }
    return j;
}

/// The controllers other than the PI loop a session switched to, in order of first use: the ones
/// that run on the model.
std::vector<std::string> modelControllersUsed(const std::vector<SessionEvent>& events) {
    std::vector<std::string> used;
    for (const auto& e : events) {
        if (e.type == EventType::Controller && e.text != "pi" &&
            std::find(used.begin(), used.end(), e.text) == used.end()) {
            used.push_back(e.text);
        }
    }
    return used;
}

} // namespace

Expected<TrainingScript> parseTrainingScript(const std::string& text, const std::string& place) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        return Error{ErrorKind::BadInput, place, "not valid JSON (" + std::string(e.what()) + ")"};
    } catch (const json::exception& e) {
        // A number no double holds (1e400) is the parser's out_of_range, not a parse_error: it
        // ended the program (a trainer's session file closed the whole window).
        return Error{ErrorKind::BadInput, place, "not valid JSON (" + std::string(e.what()) + ")"};
    }
    if (!j.is_object() || !j.contains("scenario")) {
        return Error{ErrorKind::BadInput, place, "a session file is a JSON object with a \"scenario\""};
    }
    TrainingScript script;
    script.place = place;
    const json& sc = j["scenario"];
    if (sc.is_string()) {
        const auto& bundled = control::bundledScenarios();
        const auto it = bundled.find(sc.get<std::string>());
        if (it == bundled.end()) {
            return Error{ErrorKind::BadInput, place,
                         "scenario: no bundled scenario named '" + sc.get<std::string>() + "'"};
        }
        script.scenarioJson = it->second;
    } else if (sc.is_object()) {
        script.scenarioJson = sc.dump(2);
    } else {
        return Error{ErrorKind::BadInput, place,
                     "scenario: must be a bundled scenario's name or a scenario object"};
    }
    auto scenario = control::parseScenario(script.scenarioJson, place + " (scenario)");
    if (!scenario) {
        return scenario.error();
    }
    script.scenario = *scenario;
    if (j.contains("end_s")) {
        if (!j["end_s"].is_number() || j["end_s"].get<double>() < 0 ||
            j["end_s"].get<double>() > script.scenario.lengthS) {
            return Error{ErrorKind::BadInput, place,
                         "end_s: must be a number within the scenario's length (0 … " +
                             std::to_string(script.scenario.lengthS) + " s)"};
        }
        script.endS = j["end_s"].get<double>();
    }
    if (j.contains("model") && j["model"].is_object() && j["model"].contains("fingerprint") &&
        j["model"]["fingerprint"].is_string()) {
        script.modelFingerprint = j["model"]["fingerprint"].get<std::string>();
    }
    if (j.contains("events")) {
        if (!j["events"].is_array()) {
            return Error{ErrorKind::BadInput, place, "events: must be a list"};
        }
        for (std::size_t i = 0; i < j["events"].size(); ++i) {
            const json& e = j["events"][i];
            if (!e.is_object()) {
                return eventError(place, i, "", "must be an object");
            }
            SessionEvent ev;
            // A key the event's type does not take is refused, as a scenario file's is: a
            // misspelt "onset" was ignored and the fault acted from its injection on.
            static const std::map<std::string, std::set<std::string>> keysOf = {
                {"setpoint", {"value_pct"}},
                {"controller", {"controller"}},
                {"fault", {"cause", "strength", "onset_s"}},
                {"snapshot", {"label"}},
                {"restore", {"label"}},
                {"answer", {"cause"}},
                {"freeze", {}},
                {"resume", {}}};
            if (e.contains("type") && e["type"].is_string()) {
                if (const auto known = keysOf.find(e["type"].get<std::string>()); known != keysOf.end()) {
                    for (const auto& [key, value] : e.items()) {
                        if (key != "at_s" && key != "type" && !known->second.count(key)) {
                            std::string allowed = "at_s, type";
                            for (const auto& k : known->second) {
                                allowed += ", " + k;
                            }
                            return eventError(place, i, key,
                                              "unknown key for a " + known->first + " event (it takes " +
                                                  allowed + "; docs/training.md lists them)");
                        }
                    }
                }
            }
            auto at = eventNumber(e, "at_s", place, i);
            if (!at) {
                return at.error();
            }
            if (*at < 0 || *at > script.scenario.lengthS) {
                return eventError(place, i, "at_s", "must lie within the scenario's length");
            }
            ev.atS = *at;
            auto type = eventText(e, "type", place, i);
            if (!type) {
                return type.error();
            }
            bool known = false;
            for (auto t : {EventType::Setpoint, EventType::Controller, EventType::Fault, EventType::Freeze,
                           EventType::Resume, EventType::Snapshot, EventType::Restore, EventType::Answer}) {
                if (*type == eventTypeName(t)) {
                    ev.type = t;
                    known = true;
                }
            }
            if (!known) {
                return eventError(
                    place, i, "type",
                    "'" + *type +
                        "' is not one of setpoint, controller, fault, freeze, resume, snapshot, "
                        "restore, answer");
            }
            Expected<double> number = 0.0;
            Expected<std::string> word = std::string();
            switch (ev.type) {
            case EventType::Setpoint:
                number = eventNumber(e, "value_pct", place, i);
                break;
            case EventType::Controller:
                word = eventText(e, "controller", place, i);
                if (word && !control::controllerByName(*word)) {
                    return eventError(
                        place, i, "controller",
                        "'" + *word + "' is not a controller (pi, pbm, pgrl_cc, ext_input_residual, lstm)");
                }
                break;
            case EventType::Fault:
                word = eventText(e, "cause", place, i);
                if (word && !plant::mechanismByName(*word)) {
                    return eventError(place, i, "cause",
                                      "'" + *word + "' is not a mechanism of CONTRACT.md §4");
                }
                if (word) {
                    number = eventNumber(e, "strength", place, i);
                    auto onset = e.contains("onset_s") ? eventNumber(e, "onset_s", place, i)
                                                       : Expected<double>(ev.atS);
                    if (!onset) {
                        return onset.error();
                    }
                    ev.onsetS = *onset;
                }
                break;
            case EventType::Snapshot:
            case EventType::Restore:
                word = eventText(e, "label", place, i);
                break;
            case EventType::Answer:
                word = eventText(e, "cause", place, i);
                break;
            case EventType::Freeze:
            case EventType::Resume:
                break;
            }
            if (!number) {
                return number.error();
            }
            if (!word) {
                return word.error();
            }
            ev.value = *number;
            ev.text = *word;
            script.events.push_back(ev);
        }
    }
    return script;
}

Expected<TrainingScript> loadTrainingScript(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        return Error{ErrorKind::BadInput, path, "cannot open the session file"};
    }
    std::stringstream ss;
    ss << in.rdbuf();
    return parseTrainingScript(ss.str(), path);
}

Expected<TrainingSession> replay(const TrainingScript& script,
                                 std::shared_ptr<const hybrid::HybridModel> model, const Progress& progress) {
    auto session = TrainingSession::start(script.scenario, std::move(model));
    if (!session) {
        return session.error();
    }
    const double end = script.endS >= 0 ? script.endS : session->endS();
    const auto runTo = [&](double t, const std::string& what) -> Status {
        const double gap = std::round(t - session->timeS());
        if (gap < 0) {
            // Named in the file: which entry, at what time, and why that is before (the events
            // run in time order; a restore takes the session back to its snapshot's time).
            return Error{ErrorKind::BadInput, script.place.empty() ? "replay" : script.place,
                         what + " at " + std::to_string(static_cast<long>(t)) +
                             " s lies before the session's time " +
                             std::to_string(static_cast<long>(session->timeS())) +
                             " s there: the events must be in time order"};
        }
        const auto wanted = static_cast<std::size_t>(gap);
        if (wanted > 0 && session->frozen()) {
            return Error{ErrorKind::BadInput, "replay",
                         "the session is frozen at " + std::to_string(static_cast<long>(session->timeS())) +
                             " s: no time passes before a resume"};
        }
        if (session->advance(wanted,
                             [&](const ProgressInfo& p) {
                                 return progressAction(progress, "training",
                                                       std::min(1.0, session->timeS() / std::max(1.0, end)),
                                                       p.detail);
                             }) < wanted &&
            !session->finished()) {
            return cancelledError("training");
        }
        return Status{};
    };
    for (std::size_t i = 0; i < script.events.size(); ++i) {
        const SessionEvent& e = script.events[i];
        if (auto st = runTo(e.atS, "events[" + std::to_string(i) + "] (" + eventTypeName(e.type) + ")");
            !st) {
            return st.error();
        }
        Status st;
        switch (e.type) {
        case EventType::Setpoint:
            st = session->setSetpoint(e.value);
            break;
        case EventType::Controller:
            st = session->setController(*control::controllerByName(e.text));
            break;
        case EventType::Fault:
            st = session->injectFault(*plant::mechanismByName(e.text), e.value, e.onsetS);
            break;
        case EventType::Snapshot:
            st = session->takeSnapshot(e.text);
            break;
        case EventType::Restore:
            st = session->restore(e.text);
            break;
        case EventType::Answer:
            st = session->answer(e.text);
            break;
        case EventType::Freeze:
            session->freeze();
            break;
        case EventType::Resume:
            session->resume();
            break;
        }
        if (!st) {
            Error err = st.error();
            err.place = "events[" + std::to_string(i) + "] (" + eventTypeName(e.type) + " at " +
                        std::to_string(static_cast<long>(e.atS)) + " s): " + err.place;
            return err;
        }
    }
    session->resume(); // a session saved while frozen runs on to its end when replayed
    if (auto st = runTo(end, script.endS >= 0 ? "end_s" : "the scenario's end"); !st) {
        return st.error();
    }
    return std::move(*session);
}

std::string sessionJson(const std::string& scenarioJson, const TrainingSession& session,
                        const std::vector<std::string>& recordingFiles, const std::string& modelFingerprint) {
    json j;
    j["format"] = "drytwin-training-session";
    j["version"] = 1;
    j["scenario"] = json::parse(scenarioJson);
    j["end_s"] = session.timeS();
    json events = json::array();
    for (const auto& e : session.events()) {
        events.push_back(eventJson(e)); // freeze and resume too: when the instructor paused tells the story
    }
    j["events"] = events;
    json faults = json::array();
    for (const auto& f : session.faults()) {
        faults.push_back({{"cause", plant::info(f.mechanism).name},
                          {"strength", f.strength},
                          {"unit", plant::info(f.mechanism).unit},
                          {"onset_s", f.onsetS},
                          {"injected_at_s", f.injectedAtS}});
    }
    j["faults"] = faults;
    json answers = json::array();
    for (const auto& a : session.answers()) {
        answers.push_back({{"at_s", a.atS}, {"cause", a.cause}});
    }
    j["answers"] = answers;
    const TrainingScore sc = session.score();
    json scored = json::array();
    for (const auto& f : sc.faults) {
        json fj{{"cause", plant::info(f.fault.mechanism).name},
                {"found", f.found},
                {"off_spec_pct_while_open", f.offSpecPctWhileOpen},
                {"points", f.points},
                {"within_reaction_time", f.withinReactionTime}};
        fj["time_to_find_s"] = f.found ? json(f.timeToFindS) : json(nullptr);
        scored.push_back(fj);
    }
    j["score"] = {{"points", sc.points},
                  {"faults", scored},
                  {"wrong_answers", sc.wrongAnswers},
                  {"off_spec_pct", sc.offSpecPct},
                  {"off_spec_kg", sc.offSpecKg},
                  {"summary", sc.summary}};
    j["recording"] = recordingFiles;
    if (!modelFingerprint.empty()) {
        // Which model the MPCs ran on: a replay with another one moves differently.
        j["model"] = {{"fingerprint", modelFingerprint},
                      {"controllers", modelControllersUsed(session.events())}};
    }
    return j.dump(2) + "\n";
}

} // namespace drytwin::training

namespace drytwin::training {

namespace {

/// The scenario's name as a file name: letters, digits, '-', '_' and '.' kept, anything else
/// (a '/', "..", a space) as '_'. The name came straight from the session file: "../../evil"
/// wrote the recording outside the output folder, "line 3/shift A" failed after the folder was
/// made.
std::string fileNameOf(const std::string& name) {
    std::string out;
    for (const char c : name) {
        const auto u = static_cast<unsigned char>(c);
        out += std::isalnum(u) || c == '-' || c == '_' || (c == '.' && !out.empty()) ? c : '_';
    }
    while (!out.empty() && out.back() == '.') {
        out.pop_back();
    }
    return out.empty() ? "training" : out;
}

} // namespace

Expected<SavedSession> saveSession(const std::string& folder, const std::string& scenarioJson,
                                   const TrainingSession& session, const std::string& modelFingerprint) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(fs::path(folder) / "recording", ec);
    if (ec) {
        return Error{ErrorKind::BadInput, folder, "cannot create the folder: " + ec.message()};
    }
    SavedSession saved;
    const std::string id = session.scenario().name.empty() ? "training" : session.scenario().name;
    const std::string relative = "recording/" + fileNameOf(id) + ".csv";
    const std::string csv = (fs::path(folder) / relative).string();
    if (auto st = data::writeBatchFile(session.recording(id), csv); !st) {
        return st.error();
    }
    saved.recordingFiles.push_back(csv);
    saved.sessionFile = (fs::path(folder) / "session.json").string();
    if (auto st = writeFileAtomically(saved.sessionFile,
                                      sessionJson(scenarioJson, session, {relative}, modelFingerprint));
        !st) {
        return st.error();
    }
    return saved;
}

std::string modelDiffersNote(const TrainingScript& script, const std::string& modelFingerprint) {
    const auto used = modelControllersUsed(script.events);
    if (script.modelFingerprint.empty() || script.modelFingerprint == modelFingerprint || used.empty()) {
        return {};
    }
    const std::string list = commaList(used);
    return "the session was saved with another model (fingerprint " + script.modelFingerprint +
           ", this one " + modelFingerprint + "): its MPC controllers (" + list +
           ") run on this one, so the recording may differ from the saved one; open the project or model "
           "file it was run with to replay it exactly";
}

} // namespace drytwin::training
