// Runs the tsf binary (or another program) for end-to-end tests. Part of the
// shared test support (tests/support/).
#pragma once

#include <array>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>
#include <utility>

#include "tests/support/files.h"

namespace tsf::test {

/// The exit codes `tsf --help` documents (what a script may rely on).
inline constexpr int kExitOk = 0;
inline constexpr int kExitCheckFailed = 1;
inline constexpr int kExitBadInput = 2;
inline constexpr int kExitToolFailed = 3;
inline constexpr int kExitDeviceFailed = 4;
inline constexpr int kExitInterrupted = 130;

struct RunResult {
    int exit_code = -1;
    std::string output;  ///< stdout and stderr together
    std::string out;     ///< stdout alone (runTsf with a folder only)
    std::string err;     ///< stderr alone (runTsf with a folder only)
};

/// Runs a shell command; stdout and stderr interleaved in output.
inline RunResult runCommand(const std::string& command) {
    RunResult r;
    FILE* pipe = popen((command + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    std::array<char, 4096> buf;
    size_t n;
    while ((n = fread(buf.data(), 1, buf.size(), pipe)) > 0) r.output.append(buf.data(), n);
    const int status = pclose(pipe);
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

/// Runs `tsf <args>` (a shell command line); stdout and stderr interleaved in output.
inline RunResult runTsf(const std::string& args) { return runCommand(std::string(TSF_BINARY) + " " + args); }

/// Runs a shell command and measures it: its exit code and its peak resident
/// memory in MiB (ru_maxrss of the child; with sh -c, the larger of sh and
/// the command).
inline std::pair<int, double> runMeasured(const std::string& command) {
    const pid_t pid = ::fork();
    if (pid == 0) {
        ::execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    int status = 0;
    struct rusage usage {};
    if (pid < 0 || ::wait4(pid, &status, 0, &usage) != pid) return {-1, 0.0};
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, double(usage.ru_maxrss) / 1024.0};  // KiB on Linux
}

/// Runs `tsf <args>` with stdout and stderr captured apart (through files in
/// dir); output is stdout followed by stderr.
inline RunResult runTsf(const std::string& args, const std::filesystem::path& dir) {
    RunResult r;
    const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const std::string cmd = std::string(TSF_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readText(out);
    r.err = readText(err);
    r.output = r.out + r.err;
    return r;
}

}  // namespace tsf::test
