#include "haptics/haptic_loop.h"

#include <pthread.h>
#include <sched.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <thread>

#include "haptics/force_model.h"

namespace tsf::haptics {
namespace {

double smoothstep01(double x) noexcept {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

}  // namespace

const char* loopEndName(LoopEnd end) {
    switch (end) {
    case LoopEnd::kDuration: return "duration";
    case LoopEnd::kDeviceEnded: return "device-ended";
    case LoopEnd::kInterrupted: return "interrupted";
    case LoopEnd::kDeviceFailed: return "device-failed";
    }
    return "?";
}

void MicrosHistogram::add(double seconds) noexcept {
    const double us = std::max(0.0, seconds * 1e6);
    const int bin = us >= kMaxMicros ? kMaxMicros : int(us);
    ++bins_[size_t(bin)];
    ++count_;
    max_us_ = std::max(max_us_, us);
}

double MicrosHistogram::quantile_us(double q) const {
    if (count_ == 0) return 0.0;
    const uint64_t rank = std::max<uint64_t>(1, uint64_t(std::ceil(std::clamp(q, 0.0, 1.0) * double(count_))));
    uint64_t seen = 0;
    for (size_t b = 0; b < bins_.size(); ++b) {
        seen += bins_[b];
        if (seen >= rank) return std::min(double(b + 1), max_us_);
    }
    return max_us_;
}

void runHapticLoop(HapticDevice& device, TickHandler& handler, LoopClock& clock, const LoopOptions& options,
                   const std::atomic<bool>& stop_requested, ForceLog* log, LoopStats& stats) noexcept {
    const double period = 1.0 / options.rate_Hz;
    stats.target_rate_Hz = options.rate_Hz;
    const double t0 = clock.now();
    uint64_t k = 0;
    bool stopping = false;
    double stop_t = 0.0;
    int failed_in_row = 0;
    double last_t = 0.0;
    double homed_t = -1.0;  // loop time the start ramp began (< 0: not homed)
    bool pausing = false;
    double pause_t = 0.0;
    const double stall_s = double(options.stall_ticks) * period;
    DeviceState state;
    LogRecord record;
    for (;;) {
        const double deadline = t0 + double(k) * period;
        clock.sleepUntil(deadline);
        const double wake = clock.now();
        const auto work_start = std::chrono::steady_clock::now();
        const double late = wake - deadline;
        stats.lateness.add(late);
        if (late > period) {
            ++stats.overruns;
            // Skip the deadlines already missed (rounded so the next tick is
            // at least half a period after this one: no burst of catch-up ticks).
            k += uint64_t(std::floor(late / period + 0.5));
        }
        const double t = wake - t0;
        last_t = t;
        const ReadStatus rs = device.read(t, state);
        if (rs != ReadStatus::kOk) {
            stats.end = rs == ReadStatus::kEnded ? LoopEnd::kDeviceEnded : LoopEnd::kDeviceFailed;
            break;
        }
        if (!stopping) {
            if (stop_requested.load(std::memory_order_relaxed)) {
                stopping = true;
                stats.end = LoopEnd::kInterrupted;
            } else if (options.duration_s > 0.0 && t >= options.duration_s) {
                stopping = true;
                stats.end = LoopEnd::kDuration;
            }
            if (stopping) stop_t = t;
        }
        if (!stopping && !pausing && options.pause_requested &&
            options.pause_requested->load(std::memory_order_relaxed)) {
            pausing = true;
            pause_t = t;
        }
        // The start ramp runs from the first homed tick: a device that homes
        // late (the Falcon, after the user has moved the grip) still gets
        // its forces faded in, and losing the homing or a stall restarts it.
        const bool stalled = (stall_s > 0.0 && late > stall_s) ||
                             (options.stall_ticks > 0 && state.stale_ticks >= uint32_t(options.stall_ticks));
        if (stalled && homed_t >= 0.0) ++stats.stalls;
        if (!state.homed || stalled) homed_t = -1.0;
        else if (homed_t < 0.0) homed_t = t;
        const double since_homed = homed_t < 0.0 ? 0.0 : t - homed_t;
        double gain = options.start_ramp_s > 0.0 ? smoothstep01(since_homed / options.start_ramp_s) : 1.0;
        if (stopping) {
            const double left = options.stop_ramp_s > 0.0 ? 1.0 - (t - stop_t) / options.stop_ramp_s : 0.0;
            if (left <= 0.0) break;
            gain *= smoothstep01(left);
        } else if (pausing) {
            const double left = options.stop_ramp_s > 0.0 ? 1.0 - (t - pause_t) / options.stop_ramp_s : 0.0;
            if (left <= 0.0) {
                // Zero held, then the process may stop; forces ramp in again after.
                device.writeForce(Vec3(0.0));
                device.holdZero();
                ++stats.pauses;
                if (options.pause) options.pause();
                pausing = false;
                homed_t = -1.0;
                ++k;
                continue;  // the next deadline follows the lateness the pause left
            }
            gain *= smoothstep01(left);
        }
        Vec3 force(0.0);
        record = LogRecord{};
        record.t_s = t;
        record.position_m = state.position_m;
        record.buttons = state.buttons;
        if (state.homed) force = handler.tick(state, gain, record);
        record.force_N = force;
        device.showStatus((record.flags & kFlagContact) != 0, record.volume);
        if (device.writeForce(force)) {
            failed_in_row = 0;
        } else {
            ++stats.failed_writes;
            if (++failed_in_row >= options.max_failed_writes) {
                stats.end = LoopEnd::kDeviceFailed;
                ++stats.ticks;
                break;
            }
        }
        stats.compute.add(std::chrono::duration<double>(std::chrono::steady_clock::now() - work_start).count());
        if (log) log->push(record);
        ++stats.ticks;
        ++k;
    }
    stats.zero_force_sent = device.writeForce(Vec3(0.0));
    stats.elapsed_s = last_t;
    stats.rate_Hz = last_t > 0.0 ? double(stats.ticks) / last_t : 0.0;
}

void runHapticLoopThread(HapticDevice& device, TickHandler& handler, LoopClock& clock, const LoopOptions& options,
                         const std::atomic<bool>& stop_requested, ForceLog* log, LoopStats& stats,
                         bool realtime_priority, std::string* priority_note) {
    std::atomic<int> priority_result{-1};
    std::thread worker([&]() noexcept {
        if (realtime_priority) {
            sched_param sp{};
            sp.sched_priority = std::max(1, sched_get_priority_max(SCHED_FIFO) - 1);
            priority_result.store(pthread_setschedparam(pthread_self(), SCHED_FIFO, &sp));
        }
        runHapticLoop(device, handler, clock, options, stop_requested, log, stats);
    });
    worker.join();
    if (priority_note) {
        const int r = priority_result.load();
        if (!realtime_priority) *priority_note = "normal priority (simulation)";
        else if (r == 0) *priority_note = "real-time priority (SCHED_FIFO)";
        else *priority_note = std::string("normal priority (SCHED_FIFO refused: ") + std::strerror(r) + ")";
    }
}

}  // namespace tsf::haptics
