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

int runAblation(const CommandOptions& o) {
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc)) {
        return rc;
    }
    auto result = session.ablation(o.progress);
    if (!result) {
        return fail(result.error());
    }
    printAblation(*result);
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(o.jsonPath, io::ablationJson(*result)); !st) {
            return fail(st.error());
        }
    }
    return 0;
}

} // namespace drytwin::app
