#include "HeadlessCommands.h"
#include "commands/CommandHelpers.h"
#include "commands/LiveHelpers.h"

#include "common/AtomicFile.h"
#include "live/BrokerUrl.h"
#include "live/LivePublisher.h"
#include "live/LiveRecorder.h"
#include "workflow/Session.h"

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <unistd.h>

namespace drytwin::app {

namespace detail {

Expected<live::MqttConnectOptions> connectionOptions(const CommandOptions& o, const std::string& urlOption,
                                                     const std::string& clientRole) {
    if (!o.passwordOnCommandLine.empty()) {
        // Never taken: a password on the command line is in the shell's history and in `ps` for
        // every user of the machine.
        return invalidOption("--password", "a password is never given on the command line; put it in a file "
                                           "(--password-file FILE) or in DRYTWIN_MQTT_PASSWORD");
    }
    auto url = live::parseBrokerUrl(o.brokerUrl, urlOption);
    if (!url) {
        return url.error();
    }
    live::MqttConnectOptions c;
    c.broker = *url;
    c.clientId = "drytwin-" + clientRole + "-" + std::to_string(::getpid());
    c.user = o.mqttUser;
    c.caFile = o.caFile;
    if (!o.passwordFile.empty()) {
        auto text = readWholeFile(o.passwordFile);
        if (!text) {
            return Error{ErrorKind::BadInput, "--password-file " + o.passwordFile, text.error().reason};
        }
        std::string password = *text;
        while (!password.empty() && (password.back() == '\n' || password.back() == '\r')) {
            password.pop_back();
        }
        if (password.empty()) {
            return Error{ErrorKind::BadInput, "--password-file " + o.passwordFile, "the file is empty"};
        }
        c.password = password;
    } else if (const char* env = std::getenv("DRYTWIN_MQTT_PASSWORD"); env && *env) {
        c.password = env;
    }
    if (!c.password.empty() && c.user.empty()) {
        return invalidOption("--user", "a password was given (--password-file or DRYTWIN_MQTT_PASSWORD) "
                                       "without a user name");
    }
    if (!o.caFile.empty() && ::access(o.caFile.c_str(), R_OK) != 0) {
        return Error{ErrorKind::BadInput, "--cafile " + o.caFile, "cannot read the file"};
    }
    return c;
}

Expected<live::TopicMapping> topicMapping(const CommandOptions& o) {
    live::TopicMapping mapping;
    if (!o.topicsPath.empty()) {
        auto read = live::readTopicMapping(o.topicsPath);
        if (!read) {
            return read.error();
        }
        mapping = *read;
    }
    if (!o.topicPrefix.empty()) {
        mapping.linePrefix = o.topicPrefix;
        if (auto st = mapping.validate(); !st) {
            return Error{ErrorKind::Usage, "--topic-prefix " + o.topicPrefix, st.error().reason};
        }
    }
    return mapping;
}

int publishPlant(const CommandOptions& o, const plant::PlantOptions& plant) {
    live::PublishOptions po;
    po.plant = plant;
    po.speed = o.speed;
    auto connection = connectionOptions(o, "--publish", "generate");
    if (!connection) {
        return fail(connection.error());
    }
    po.connection = *connection;
    auto topics = topicMapping(o);
    if (!topics) {
        return fail(topics.error());
    }
    po.topics = *topics;
    auto result = workflow::Session().publish(po, o.progress);
    if (!result) {
        return fail(result.error());
    }
    std::printf(
        "published %d batch(es), %ld samples (%ld messages, %.0f s of line time) to %s under %s at %gx "
        "in %.2f s\n",
        result->batches, result->samples, result->messages, result->lineSeconds,
        po.connection.broker.text().c_str(), po.topics.linePrefix.c_str(), po.speed,
        result->ending.elapsedSeconds);
    return 0;
}

} // namespace detail

using namespace detail;

int runLive(const CommandOptions& o) {
    if (!o.modelPath.empty()) {
        return fail(Error{ErrorKind::Usage,
                          "--model",
                          "the twin's prediction and forecast beside a live line are not in this version yet "
                          "(issue #73); --reference runs the monitor",
                          ErrorCode::NotImplemented,
                          {"live --model"}});
    }
    live::LiveOptions lo;
    auto connection = connectionOptions(o, "--broker", "live");
    if (!connection) {
        return fail(connection.error());
    }
    lo.connection = *connection;
    auto topics = topicMapping(o);
    if (!topics) {
        return fail(topics.error());
    }
    lo.topics = *topics;
    lo.recording.folder = o.recordFolder;
    lo.recording.reorderWindowS = o.reorderWindowS;
    lo.recording.splitGapS = o.splitGapS;
    lo.durationS = o.durationS;
    lo.referencePath = o.referencePath;
    lo.monitor.falseAlarmRate = o.liveFalseAlarmRate;
    lo.monitor.plannedRunS = o.plannedRunS;
    // What happens on the link goes to stderr at once, stamped: an operator reads it as a log.
    lo.onEvent = [](const std::string& line) {
        const std::time_t now = std::time(nullptr);
        char stamp[32];
        std::strftime(stamp, sizeof stamp, "%H:%M:%S", std::localtime(&now));
        std::fprintf(stderr, "live %s: %s\n", stamp, line.c_str());
        std::fflush(stderr);
    };
    auto result = workflow::Session().live(lo, o.progress);
    if (!result) {
        return fail(result.error());
    }
    const auto& c = result->counts;
    std::printf("recorded %ld rows in %zu file(s)%s: %ld samples, %ld late, %ld duplicate, %ld malformed, "
                "%ld missing cells; %ld messages; link dropped %d time(s)\n",
                c.rows, result->files.size(), o.recordFolder.empty() ? "" : (" to " + o.recordFolder).c_str(),
                c.samples, c.late, c.duplicates, c.malformed, c.missingCells, result->messages,
                result->disconnects);
    for (const auto& f : result->files) {
        std::printf("  %s\n", f.c_str());
    }
    if (result->monitored) {
        std::printf("monitor: %ld windows published under %s/monitor; ", result->monitorWindows,
                    lo.topics.twinTopicPrefix().c_str());
        if (result->alarms.empty()) {
            std::printf("no alarm\n");
        }
        for (const auto& a : result->alarms) {
            std::printf("alarm by %s in batch %s at %.0f s", a.statistic.c_str(), a.batch.c_str(), a.timeS);
            if (a.hasOnset) {
                std::printf(", onset about %.0f s in batch %s", a.onsetS, a.onsetBatch.c_str());
            }
            std::printf("\n");
        }
    }
    // Ctrl+C ends a live run as the contract says (130), the recording written.
    return result->stoppedByUser ? 130 : 0;
}

} // namespace drytwin::app
