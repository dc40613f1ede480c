#include "app/session_signals.h"

#include <signal.h>
#include <unistd.h>

#include <cstdio>

namespace tsf::cli {
namespace {

std::atomic<bool> g_stop{false};
std::atomic<bool> g_pause{false};
std::atomic<int> g_caught{0};
static_assert(std::atomic<bool>::is_always_lock_free && std::atomic<int>::is_always_lock_free,
              "signal handlers store to these");

constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGTSTP};

extern "C" void onSessionSignal(int sig) {
    if (sig == SIGTSTP) {
        g_pause.store(true);
        return;
    }
    int none = 0;
    g_caught.compare_exchange_strong(none, sig);
    g_stop.store(true);
}

}  // namespace

SessionSignals::SessionSignals() {
    g_stop.store(false);
    g_pause.store(false);
    g_caught.store(0);
    static_assert(sizeof kSignals / sizeof kSignals[0] == kCount);
    struct sigaction sa {};
    sa.sa_handler = onSessionSignal;
    sigemptyset(&sa.sa_mask);
    sa.sa_flags = SA_RESTART;
    for (int k = 0; k < kCount; ++k) {
        if (sigaction(kSignals[k], nullptr, &old_[k]) != 0 || old_[k].sa_handler == SIG_IGN) continue;
        installed_[k] = sigaction(kSignals[k], &sa, nullptr) == 0;
    }
}

SessionSignals::~SessionSignals() {
    for (int k = 0; k < kCount; ++k)
        if (installed_[k]) sigaction(kSignals[k], &old_[k], nullptr);
}

const std::atomic<bool>& SessionSignals::stop() { return g_stop; }
const std::atomic<bool>& SessionSignals::pause() { return g_pause; }
int SessionSignals::caught() { return g_caught.load(); }

void SessionSignals::pauseProcess() noexcept {
    g_pause.store(false);
    // To this thread, not the process: a process-directed SIGSTOP may be
    // taken by another thread (the main one, waiting for the loop), and
    // until that thread runs, kill() returns here and the loop goes on
    // sending forces that the stopped process then leaves the device
    // holding. A signal to the calling thread stops it before raise returns.
    ::raise(SIGSTOP);
}

void finishBySignal(int sig) {
    if (sig != SIGTERM && sig != SIGHUP) return;
    std::fflush(nullptr);
    ::raise(sig);  // the temporary-file cleanup's handler, or the default action
}

}  // namespace tsf::cli
