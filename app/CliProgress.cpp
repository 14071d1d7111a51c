#include "CliProgress.h"

#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <unistd.h>

namespace drytwin::app {

std::atomic<bool> g_interrupted{false};

namespace {
extern "C" void onSigint(int) {
    g_interrupted = true;
}
} // namespace

void installInterruptHandler() {
    std::signal(SIGINT, onSigint);
}

Progress makeCliProgress(bool quiet) {
    const bool tty = ::isatty(STDERR_FILENO) != 0;
    struct State {
        std::string stage;
        int lastDecile = -1;
    };
    auto state = std::make_shared<State>();
    return [quiet, tty, state](const ProgressInfo& info) {
        if (g_interrupted) {
            return ProgressAction::Stop;
        }
        if (quiet) {
            return ProgressAction::Continue;
        }
        const int pct = static_cast<int>(info.fraction * 100.0 + 0.5);
        if (tty) {
            std::fprintf(stderr, "\r\033[K[%s] %3d%% %s", info.stage.c_str(), pct, info.detail.c_str());
            if (info.fraction >= 1.0) {
                std::fputc('\n', stderr);
            }
        } else {
            const int decile = pct / 10;
            if (info.stage != state->stage || decile != state->lastDecile) {
                std::fprintf(stderr, "[%s] %3d%% %s\n", info.stage.c_str(), pct, info.detail.c_str());
            }
            state->lastDecile = decile;
        }
        state->stage = info.stage;
        std::fflush(stderr);
        return ProgressAction::Continue;
    };
}

} // namespace drytwin::app
