#include "baselines/LstmNetwork.h"

#include "common/BlasThreads.h"

#include <cstdlib>
#include <dlfcn.h>
#include <filesystem>
#include <mutex>
#include <system_error>

// Loads libdrytwin_lstm.so once, on the first LSTM trained or read (LstmNetwork.h says why).
// The module is never unloaded: networks made by it live until the program ends.

namespace drytwin::baselines {

namespace {

constexpr const char* kModuleFile = "libdrytwin_lstm.so";

/// Where to look, in order: the environment's choice, beside the program, an installed layout
/// (bin/ and lib/drytwin/), and the build tree's output (set by engine/CMakeLists.txt).
std::vector<std::string> candidatePaths() {
    std::vector<std::string> paths;
    if (const char* chosen = std::getenv("DRYTWIN_LSTM_MODULE"); chosen && *chosen) {
        paths.emplace_back(chosen);
        return paths; // an explicit choice is not second-guessed
    }
    std::error_code ec;
    const auto program = std::filesystem::read_symlink("/proc/self/exe", ec);
    if (!ec) {
        const auto dir = program.parent_path();
        paths.push_back((dir / kModuleFile).string());
        paths.push_back((dir / ".." / "lib" / "drytwin" / kModuleFile).lexically_normal().string());
    }
#ifdef DRYTWIN_LSTM_MODULE_PATH
    paths.emplace_back(DRYTWIN_LSTM_MODULE_PATH);
#endif
    return paths;
}

struct Loaded {
    const LstmModuleEntry* entry = nullptr;
    std::string failure;
};

Loaded load() {
    Loaded out;
    std::string tried;
    const auto note = [&tried](const std::string& path, const std::string& why) {
        tried += (tried.empty() ? "" : ", ") + path + " (" + why + ")";
    };
    for (const auto& path : candidatePaths()) {
        std::error_code ec;
        if (!std::filesystem::exists(path, ec)) {
            note(path, "absent");
            continue;
        }
        void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!handle) {
            const char* why = dlerror();
            note(path, why ? why : "cannot be loaded");
            continue;
        }
        using EntryFunction = const LstmModuleEntry* (*)();
        auto function = reinterpret_cast<EntryFunction>(dlsym(handle, kLstmModuleSymbol));
        const LstmModuleEntry* entry = function ? function() : nullptr;
        if (!entry || entry->interfaceVersion != kLstmModuleInterfaceVersion || !entry->train ||
            !entry->fromJson) {
            note(path, "from another build of DryTwin");
            dlclose(handle);
            continue;
        }
        out.entry = entry;
        blasInCallingThread(); // libtorch's BLAS, called beside other threads' (common/BlasThreads.h)
        return out;
    }
    out.failure = "the LSTM's libtorch module (" + std::string(kModuleFile) +
                  ") could not be loaded; tried " + tried +
                  ". Build it (cmake --build build --target drytwin_lstm) or point DRYTWIN_LSTM_MODULE at it";
    return out;
}

} // namespace

Expected<const LstmModuleEntry*> lstmModule() {
    static std::once_flag once;
    static Loaded loaded;
    std::call_once(once, [] { loaded = load(); });
    if (!loaded.entry) {
        return Error{ErrorKind::BadInput, "LSTM module", loaded.failure};
    }
    return loaded.entry;
}

} // namespace drytwin::baselines
