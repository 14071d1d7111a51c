// The runs that need no loaded data, because the virtual plant makes its own: mpc(), a what-if
// scenario (a file, or one bundled with DryTwin) once per controller, and training(), the replay
// of a scripted training session with the session's model, written only when it succeeds.

#include "workflow/Session.h"

#include "control/BundledScenarios.h"
#include "io/ModelFile.h"
#include "workflow/session/SessionInternal.h"

#include <memory>

namespace drytwin::workflow {

Expected<MpcResult> Session::mpc(const MpcOptions& options, const Progress& progress) {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    Expected<control::Scenario> scenario = Error{ErrorKind::Usage, "mpc", "no scenario"};
    if (!options.scenarioPath.empty()) {
        scenario = control::loadScenario(options.scenarioPath);
    } else {
        const auto& bundled = control::bundledScenarios();
        const auto it = bundled.find(options.bundledScenario);
        if (it == bundled.end()) {
            return Error{ErrorKind::Usage, "scenario",
                         "no bundled scenario named " + options.bundledScenario};
        }
        scenario = control::parseScenario(it->second, "resources/scenarios/" + it->first + ".json");
    }
    if (!scenario) {
        return scenario.error();
    }
    auto run = control::runScenario(*scenario, m_model, options.closedLoop, progress);
    if (!run) {
        return run.error();
    }
    MpcResult out;
    out.ending = run->ending;
    out.closedLoop = std::move(*run);
    m_latest.mpc = out;
    return out;
}

Expected<TrainingResult> Session::training(const TrainingOptions& options, const Progress& progress) const {
    const auto t0 = std::chrono::steady_clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    auto script = training::loadTrainingScript(options.scriptPath);
    if (!script) {
        return script.error();
    }
    // Nothing is written unless the whole replay succeeds.
    auto session = training::replay(*script, std::make_shared<hybrid::HybridModel>(m_model), progress);
    if (!session) {
        return session.error();
    }
    const std::string fingerprint = io::modelFingerprint(m_model);
    auto saved = training::saveSession(options.outFolder, script->scenarioJson, *session, fingerprint);
    if (!saved) {
        return saved.error();
    }
    TrainingResult result;
    result.files = *saved;
    result.score = session->score();
    result.endS = session->timeS();
    result.events = session->events().size();
    if (auto note = training::modelDiffersNote(*script, fingerprint); !note.empty()) {
        result.notes.push_back(std::move(note));
    }
    result.ending = {Termination::Completed, result.score.summary, secondsSince(t0)};
    return result;
}

} // namespace drytwin::workflow
