#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "data/Batch.h"
#include "live/MqttClient.h"
#include "live/TopicMapping.h"
#include "plant/VirtualPlant.h"

#include <vector>

namespace drytwin::live {

/// @brief `drytwin generate --publish`: the virtual plant's batches sent to a broker as they
/// would come from the line, at N x real time (CONTRACT.md §2).
struct PublishOptions {
    plant::PlantOptions plant; ///< the same options generate() writes files for
    MqttConnectOptions connection;
    TopicMapping topics;
    double speed = 1; ///< line seconds per wall-clock second
    /// Unix time of the first sample's stamp; 0: now, whole seconds. Batches follow each other
    /// without a pause, each with its own `batch_id` message at its first second.
    double startEpochS = 0;
    Status validate() const;
};

/// @brief What was sent.
struct PublishResult {
    int batches = 0;
    long samples = 0;  ///< rows
    long messages = 0; ///< tag messages and batch ids
    double lineSeconds = 0;
    double firstStampS = 0; ///< the first sample's "t"
    Ending ending;
};

/// @brief Publishes @p batches (as their batch files would hold them) row by row: one message per
/// contract column per row, `{"t": <Unix seconds>, "v": <value or null>}`, paced to
/// options.speed, then waits until the broker has acknowledged every message. Progress "publish"
/// may stop it (a Cancelled error, after what was sent is delivered).
Expected<PublishResult> publishBatches(const std::vector<data::Batch>& batches, const PublishOptions& options,
                                       const Progress& progress = {});

} // namespace drytwin::live
