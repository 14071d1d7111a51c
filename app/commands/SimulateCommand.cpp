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

int runSimulate(const CommandOptions& o) {
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc)) {
        return rc;
    }
    auto result = session.simulate({}, o.progress);
    if (!result) {
        return fail(result.error());
    }
    std::printf("%-10s %8s %14s %14s\n", "batch", "rows", "MAE X_out [%]", "MAE T_out [°C]");
    for (const auto& f : result->fits) {
        std::printf("%-10s %8zu %14.4f %14.4f\n", f.id.c_str(), f.rows, f.maeXOutPct, f.maeTOutC);
    }
    if (auto st = writeFileAtomically(o.outPath, io::simulationCsv(session.siBatches(), result->simulations));
        !st) {
        return fail(st.error());
    }
    return 0;
}

} // namespace drytwin::app
