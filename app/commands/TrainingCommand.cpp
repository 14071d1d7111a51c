#include "HeadlessCommands.h"
#include "commands/CommandHelpers.h"

#include "common/AtomicFile.h"
#include "common/Units.h"
#include "control/BundledScenarios.h"
#include "io/ModelFile.h"
#include "io/ResultFiles.h"
#include "plant/Mechanisms.h"
#include "workflow/Session.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace drytwin::app {

using namespace detail;

int runTraining(const CommandOptions& o) {
    workflow::TrainingOptions options;
    options.scriptPath = o.scriptPath;
    options.outFolder = o.outPath;
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc, false)) {
        return rc;
    }
    auto result = session.training(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    const auto& r = *result;
    std::printf("Training session %s: replayed %zu event(s) to %.0f s\n", o.scriptPath.c_str(), r.events,
                r.endS);
    for (const auto& f : r.score.faults) {
        const auto& mi = plant::info(f.fault.mechanism);
        std::printf("  fault %-24s %g %s from %.0f s: %s, %.1f %% of the time out of the band meanwhile, "
                    "%.0f points\n",
                    std::string(mi.name).c_str(), f.fault.strength, std::string(mi.unit).c_str(),
                    f.fault.onsetS,
                    f.found                ? ("found after " + fmt(f.timeToFindS, 0) + " s").c_str()
                    : f.withinReactionTime ? "not found yet, within the time to react (not scored)"
                                           : "not found",
                    f.offSpecPctWhileOpen, f.points);
    }
    std::printf("Score: %s\n", r.score.summary.c_str());
    for (const auto& note : r.notes) {
        std::printf("note: %s\n", note.c_str());
    }
    std::printf("Wrote %s and %s\n", r.files.sessionFile.c_str(), r.files.recordingFiles.front().c_str());
    return 0;
}

} // namespace drytwin::app
