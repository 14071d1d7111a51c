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

int runCalibrate(const CommandOptions& o) {
    workflow::CalibrateOptions options;
    workflow::Session session;
    int rc = 0;
    if (!calibrateOptions(o, options, rc) || !open(o, session, rc)) {
        return rc;
    }
    auto result = session.calibrate(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    printCalibration(*result);
    if (auto st = session.saveModel(o.outPath); !st) {
        return fail(st.error());
    }
    return 0;
}

} // namespace drytwin::app
