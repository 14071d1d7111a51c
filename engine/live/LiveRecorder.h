#pragma once

#include "common/Error.h"
#include "common/Progress.h"
#include "live/GridRecorder.h"
#include "live/LiveMonitor.h"
#include "live/MqttClient.h"
#include "live/TopicMapping.h"

#include <functional>
#include <string>
#include <vector>

namespace drytwin::live {

/// @brief `drytwin live`: follow a running line on a broker and record it (CONTRACT.md §2).
struct LiveOptions {
    MqttConnectOptions connection;
    TopicMapping topics;
    GridRecorderOptions recording; ///< folder empty: nothing written, the stream only counted
    double durationS = 0;          ///< wall-clock seconds to run; 0: until progress says stop
    /// A period when the line ran as it should (batch file or folder): the dynamic-PCA monitor is
    /// fitted on it and fed the recording's rows; its windows and its alarm are published under
    /// the twin's prefix (`<twin>/monitor`, `<twin>/alarm`). Empty: no monitor.
    std::string referencePath;
    LiveMonitorOptions monitor;
    /// Told of what happens on the link (connected, dropped, back) and of the first malformed
    /// messages, as one English line each; called on the thread that runs runLive().
    std::function<void(const std::string&)> onEvent;
    Status validate() const;
};

/// @brief How a live run went.
struct LiveResult {
    RecorderCounts counts;
    long messages = 0;          ///< messages received, of every kind
    int disconnects = 0;        ///< times the link dropped (each followed by reconnect attempts)
    bool stoppedByUser = false; ///< ended by progress (Ctrl+C), not by the duration
    std::vector<std::string> files;
    bool monitored = false;        ///< a reference was given and the monitor ran
    long monitorWindows = 0;       ///< windows the monitor completed (each published)
    std::vector<LiveAlarm> alarms; ///< at most one: the monitor stays alarmed once it alarmed
    Ending ending;
};

/// @brief Connects, subscribes to the mapping's topics and records until the duration passes or
/// progress ("live", once a second) says stop; the recording is written either way. A broker
/// that cannot be reached at the start is an error; a drop later is ridden out by reconnecting
/// with back-off while the gap is recorded as missing.
Expected<LiveResult> runLive(const LiveOptions& options, const Progress& progress = {});

} // namespace drytwin::live
