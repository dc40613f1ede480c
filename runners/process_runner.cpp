#include "runners/process_runner.h"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <thread>

extern char** environ;

namespace tsf {
namespace {

using Clock = std::chrono::steady_clock;

// Set by the signal handler; read by the wait loop.
volatile sig_atomic_t g_stop_signal = 0;

extern "C" void onStopSignal(int sig) { g_stop_signal = sig; }

// Installs the stop handlers for the lifetime of the object.
class StopSignalGuard {
public:
    StopSignalGuard() {
        g_stop_signal = 0;
        struct sigaction sa {};
        sa.sa_handler = onStopSignal;
        sigemptyset(&sa.sa_mask);
        sa.sa_flags = 0;  // no SA_RESTART: poll() returns EINTR at once
        sigaction(SIGINT, &sa, &old_int_);
        sigaction(SIGTERM, &sa, &old_term_);
    }
    ~StopSignalGuard() {
        sigaction(SIGINT, &old_int_, nullptr);
        sigaction(SIGTERM, &old_term_, nullptr);
    }
    StopSignalGuard(const StopSignalGuard&) = delete;
    StopSignalGuard& operator=(const StopSignalGuard&) = delete;

private:
    struct sigaction old_int_ {};
    struct sigaction old_term_ {};
};

double secondsSince(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

// Waits for pid without blocking forever; true when it was reaped.
bool reap(pid_t pid, int& status, rusage& usage, bool block) {
    for (;;) {
        const pid_t r = wait4(pid, &status, block ? 0 : WNOHANG, &usage);
        if (r == pid) return true;
        if (r == 0) return false;
        if (errno != EINTR) return true;  // already reaped or not ours: nothing to wait for
    }
}

// SIGTERM to the group, SIGKILL after the grace period; reaps the child.
void stopGroup(pid_t pid, int& status, rusage& usage) {
    kill(-pid, SIGTERM);
    const auto t0 = Clock::now();
    while (secondsSince(t0) < kTerminateGraceS) {
        if (reap(pid, status, usage, false)) {
            kill(-pid, SIGKILL);  // anything it started and left behind
            return;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    kill(-pid, SIGKILL);
    reap(pid, status, usage, true);
}

class LineSplitter {
public:
    LineSplitter(const ProcessOptions& o, ProcessResult& r) : opts_(o), result_(r) {}
    void feed(const char* data, size_t n) {
        const size_t keep = std::min(n, opts_.max_output_bytes - std::min(opts_.max_output_bytes, result_.output.size()));
        result_.output.append(data, keep);
        result_.output_dropped_bytes += n - keep;
        for (size_t i = 0; i < n; ++i) {
            if (data[i] == '\n') flush();
            else if (data[i] != '\r') partial_ += data[i];
        }
    }
    void flush() {
        if (!partial_.empty()) last_line_ = partial_;
        if (opts_.on_line) opts_.on_line(partial_);
        partial_.clear();
    }
    void finish() {
        if (!partial_.empty()) flush();
    }
    const std::string& lastLine() const { return last_line_; }

private:
    const ProcessOptions& opts_;
    ProcessResult& result_;
    std::string partial_;
    std::string last_line_;
};

}  // namespace

std::string findExecutable(const std::string& name) {
    if (name.empty()) return "";
    if (name.find('/') != std::string::npos) return access(name.c_str(), X_OK) == 0 ? name : "";
    const char* path = std::getenv("PATH");
    std::stringstream dirs(path ? path : "/usr/local/bin:/usr/bin:/bin");
    std::string dir;
    while (std::getline(dirs, dir, ':')) {
        if (dir.empty()) dir = ".";
        const std::string candidate = dir + "/" + name;
        struct stat st {};
        if (stat(candidate.c_str(), &st) == 0 && S_ISREG(st.st_mode) && access(candidate.c_str(), X_OK) == 0)
            return candidate;
    }
    return "";
}

ProcessResult runProcess(const std::vector<std::string>& argv, const ProcessOptions& opts) {
    ProcessResult result;
    if (argv.empty()) {
        result.start_error = "no program given";
        return result;
    }
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
        result.start_error = std::string("cannot create a pipe: ") + std::strerror(errno);
        return result;
    }
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 1);
    posix_spawn_file_actions_adddup2(&actions, fds[1], 2);
    posix_spawnattr_t attr;
    posix_spawnattr_init(&attr);
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    sigaddset(&defaults, SIGINT);
    sigaddset(&defaults, SIGTERM);
    sigaddset(&defaults, SIGPIPE);
    posix_spawnattr_setsigmask(&attr, &none);
    posix_spawnattr_setsigdefault(&attr, &defaults);
    posix_spawnattr_setpgroup(&attr, 0);  // its own group: we can stop it and all it starts
    posix_spawnattr_setflags(&attr, POSIX_SPAWN_SETPGROUP | POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);

    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);

    StopSignalGuard guard;
    const auto t0 = Clock::now();
    pid_t pid = 0;
    const int spawn_error = posix_spawnp(&pid, args[0], &actions, &attr, args.data(), environ);
    posix_spawn_file_actions_destroy(&actions);
    posix_spawnattr_destroy(&attr);
    close(fds[1]);
    if (spawn_error != 0) {
        close(fds[0]);
        result.start_error = "cannot start " + argv[0] + ": " + std::strerror(spawn_error);
        return result;
    }

    LineSplitter lines(opts, result);
    int status = 0;
    rusage usage {};
    bool eof = false;
    double next_progress = opts.progress_interval_s > 0 ? opts.progress_interval_s : 1e300;
    char buf[65536];
    // Reads what is in the pipe now, without waiting (after the child ended,
    // a process it left behind may hold the pipe open).
    auto drain = [&] {
        fcntl(fds[0], F_SETFL, fcntl(fds[0], F_GETFL) | O_NONBLOCK);
        ssize_t n;
        while (!eof && (n = read(fds[0], buf, sizeof buf)) > 0) lines.feed(buf, size_t(n));
        lines.finish();
        close(fds[0]);
        result.elapsed_s = secondsSince(t0);
        result.peak_memory_kb = usage.ru_maxrss;
    };
    for (;;) {
        const double elapsed = secondsSince(t0);
        if (g_stop_signal != 0 || (opts.timeout_s > 0 && elapsed >= opts.timeout_s)) {
            result.end = g_stop_signal != 0 ? ProcessResult::End::Interrupted : ProcessResult::End::TimedOut;
            stopGroup(pid, status, usage);
            drain();
            return result;
        }
        if (elapsed >= next_progress) {
            if (opts.on_progress) opts.on_progress(elapsed, lines.lastLine());
            next_progress += opts.progress_interval_s;
        }
        int wait_ms = 200;  // also bounds how late a timeout or a signal is noticed
        if (opts.timeout_s > 0) wait_ms = std::clamp(int((opts.timeout_s - elapsed) * 1000) + 1, 1, wait_ms);
        if (!eof) {
            pollfd p{fds[0], POLLIN, 0};
            if (poll(&p, 1, wait_ms) > 0) {
                const ssize_t n = read(fds[0], buf, sizeof buf);
                if (n > 0) lines.feed(buf, size_t(n));
                else if (n == 0 || (errno != EINTR && errno != EAGAIN)) eof = true;
            }
        } else {
            std::this_thread::sleep_for(std::chrono::milliseconds(wait_ms));
        }
        if (reap(pid, status, usage, false)) break;
    }
    drain();
    if (WIFEXITED(status)) {
        result.end = ProcessResult::End::Exited;
        result.exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
        result.end = ProcessResult::End::Signalled;
        result.signal = WTERMSIG(status);
    }
    return result;
}

}  // namespace tsf
