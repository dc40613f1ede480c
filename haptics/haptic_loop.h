// The haptic loop: a dedicated thread that reads the device, computes the
// force and writes it, at a fixed rate (default 1 kHz).
//
// Scheduling: deadline k is t0 + k / rate on the LoopClock (absolute
// deadlines, so lateness never accumulates). A tick that wakes more than one
// period late counts as an overrun and the missed deadlines are skipped
// rather than run in a burst (the next tick comes 0.5 to 1.5 periods later).
//
// Inside a tick: no allocation, locks, logging, I/O or exceptions. The
// handler and device calls are noexcept; the log and the timing statistics
// go to memory reserved before the loop.
//
// Force safety:
//   - the output gain ramps from 0 to 1 over start_ramp_s (smoothstep) from
//     the first tick the device is homed, so a probe resting inside the
//     surface at start (or when homing completes) is not kicked;
//   - on a stop request (a signal handler sets the flag), at duration_s, or
//     when the handler asks, the gain ramps to 0 over stop_ramp_s and then
//     the loop ends;
//   - on a pause request (Ctrl-Z) the gain ramps to 0 over stop_ramp_s, the
//     device is told to hold zero (HapticDevice::holdZero), LoopOptions::pause
//     is called (it stops the process and returns when it continues), and
//     the start ramp begins again;
//   - a stall - a tick more than stall_ticks periods late (the process was
//     stopped or starved) or a device whose position is stall_ticks ticks
//     old - restarts the start ramp: forces never come back at full strength
//     onto a hand that has moved meanwhile;
//   - on EVERY exit (ramp finished, device ended or failed, a device that
//     refuses forces) the loop writes zero force before returning;
//   - the device not homed: zero force (the handler is not even asked).
// After each tick the device is told whether the probe touches and whether
// volume mode is on (HapticDevice::showStatus; the Falcon lights its LEDs).
#pragma once

#include <atomic>
#include <cstdint>
#include <string>
#include <vector>

#include "haptics/force_log.h"
#include "haptics/haptic_device.h"
#include "haptics/loop_clock.h"

namespace tsf::haptics {

/// What the loop calls once per tick. gain is the output gain to apply
/// (0..1); the record is filled for the log.
class TickHandler {
public:
    virtual ~TickHandler() = default;
    virtual Vec3 tick(const DeviceState& state, double gain, LogRecord& record) noexcept = 0;
};

struct LoopOptions {
    double rate_Hz = 1000.0;
    double duration_s = 0.0;     ///< 0 = until the device ends or a stop request
    double start_ramp_s = 1.0;
    double stop_ramp_s = 0.1;
    /// Consecutive refused writes after which the device counts as failed.
    int max_failed_writes = 3;
    /// A stall this many ticks long (lateness or a stale position) restarts the start ramp.
    int stall_ticks = 5;
    /// Set (by a signal handler) to pause the session; may be null. The loop
    /// never clears it: `pause` must.
    const std::atomic<bool>* pause_requested = nullptr;
    /// Called on the loop's thread once the device holds zero; returns when
    /// the session may go on (stopping the process is its business).
    void (*pause)() noexcept = nullptr;
};

enum class LoopEnd {
    kDuration,      ///< duration_s reached
    kDeviceEnded,   ///< the script or recording finished
    kInterrupted,   ///< the stop flag was set (Ctrl-C)
    kDeviceFailed,  ///< read failed or writes were refused
};

const char* loopEndName(LoopEnd end);

/// Timing histogram with 1 us bins up to kMaxMicros (anything above lands in
/// the last bin; the exact maximum is kept apart). Fixed size, no allocation
/// after construction.
class MicrosHistogram {
public:
    static constexpr int kMaxMicros = 20000;
    MicrosHistogram() : bins_(kMaxMicros + 1, 0) {}
    void add(double seconds) noexcept;
    uint64_t count() const { return count_; }
    double max_us() const { return max_us_; }
    /// q in [0, 1]; the upper edge of the bin holding that quantile, us.
    double quantile_us(double q) const;

private:
    std::vector<uint64_t> bins_;
    uint64_t count_ = 0;
    double max_us_ = 0.0;
};

struct LoopStats {
    LoopEnd end = LoopEnd::kDuration;
    uint64_t ticks = 0;
    double elapsed_s = 0.0;        ///< loop clock time from first deadline to the end
    double rate_Hz = 0.0;          ///< ticks / elapsed
    double target_rate_Hz = 0.0;
    MicrosHistogram lateness;      ///< wake-up time minus deadline
    MicrosHistogram compute;       ///< read + force + write, on the steady clock (real CPU time)
    uint64_t overruns = 0;         ///< ticks that woke more than a period late
    uint64_t failed_writes = 0;
    uint64_t pauses = 0;           ///< pause requests served (zero held, then the start ramp again)
    uint64_t stalls = 0;           ///< stalls that restarted the start ramp
    bool zero_force_sent = false;  ///< the final zero write happened
};

/// Runs the loop on the calling thread until it ends (see LoopEnd). log may
/// be null. Never throws.
void runHapticLoop(HapticDevice& device, TickHandler& handler, LoopClock& clock, const LoopOptions& options,
                   const std::atomic<bool>& stop_requested, ForceLog* log, LoopStats& stats) noexcept;

/// Runs runHapticLoop on a new thread (asking for real-time priority when
/// `realtime_priority`; refusal is fine and reported in priority_note) and
/// waits for it. Throws std::system_error when no thread can be started
/// (nothing was sent to the device then).
void runHapticLoopThread(HapticDevice& device, TickHandler& handler, LoopClock& clock, const LoopOptions& options,
                         const std::atomic<bool>& stop_requested, ForceLog* log, LoopStats& stats,
                         bool realtime_priority, std::string* priority_note = nullptr);

}  // namespace tsf::haptics
