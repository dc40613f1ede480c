// runProcess: run an external program with a time limit, capturing what it
// prints, without a shell.
//
// Behaviour:
//   - argv[0] is looked up in PATH unless it contains a '/'; nothing is
//     interpreted by a shell, so file names with spaces are safe;
//   - the child gets /dev/null as stdin and ONE pipe for stdout and stderr
//     (so their lines stay in order); it runs in its own process group;
//   - when timeout_s passes, or SIGINT / SIGTERM reaches this process while
//     the child runs, the child's whole process group gets SIGTERM, then
//     SIGKILL after kTerminateGraceS; the result says which;
//   - every complete output line is passed to on_line as it arrives, and
//     on_progress is called every progress_interval_s with the elapsed time
//     and the last non-empty line (for "still rendering ..." messages).
// Single-threaded use only: it installs its own SIGINT / SIGTERM handlers
// while it runs and restores the previous ones before returning.
#pragma once

#include <functional>
#include <string>
#include <vector>

namespace tsf {

/// Seconds between SIGTERM and SIGKILL when a child is stopped.
inline constexpr double kTerminateGraceS = 2.0;

struct ProcessOptions {
    double timeout_s = 0;              ///< 0 = no limit
    double progress_interval_s = 5.0;  ///< how often on_progress is called
    std::function<void(double elapsed_s, const std::string& last_line)> on_progress;
    std::function<void(const std::string& line)> on_line;
    size_t max_output_bytes = 16u << 20;  ///< output kept in ProcessResult::output (the rest is counted, not kept)
};

struct ProcessResult {
    enum class End {
        Exited,       ///< the program ended by itself; exit_code is valid
        Signalled,    ///< a signal it did not ask for ended it (a crash); signal is valid
        TimedOut,     ///< stopped by us after timeout_s
        Interrupted,  ///< stopped by us because this process got SIGINT / SIGTERM
        NotStarted,   ///< it could not be started (start_error says why)
    };
    End end = End::NotStarted;
    int exit_code = -1;
    int signal = 0;
    double elapsed_s = 0;
    long peak_memory_kb = 0;       ///< the child's peak resident memory (its own, not its children's)
    std::string output;            ///< stdout and stderr interleaved, up to max_output_bytes
    size_t output_dropped_bytes = 0;
    std::string start_error;       ///< End::NotStarted: the OS's reason

    bool succeeded() const { return end == End::Exited && exit_code == 0; }
};

/// Runs argv (argv[0] = program) and waits for it as described above.
/// An empty argv gives End::NotStarted.
ProcessResult runProcess(const std::vector<std::string>& argv, const ProcessOptions& options);

/// Full path of an executable named `name` found in PATH, or "" (a name with
/// a '/' is returned as is when that file is executable).
std::string findExecutable(const std::string& name);

}  // namespace tsf
