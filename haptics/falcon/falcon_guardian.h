// FalconGuardian: a small process that leaves the Falcon at zero force when
// the process serving it dies without doing so itself.
//
// The Falcon holds the last motor command it was sent. The session process
// zeroes it on every way out it lives through (the loop's ramp, signals,
// exceptions), but nothing in a process runs after SIGKILL, a crash or an
// abort: its USB interface is released by the kernel with the motors still
// pushing. The guardian is forked before the device is opened (so it holds
// no USB state of its own) and waits on a pipe whose only writer is the
// session process:
//   - a byte on the pipe: the session closed the device at zero force; the
//     guardian exits without touching it;
//   - end of file without that byte: the session process is gone, whatever
//     ended it; the guardian opens the Falcon (retrying while the dead
//     process's interface is being released), writes zero packets with the
//     homing bit, reads their replies, says so on stderr and exits.
// The guardian runs in its own session and process group and ignores
// SIGHUP, SIGINT, SIGQUIT and SIGTSTP: closing a terminal, Ctrl-C, Ctrl-Z
// and Ctrl-\ (SIGQUIT) signal the whole foreground group, and the guardian
// must outlive them. SIGTERM and SIGKILL still end it (a shutdown).
//
// What no software on the host covers (docs/haptics.md, Safety): SIGSTOP
// (the process is frozen, alive, holding the interface: the guardian does
// not act, the Falcon keeps the last command), a process hung inside a USB
// call or the kernel, and the host itself stopping (power, kernel panic).
// The power switch is the Falcon's only guard then.
#pragma once

#include <sys/types.h>

#include "haptics/falcon/falcon_device.h"

namespace tsf::haptics {

/// Zero packets the guardian sends; a quarter of a second of them.
inline constexpr int kGuardianZeroPackets = 250;

/// Opens the device with `opener` and writes `packets` zero commands (the
/// homing bit set), each followed by a short read of the reply. Returns the
/// packets written; 0 when the device cannot be opened. Retries opening for
/// about two seconds (the dead process's interface may still be held).
int writeFalconZeroPackets(const UsbOpener& opener, int packets) noexcept;

class FalconGuardian {
public:
    /// Forks the guardian. Throws DeviceError when it cannot (no device is
    /// open yet then). `opener` is only called in the guardian.
    explicit FalconGuardian(UsbOpener opener);
    /// release()
    ~FalconGuardian();
    FalconGuardian(const FalconGuardian&) = delete;
    FalconGuardian& operator=(const FalconGuardian&) = delete;

    /// The session closed the device at zero force: the guardian exits
    /// without touching it (waited for). Idempotent.
    void release() noexcept;
    pid_t pid() const { return pid_; }

private:
    int fd_ = -1;
    pid_t pid_ = -1;
};

}  // namespace tsf::haptics
