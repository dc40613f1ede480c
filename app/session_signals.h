// The signals a feel session answers, for as long as a SessionSignals lives.
//
// SIGINT (Ctrl-C), SIGTERM (kill, timeout, a shutdown), SIGHUP (the
// terminal closed) and SIGQUIT (Ctrl-\) set the stop flag: the haptic loop
// ramps the force out, the device is left at zero and closed, and only then
// does the command finish - reporting, then ending the way the signal asks
// (finishBySignal). SIGTSTP (Ctrl-Z) sets the pause flag: the loop ramps
// out, the device holds zero, and pauseProcess() stops the process; on
// SIGCONT (fg, bg) the loop starts its start ramp again.
//
// The handlers only store to lock-free atomics. While they are installed
// they replace the temporary-file cleanup's handlers (gen/util/temp_files.h),
// which come back when this object is destroyed, after the device is closed:
// finishBySignal re-raises the signal into them. A signal the parent set to
// be ignored (nohup) stays ignored.
#pragma once

#include <atomic>
#include <csignal>

namespace tsf::cli {

class SessionSignals {
public:
    SessionSignals();
    ~SessionSignals();
    SessionSignals(const SessionSignals&) = delete;
    SessionSignals& operator=(const SessionSignals&) = delete;

    /// Set by a stopping signal; the haptic loop polls it.
    static const std::atomic<bool>& stop();
    /// Set by SIGTSTP; cleared by pauseProcess.
    static const std::atomic<bool>& pause();
    /// The first stopping signal caught (0: none).
    static int caught();
    /// Clears the pause flag and stops this process (SIGSTOP: a stop that
    /// is never discarded, as SIGTSTP is in an orphaned process group),
    /// sent to the calling thread so that it is stopped before this
    /// returns; returns when it is continued. For LoopOptions::pause.
    static void pauseProcess() noexcept;

private:
    static constexpr int kCount = 5;
    struct sigaction old_[kCount] {};
    bool installed_[kCount] = {};
};

/// After the session (the SessionSignals gone, the device closed): for
/// SIGTERM and SIGHUP, ends the process by that signal with its default
/// action, through the temporary-file cleanup, so that the exit status says
/// which signal it was. SIGINT and SIGQUIT return (the command then exits
/// with 128 + the signal, 130 and 131, as a shell reports them, without
/// the core dump SIGQUIT's default action would write); so does a signal
/// that is ignored.
void finishBySignal(int sig);

}  // namespace tsf::cli
