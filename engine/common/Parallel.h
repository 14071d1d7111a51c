#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstddef>
#include <thread>
#include <vector>

namespace drytwin {

/// @brief Runs f(i) for every i in [0, n) on up to every core, the calling thread included.
/// Each i runs exactly once; the order between them is not defined, so f must write only to
/// its own slot of a result (callers then assemble results in index order, which keeps them
/// independent of the number of threads).
template <class F> void parallelFor(std::size_t n, F&& f) {
    const unsigned threads =
        std::max(1u, std::min<unsigned>(std::thread::hardware_concurrency(),
                                        static_cast<unsigned>(std::max<std::size_t>(n, 1))));
    std::atomic<std::size_t> next{0};
    auto work = [&] {
        for (std::size_t i = next++; i < n; i = next++) {
            f(i);
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) {
        pool.emplace_back(work);
    }
    work();
    for (auto& t : pool) {
        t.join();
    }
}

/// @brief parallelFor for long items whose progress the caller's callback must hear from the
/// calling thread alone (ARCHITECTURE.md rule 3): f(i, onCallerThread) runs every i in [0, n)
/// once on up to @p maxThreads threads, the calling thread included (onCallerThread true there:
/// it may call the progress callback). Once the calling thread finds no item left, it calls
/// whileWaiting() every 200 ms until the other threads are done, to relay their progress and
/// pass on a stop. Items are taken in index order; f writes only to its own slot.
template <class F, class W>
void parallelForFromCaller(std::size_t n, unsigned maxThreads, F&& f, W&& whileWaiting) {
    const unsigned threads = std::max(1u, std::min({std::thread::hardware_concurrency(), maxThreads,
                                                    static_cast<unsigned>(std::max<std::size_t>(n, 1))}));
    std::atomic<std::size_t> next{0};
    std::atomic<unsigned> running{threads - 1};
    auto work = [&](bool onCallerThread) {
        for (std::size_t i = next++; i < n; i = next++) {
            f(i, onCallerThread);
        }
    };
    std::vector<std::thread> pool;
    for (unsigned t = 1; t < threads; ++t) {
        pool.emplace_back([&] {
            work(false);
            --running;
        });
    }
    work(true);
    while (running.load() > 0) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        if (running.load() > 0) {
            whileWaiting();
        }
    }
    for (auto& t : pool) {
        t.join();
    }
}

} // namespace drytwin
