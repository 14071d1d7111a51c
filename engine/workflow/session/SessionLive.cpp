// The live link's two Session calls (issue #73): generate --publish and live. Apart from
// SessionData.cpp so that the MQTT pieces stay out of the files every other call compiles with.
#include "workflow/Session.h"

#include "live/LivePublisher.h"
#include "live/LiveRecorder.h"
#include "plant/PlantExport.h"

namespace drytwin::workflow {

Expected<live::PublishResult> Session::publish(const live::PublishOptions& options,
                                               const Progress& progress) const {
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    auto plantResult = plant::runPlant(options.plant, progress);
    if (!plantResult) {
        return plantResult.error();
    }
    // The batches as generate() writes them (the files' rounding): what a line's historian
    // would have, so that a recording can be compared with the files sample for sample.
    std::vector<data::Batch> batches;
    batches.reserve(plantResult->batches.size());
    for (const auto& pb : plantResult->batches) {
        batches.push_back(plant::toBatch(pb, options.plant.seed));
    }
    return live::publishBatches(batches, options, progress);
}

Expected<live::LiveResult> Session::live(const live::LiveOptions& options, const Progress& progress) const {
    return live::runLive(options, progress);
}

} // namespace drytwin::workflow
