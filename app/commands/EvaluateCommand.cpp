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

int runEvaluate(const CommandOptions& o) {
    workflow::EvaluateOptions options;
    options.evaluation.horizonSteps = o.horizonSteps;
    workflow::Session session;
    int rc = 0;
    if (!open(o, session, rc)) {
        return rc;
    }
    auto result = session.evaluate(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    printEvaluation(result->evaluation);
    if (!session.model().hasResidualModels()) {
        // A calibrated-only model file gives the physics and the trivial forecasts alone; said,
        // so that the missing PGRL-CC rows do not read as a failure.
        std::printf("\nThe model file holds no learnt models (physics only): `drytwin train --data D --model "
                    "M --out M2` adds PGRL-CC, the input-only correction and the LSTM to compare.\n");
    }
    if (const auto& lstm = session.model().lstm) {
        printLstmValidation(*lstm); // the held-out table above, beside what its training part said
    }
    if (!o.jsonPath.empty()) {
        if (auto st = writeFileAtomically(o.jsonPath, io::evaluationJson(result->evaluation)); !st) {
            return fail(st.error());
        }
    }
    if (!o.diagnosticsPath.empty()) {
        if (auto st =
                writeFileAtomically(o.diagnosticsPath, io::residualDiagnosticsJson(result->diagnostics));
            !st) {
            return fail(st.error());
        }
    }
    return 0;
}

} // namespace drytwin::app
