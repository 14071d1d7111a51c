#include "common/BlasThreads.h"

#include <dlfcn.h>
#include <mutex>

namespace drytwin {

namespace {

/// OpenBLAS's own entry points, looked up at run time: the engine links the BLAS interface, not
/// OpenBLAS, and runs with any BLAS the system provides.
template <typename Function> Function openBlasFunction(const char* name) {
    return reinterpret_cast<Function>(dlsym(RTLD_DEFAULT, name));
}

} // namespace

void blasInCallingThread() {
    static std::once_flag once;
    std::call_once(once, [] {
        if (auto setThreads = openBlasFunction<void (*)(int)>("openblas_set_num_threads")) {
            setThreads(1);
        }
    });
}

std::string blasConcurrencyProblem() {
    // openblas_get_parallel(): 0 sequential build, 1 pthreads, 2 OpenMP. The sequential build is
    // not safe to call from two threads at once (its buffers are shared without a lock).
    const auto parallel = openBlasFunction<int (*)()>("openblas_get_parallel");
    if (parallel && parallel() == 0) {
        return "the BLAS is OpenBLAS built without threads (libopenblas0-serial), which is not safe to call "
               "from two threads at once, as DryTwin does (a training session beside a job, controllers side "
               "by side): install libopenblas0-pthread (scripts/install-deps.sh does)";
    }
    return {};
}

} // namespace drytwin
