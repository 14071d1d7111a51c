#include "LiveRecorder.h"

#include "data/BatchReader.h"
#include "live/TagPayload.h"

#include <chrono>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <thread>

namespace drytwin::live {

Status LiveOptions::validate() const {
    if (!(durationS >= 0)) {
        return invalidOption("--duration", "must be 0 (until stopped) or a number of seconds");
    }
    if (auto st = connection.validate(); !st) {
        return st;
    }
    if (auto st = topics.validate(); !st) {
        return st;
    }
    return recording.validate();
}

namespace {

double unixNow() {
    return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

/// Messages handed from the client's network thread to the recording loop: the network thread
/// never waits on the recorder's file writes.
struct Inbox {
    struct Message {
        std::string topic;
        std::string payload;
        double arrivalS = 0;
    };
    std::mutex mutex;
    std::deque<Message> messages;
    std::deque<std::string> linkEvents;

    void take(std::deque<Message>& into, std::deque<std::string>& events) {
        std::lock_guard<std::mutex> lock(mutex);
        into.swap(messages);
        events.swap(linkEvents);
    }
};

} // namespace

Expected<LiveResult> runLive(const LiveOptions& options, const Progress& progress) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    std::optional<LiveMonitor> monitor;
    if (!options.referencePath.empty()) {
        // Fitted before connecting: a reference that cannot be used stops the run at once.
        auto reference = data::loadDataSet(options.referencePath, {}, progress);
        if (reference.cancelled) {
            return cancelledError("live");
        }
        if (!reference.ok()) {
            Error e = reference.errors.front();
            e.causes = reference.errors;
            return e;
        }
        auto commissioned = LiveMonitor::commission(reference.dataSet, options.monitor);
        if (!commissioned) {
            return commissioned.error();
        }
        monitor = std::move(*commissioned);
    }
    auto say = [&](const std::string& line) {
        if (options.onEvent) {
            options.onEvent(line);
        }
    };
    auto inbox = std::make_shared<Inbox>();
    auto onMessage = [inbox](const std::string& topic, std::string_view payload) {
        Inbox::Message m{topic, std::string(payload), unixNow()};
        std::lock_guard<std::mutex> lock(inbox->mutex);
        inbox->messages.push_back(std::move(m));
    };
    auto onConnection = [inbox](bool up, const std::string& reason) {
        std::lock_guard<std::mutex> lock(inbox->mutex);
        inbox->linkEvents.push_back(up ? "link up again, subscribed"
                                       : "link down (" + reason + "), reconnecting");
    };
    const auto subscriptions = options.topics.subscriptions();
    auto client = MqttClient::connect(options.connection, subscriptions, onMessage, onConnection);
    if (!client) {
        return client.error();
    }
    {
        // The first connect's own event is not news: connect() returning says it.
        std::lock_guard<std::mutex> lock(inbox->mutex);
        inbox->linkEvents.clear();
    }
    say("connected to " + (*client)->brokerText() + ", subscribed to " +
        std::to_string(subscriptions.size()) + " topics under " + options.topics.linePrefix);

    if (monitor) {
        say("monitor fitted on the reference " + options.referencePath + " (false-alarm rate " +
            std::to_string(options.monitor.falseAlarmRate) + " per " +
            std::to_string(static_cast<int>(monitor->plannedRunS())) + " s run), publishing under " +
            options.topics.twinTopicPrefix());
    }
    GridRecorderOptions recording = options.recording;
    recording.keepFinalRows = monitor.has_value();
    if (recording.sourceText.empty()) {
        recording.sourceText = "drytwin live, " + (*client)->brokerText();
    }
    GridRecorder recorder(recording);
    LiveResult result;
    const std::string batchTopic = options.topics.batchIdTopic();
    std::map<std::string, data::Column> columnOfTopic; // once, not per message
    for (const auto& s : data::columnSpecs()) {
        if (s.id != data::Column::Time) {
            columnOfTopic.emplace(options.topics.topicOf(s.id), s.id);
        }
    }
    int malformedTold = 0;
    // Places one message on the grid; a malformed one is counted, and the first few are told
    // with their topic and cause.
    auto handle = [&](const Inbox::Message& m) {
        ++result.messages;
        std::string problem;
        if (m.topic == batchTopic) {
            std::string id;
            double timeS = 0;
            if (readBatchIdPayload(m.payload, m.arrivalS, id, timeS, problem)) {
                recorder.addBatchStart(id, timeS);
                return;
            }
        } else if (const auto column = columnOfTopic.find(m.topic); column != columnOfTopic.end()) {
            const auto reading = readTagPayload(m.payload, m.arrivalS);
            if (reading.ok) {
                recorder.addSample(column->second, reading.sample);
                return;
            }
            problem = reading.problem;
        } else {
            problem = "not a mapped topic";
        }
        recorder.addMalformed();
        if (malformedTold < 5) {
            ++malformedTold;
            say("malformed message on " + m.topic + ": " + problem + " (not recorded)" +
                (malformedTold == 5 ? "; further ones are only counted" : ""));
        }
    };
    std::deque<Inbox::Message> messages;
    std::deque<std::string> events;
    auto lastReport = Clock::now();
    const std::string monitorTopic = options.topics.twinTopicPrefix() + "/monitor";
    const std::string alarmTopic = options.topics.twinTopicPrefix() + "/alarm";
    // The recording's final rows into the monitor; its windows and its alarm out to the broker.
    auto publishWindows = [&](const std::vector<monitoring::StreamingWindow>& windows) -> Status {
        for (const auto& w : windows) {
            ++result.monitorWindows;
            if (auto st = (*client)->publish(monitorTopic, monitor->windowPayload(w)); !st) {
                return st;
            }
            if (auto alarm = monitor->alarmOf(w)) {
                if (auto st = (*client)->publish(alarmTopic, monitor->alarmPayload(*alarm, w)); !st) {
                    return st;
                }
                say("ALARM by " + alarm->statistic + " in batch " + alarm->batch + " at " +
                    std::to_string(static_cast<long>(alarm->timeS)) + " s" +
                    (alarm->hasOnset ? ", onset about " + std::to_string(static_cast<long>(alarm->onsetS)) +
                                           " s in batch " + alarm->onsetBatch
                                     : std::string()));
                result.alarms.push_back(*alarm);
            }
        }
        return {};
    };
    auto feedMonitor = [&](bool finish) -> Status {
        if (!monitor) {
            return {};
        }
        for (const auto& row : recorder.takeFinalRows()) {
            auto windows = monitor->push(row.batch, row.batchStartS, row.timeS, row.values);
            if (!windows) {
                return windows.error();
            }
            if (auto st = publishWindows(*windows); !st) {
                return st;
            }
        }
        return finish ? publishWindows(monitor->finish()) : Status{};
    };
    for (;;) {
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
        inbox->take(messages, events);
        for (const auto& e : events) {
            say(e);
        }
        events.clear();
        for (const auto& m : messages) {
            handle(m);
        }
        messages.clear();
        if (auto st = recorder.flush(); !st) {
            return st.error();
        }
        if (auto st = feedMonitor(false); !st) {
            return st.error();
        }
        const double elapsedS = std::chrono::duration<double>(Clock::now() - t0).count();
        const bool timeUp = options.durationS > 0 && elapsedS >= options.durationS;
        if (Clock::now() - lastReport >= std::chrono::seconds(1) || timeUp) {
            lastReport = Clock::now();
            const auto& c = recorder.counts();
            const std::string detail =
                std::to_string(c.rows) + " rows, " + std::to_string(c.samples) + " samples, " +
                std::to_string(c.late) + " late, " + std::to_string(c.duplicates) + " duplicate, " +
                std::to_string(c.malformed) + " malformed" + ((*client)->connected() ? "" : ", link down");
            const double fraction = options.durationS > 0 ? std::min(1.0, elapsedS / options.durationS) : 0.0;
            if (reportProgress(progress, "live", fraction, detail)) {
                result.stoppedByUser = true;
                break;
            }
        }
        if (timeUp) {
            break;
        }
    }
    // What came in until the end is placed and written: the reorder window no longer waits.
    inbox->take(messages, events);
    for (const auto& m : messages) {
        handle(m);
    }
    if (auto st = recorder.flush(true); !st) {
        return st.error();
    }
    if (auto st = feedMonitor(true); !st) {
        return st.error();
    }
    result.monitored = monitor.has_value();
    // The monitor's last messages reach the broker before the client goes.
    (*client)->waitUntilDelivered(5);
    result.counts = recorder.counts();
    result.files = recorder.files();
    result.disconnects = (*client)->disconnects();
    result.ending = {Termination::Completed,
                     std::to_string(result.counts.rows) + " rows recorded in " +
                         std::to_string(result.files.size()) + " file(s)",
                     std::chrono::duration<double>(Clock::now() - t0).count()};
    return result;
}

} // namespace drytwin::live
