#pragma once

#include <algorithm>
#include <atomic>
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

} // namespace drytwin
