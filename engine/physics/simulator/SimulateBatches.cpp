// How many batches are simulated at once: simulateBatches() spreads them over worker threads,
// reports progress per finished batch from the calling thread, stops starting new ones when told
// to, and names the batch in the error of one that failed.

#include "physics/LineSimulator.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace drytwin::physics {

using properties::ParameterSet;

Expected<std::vector<SimulationResult>> simulateBatches(const std::vector<LineInputs>& batches,
                                                        const ParameterSet& params,
                                                        const SimulationOptions& options, unsigned threads,
                                                        const Progress& progress) {
    const std::size_t nb = batches.size();
    std::vector<std::optional<Expected<SimulationResult>>> results(nb);
    std::atomic<std::size_t> next{0};
    std::atomic<bool> stop{false};
    std::mutex mutex;
    std::condition_variable finished;
    std::size_t done = 0;
    auto work = [&] {
        for (;;) {
            const std::size_t i = next++;
            if (i >= nb || stop) {
                return;
            }
            auto r = simulateLine(batches[i], params, options);
            std::lock_guard lock(mutex);
            results[i].emplace(std::move(r));
            ++done;
            finished.notify_all();
        }
    };
    if (threads == 0) {
        threads = std::max(1u, std::thread::hardware_concurrency());
    }
    threads = static_cast<unsigned>(std::min<std::size_t>(threads, std::max<std::size_t>(nb, 1)));
    std::vector<std::thread> pool;
    for (unsigned t = 0; threads > 1 && t < threads; ++t) {
        pool.emplace_back(work);
    }
    if (threads == 1) {
        for (std::size_t i = 0; i < nb && !stop; ++i) {
            if (reportProgress(progress, "simulate", static_cast<double>(i) / static_cast<double>(nb),
                               std::to_string(i) + "/" + std::to_string(nb) + " batches")) {
                stop = true;
                break;
            }
            results[i].emplace(simulateLine(batches[i], params, options));
        }
    } else {
        // The calling thread reports progress while the pool works.
        std::unique_lock lock(mutex);
        std::size_t reported = 0;
        while (done < nb && !(stop && pool.empty())) {
            finished.wait_for(lock, std::chrono::milliseconds(50),
                              [&] { return done != reported || done == nb; });
            if (done != reported) {
                reported = done;
                lock.unlock();
                if (reportProgress(progress, "simulate",
                                   static_cast<double>(reported) / static_cast<double>(nb),
                                   std::to_string(reported) + "/" + std::to_string(nb) + " batches")) {
                    stop = true;
                }
                lock.lock();
            }
            if (stop) {
                break;
            }
        }
    }
    for (auto& t : pool) {
        t.join();
    }
    if (stop) {
        return cancelledError("simulate");
    }
    std::vector<SimulationResult> out;
    out.reserve(nb);
    for (std::size_t i = 0; i < nb; ++i) {
        if (!results[i] || !*results[i]) {
            Error e =
                results[i] ? results[i]->error() : Error{ErrorKind::Numerical, "simulate", "batch not run"};
            if (e.place.rfind("batch ", 0) != 0) { // LineInputs::validate names the batch itself
                const std::string& id = batches[i].batchId;
                e.place = "batch " + (id.empty() ? std::to_string(i + 1) : id) + ": " + e.place;
            }
            return e;
        }
        out.push_back(std::move(results[i]->value()));
    }
    return out;
}

} // namespace drytwin::physics
