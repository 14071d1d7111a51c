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

int runTrain(const CommandOptions& o) {
    workflow::TrainOptions options;
    workflow::Session session;
    int rc = 0;
    if (!trainOptions(o, options, rc) || !open(o, session, rc)) {
        return rc;
    }
    if (!session.model().calibration) {
        std::fprintf(stderr,
                     "drytwin train: note: %s holds no calibration; the residual model is learnt on top of "
                     "the default physics parameters\n",
                     o.modelPath.c_str());
    }
    auto result = session.train(options, o.progress);
    if (!result) {
        return fail(result.error());
    }
    printTraining(*result);
    if (auto st = session.saveModel(o.outPath); !st) {
        return fail(st.error());
    }
    return 0;
}

} // namespace drytwin::app
