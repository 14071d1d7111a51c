#include "baselines/LstmBaseline.h"

// Compiled into the engine and into the libtorch module alike (engine/CMakeLists.txt): both
// check options, and the module is loaded without the engine's symbols.

namespace drytwin::baselines {

Status LstmOptions::validate() const {
    if (hidden < 1 || hidden > 512 || sequenceLength < 4 || segmentLength < sequenceLength || epochs < 1 ||
        batchSize < 1 || threads < 1 || patience < 1 || !(learningRate > 0 && learningRate < 1) ||
        !(validationFraction >= 0.05 && validationFraction <= 0.5) ||
        !(clipMargin >= 0 && clipMargin <= 10) || freeRunSteps < 0 || freeRunSteps >= sequenceLength ||
        !(freeRunWeight >= 0 && freeRunWeight <= 100) || !(highPassSeconds >= 0 && highPassSeconds <= 1e6) ||
        validationHorizon < 0 || validationHorizon > 3600) {
        return Error{ErrorKind::BadInput, "LSTM options",
                     "need 1 ≤ hidden ≤ 512, sequence ≥ 4, segment ≥ sequence, epochs ≥ 1, batch ≥ 1, "
                     "threads ≥ 1, patience ≥ 1, 0 < rate < 1, 0.05 ≤ validation share ≤ 0.5, "
                     "0 ≤ clip margin ≤ 10, 0 ≤ free-run steps < sequence, 0 ≤ free-run weight ≤ 100, "
                     "0 ≤ high-pass time ≤ 1e6 s, 0 ≤ validation horizon ≤ 3600"};
    }
    return {};
}

} // namespace drytwin::baselines
