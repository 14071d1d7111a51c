#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "control/Scenario.h"
#include "training/TrainingSession.h"

#include <memory>
#include <string>
#include <vector>

namespace drytwin::training {

/// @brief A training session as a file (docs/training.md): the scenario, the events in the
/// order they happened, and how long to run after the last. A saved session is a script: replaying
/// it gives the same record for the same seed.
struct TrainingScript {
    std::string scenarioJson; ///< the scenario as JSON text (a bundled one's, or the file's)
    control::Scenario scenario;
    std::vector<SessionEvent> events;
    double endS = -1;  ///< session time to run to after the last event; negative: the scenario's end
    std::string place; ///< the session file (or what parsed it), for the replay's messages
    /// A saved session's "model": {"fingerprint"}: the model its MPCs ran on
    /// (io::modelFingerprint); empty where the file does not say.
    std::string modelFingerprint;
};

/// @brief Parses a session file; errors name @p place and the event ("place: events[3].at_s: …").
/// "scenario" is either the name of a bundled scenario or a scenario object.
Expected<TrainingScript> parseTrainingScript(const std::string& text, const std::string& place);
Expected<TrainingScript> loadTrainingScript(const std::string& path);

/// @brief Runs a script headless: starts the session, applies each event at its time (no time
/// passes between a freeze and its resume, as in the live session), then runs to the end.
Expected<TrainingSession> replay(const TrainingScript& script,
                                 std::shared_ptr<const hybrid::HybridModel> model,
                                 const Progress& progress = {});

/// @brief The session file: the scenario, the events (with the faults, answers and snapshots
/// among them), the faults and answers as they stand, the score, and the recording's files
/// (relative to the session file). "end_s" is the session's time now.
/// @p modelFingerprint (io::modelFingerprint of the model the MPCs ran on) is written as
/// "model": {"fingerprint", "controllers"} when not empty.
std::string sessionJson(const std::string& scenarioJson, const TrainingSession& session,
                        const std::vector<std::string>& recordingFiles,
                        const std::string& modelFingerprint = {});

/// @brief The files of a saved session.
struct SavedSession {
    std::string sessionFile; ///< FOLDER/session.json
    std::vector<std::string>
        recordingFiles; ///< FOLDER/recording/<scenario>.csv, a batch file of CONTRACT.md §1
};

/// @brief Writes a session into @p folder: the recording first, then session.json atomically
/// (a session file never names a recording that is not there).
Expected<SavedSession> saveSession(const std::string& folder, const std::string& scenarioJson,
                                   const TrainingSession& session, const std::string& modelFingerprint = {});

/// @brief Empty, or why a replay of @p script with the model of @p modelFingerprint need not give
/// the recording saved with it: the session switched to an MPC controller (any but "pi") and was
/// saved with another model.
std::string modelDiffersNote(const TrainingScript& script, const std::string& modelFingerprint);

} // namespace drytwin::training
