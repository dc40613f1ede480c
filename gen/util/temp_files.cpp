#include "gen/util/temp_files.h"

#include <atomic>
#include <cerrno>
#include <csignal>
#include <cstdlib>
#include <cstring>
#include <stdexcept>
#include <vector>
#include <signal.h>
#include <unistd.h>

namespace tsf {
namespace {

// A slot is Free, being Filled by registerTempFile, or Ready (its path may be
// unlinked by the handler). The handler reads only Ready slots, and a slot's
// path is written before it becomes Ready, so the handler never sees half a
// path.
enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };

struct Slot {
    std::atomic<int> state{kFree};
    char path[kMaxTempPathBytes];
};

Slot g_slots[kMaxTempFiles];
std::atomic<bool> g_installed{false};

static_assert(std::atomic<int>::is_always_lock_free, "the signal handler reads the slot states");

extern "C" void removeTempFilesAndDie(int sig) {
    for (Slot& s : g_slots)
        if (s.state.load() == kReady) ::unlink(s.path);  // unlink is async-signal-safe
    ::signal(sig, SIG_DFL);
    ::raise(sig);
}

}  // namespace

int registerTempFile(const std::string& path) {
    if (path.size() >= kMaxTempPathBytes) return -1;
    for (int k = 0; k < kMaxTempFiles; ++k) {
        int expected = kFree;
        if (!g_slots[k].state.compare_exchange_strong(expected, kFilling)) continue;
        std::memcpy(g_slots[k].path, path.c_str(), path.size() + 1);
        g_slots[k].state.store(kReady);
        return k;
    }
    return -1;
}

void unregisterTempFile(int slot) {
    if (slot >= 0 && slot < kMaxTempFiles) g_slots[slot].state.store(kFree);
}

void installTempFileCleanup() {
    if (g_installed.exchange(true)) return;
    struct sigaction sa {};
    sa.sa_handler = removeTempFilesAndDie;
    sigemptyset(&sa.sa_mask);
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
        struct sigaction old {};
        // A signal the parent told us to ignore (nohup) stays ignored.
        if (sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
        sigaction(sig, &sa, nullptr);
    }
    ::signal(SIGXFSZ, SIG_IGN);
}

ScopedTempFile::ScopedTempFile(const std::string& prefix, const std::string& suffix) {
    const char* tmp = std::getenv("TMPDIR");
    const std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/" + prefix + "XXXXXX" + suffix;
    std::vector<char> buf(pattern.begin(), pattern.end());
    buf.push_back('\0');
    const int fd = ::mkstemps(buf.data(), int(suffix.size()));
    if (fd < 0) throw std::runtime_error("cannot create a temporary file " + pattern + ": " + std::strerror(errno));
    ::close(fd);
    path_ = buf.data();
    slot_ = registerTempFile(path_);
}

ScopedTempFile::~ScopedTempFile() {
    ::unlink(path_.c_str());
    unregisterTempFile(slot_);
}

}  // namespace tsf
