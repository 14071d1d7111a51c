#include "LivePublisher.h"

#include "live/TagPayload.h"

#include <chrono>
#include <cmath>
#include <thread>

namespace drytwin::live {

Status PublishOptions::validate() const {
    if (!(speed >= 0.01 && speed <= 100000)) {
        return invalidOption("--speed", "must lie in [0.01, 100000] (line seconds per second)");
    }
    if (auto st = connection.validate(); !st) {
        return st;
    }
    if (auto st = topics.validate(); !st) {
        return st;
    }
    return plant.validate();
}

Expected<PublishResult> publishBatches(const std::vector<data::Batch>& batches, const PublishOptions& options,
                                       const Progress& progress) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    if (auto st = options.validate(); !st) {
        return st.error();
    }
    auto client = MqttClient::connect(options.connection);
    if (!client) {
        return client.error();
    }
    PublishResult result;
    result.firstStampS =
        options.startEpochS > 0
            ? options.startEpochS
            : std::floor(
                  std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count());
    std::size_t totalRows = 0;
    for (const auto& b : batches) {
        totalRows += b.rows();
    }
    double lineOffsetS = 0; // line seconds from the first sample to this batch's first
    const auto paceStart = Clock::now();
    int lastPercent = -1;
    bool stopped = false;
    for (const auto& batch : batches) {
        const auto* time = batch.values(data::Column::Time);
        if (!time || batch.rows() == 0) {
            continue;
        }
        const double batchTime0 = time->front();
        std::vector<std::pair<std::string, const std::vector<double>*>> tags;
        for (const auto& s : data::columnSpecs()) {
            if (s.id != data::Column::Time && batch.has(s.id)) {
                tags.emplace_back(options.topics.topicOf(s.id), batch.values(s.id));
            }
        }
        const double batchStartStamp = result.firstStampS + lineOffsetS;
        if (auto st = (*client)->publish(options.topics.batchIdTopic(),
                                         formatTextPayload(batchStartStamp, batch.id));
            !st) {
            return st.error();
        }
        ++result.messages;
        for (std::size_t r = 0; r < batch.rows() && !stopped; ++r) {
            const double lineS = lineOffsetS + ((*time)[r] - batchTime0);
            // Paced by the line's own clock: a sample goes out when its time has come at N x.
            std::this_thread::sleep_until(paceStart +
                                          std::chrono::duration_cast<Clock::duration>(
                                              std::chrono::duration<double>(lineS / options.speed)));
            const double stamp = result.firstStampS + lineS;
            for (const auto& [topic, values] : tags) {
                if (auto st = (*client)->publish(topic, formatTagPayload(stamp, (*values)[r])); !st) {
                    return st.error();
                }
                ++result.messages;
            }
            ++result.samples;
            const int percent = static_cast<int>(100.0 * static_cast<double>(result.samples) /
                                                 static_cast<double>(std::max<std::size_t>(totalRows, 1)));
            if (percent != lastPercent) {
                lastPercent = percent;
                if (reportProgress(progress, "publish", percent / 100.0,
                                   batch.id + ", " + std::to_string(result.samples) + " samples")) {
                    stopped = true;
                }
            }
        }
        ++result.batches;
        lineOffsetS += time->back() - batchTime0 + 1.0; // the next batch's first second follows
        if (stopped) {
            break;
        }
    }
    result.lineSeconds = lineOffsetS;
    // What is queued still goes out: the recording of a stopped run keeps every sample sent.
    const double patienceS = 30 + static_cast<double>((*client)->pendingDeliveries()) / 1000.0;
    if (!(*client)->waitUntilDelivered(patienceS)) {
        return Error{ErrorKind::BadInput, "broker " + (*client)->brokerText(),
                     std::to_string((*client)->pendingDeliveries()) + " message(s) not acknowledged within " +
                         std::to_string(static_cast<int>(patienceS)) + " s (link down?)"};
    }
    if (stopped) {
        return cancelledError("publish");
    }
    result.ending = {Termination::Completed,
                     std::to_string(result.messages) + " messages published to " + (*client)->brokerText(),
                     std::chrono::duration<double>(Clock::now() - t0).count()};
    return result;
}

} // namespace drytwin::live
