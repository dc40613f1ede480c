// The haptic loop's logic on a fake clock: tick count, deadlines, overruns,
// ramps, and zero force on every way out. No real-time assertions here -
// jitter on this machine is measured by the benchmark, not asserted.
#include <atomic>
#include <cmath>
#include <vector>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "haptics/haptic_loop.h"

using namespace tsf::haptics;

namespace {

/// A device that records every force written and can end or fail on cue.
class RecordingDevice final : public HapticDevice {
public:
    double end_at_s = 1e9;
    double fail_at_s = 1e9;
    bool refuse_writes = false;
    bool homed = true;
    double homed_at_s = 0.0;  ///< homed from this loop time on
    double stale_from_s = 1e9, stale_until_s = 0.0;  ///< the position is this many ticks old in between
    std::vector<Vec3> forces;
    std::vector<double> read_times;

    std::string name() const override { return "recording"; }
    DeviceLimits limits() const override { return {}; }
    bool needsRealtime() const override { return false; }
    void open() override {}
    void close() noexcept override {}
    ReadStatus read(double t, DeviceState& out) noexcept override {
        if (t >= fail_at_s) return ReadStatus::kFailed;
        if (t >= end_at_s) return ReadStatus::kEnded;
        read_times.push_back(t);
        out.t_s = t;
        out.position_m = Vec3(0.0);
        out.homed = homed && t >= homed_at_s;
        out.stale_ticks = t >= stale_from_s && t < stale_until_s ? uint32_t((t - stale_from_s) * 1000.0) + 1 : 0;
        return ReadStatus::kOk;
    }
    bool writeForce(const Vec3& f) noexcept override {
        forces.push_back(f);
        return !refuse_writes;
    }
};

/// Asks for a constant 2 N; records the gains it was given.
class ConstantHandler final : public TickHandler {
public:
    std::vector<double> gains;
    FakeLoopClock* slow_clock = nullptr;  ///< when set, each tick takes slow_s
    double slow_s = 0.0;
    Vec3 tick(const DeviceState&, double gain, LogRecord&) noexcept override {
        gains.push_back(gain);
        if (slow_clock) slow_clock->advance(slow_s);
        return Vec3(0.0, 2.0 * gain, 0.0);
    }
};

struct Result {
    LoopStats stats;
    RecordingDevice device;
    ConstantHandler handler;
};

}  // namespace

TEST(Loop, RunsOneTickPerPeriodAndEndsOnDuration) {
    RecordingDevice dev;
    ConstantHandler h;
    FakeLoopClock clock;
    LoopOptions o;
    o.duration_s = 2.0;
    o.stop_ramp_s = 0.1;
    std::atomic<bool> stop{false};
    ForceLog log(5000);
    LoopStats s;
    runHapticLoop(dev, h, clock, o, stop, &log, s);
    EXPECT_EQ(s.end, LoopEnd::kDuration);
    // 2 s of ticks, plus the 0.1 s ramp-down, at 1 kHz.
    EXPECT_NEAR(double(s.ticks), 2100.0, 2.0);
    EXPECT_EQ(log.size(), s.ticks);
    for (size_t k = 1; k < dev.read_times.size(); ++k) ASSERT_NEAR(dev.read_times[k] - dev.read_times[k - 1], 0.001, 1e-9);
    EXPECT_EQ(s.overruns, 0u);
    EXPECT_NEAR(s.rate_Hz, 1000.0, 1.0);
    EXPECT_EQ(dev.forces.back(), Vec3(0.0));
    EXPECT_TRUE(s.zero_force_sent);
}

TEST(Loop, RampsForceInAtStartAndOutAtStop) {
    RecordingDevice dev;
    ConstantHandler h;
    FakeLoopClock clock;
    LoopOptions o;
    o.duration_s = 1.5;
    o.start_ramp_s = 1.0;
    o.stop_ramp_s = 0.2;
    std::atomic<bool> stop{false};
    LoopStats s;
    runHapticLoop(dev, h, clock, o, stop, nullptr, s);
    ASSERT_GT(h.gains.size(), 1700u);
    EXPECT_EQ(h.gains.front(), 0.0);                   // nothing at t = 0
    EXPECT_LT(h.gains[100], 0.05);                     // still small at 0.1 s
    EXPECT_NEAR(h.gains[1000], 1.0, 1e-9);             // full after the ramp
    for (size_t k = 1; k < h.gains.size(); ++k)         // never a step
        ASSERT_LT(std::abs(h.gains[k] - h.gains[k - 1]), 0.02) << k;
    EXPECT_LT(h.gains.back(), 0.01);                   // ramped down at the end
    EXPECT_EQ(dev.forces.back(), Vec3(0.0));
}

TEST(Loop, StopFlagRampsDownZeroesAndReportsInterrupted) {
    RecordingDevice dev;
    ConstantHandler h;
    FakeLoopClock clock;
    LoopOptions o;
    o.start_ramp_s = 0.0;
    o.stop_ramp_s = 0.05;
    std::atomic<bool> stop{false};
    // Set the flag from "another thread" after 300 ticks, through the clock.
    clock.lateness_s = [&](uint64_t k) {
        if (k == 300) stop.store(true);
        return 0.0;
    };
    LoopStats s;
    runHapticLoop(dev, h, clock, o, stop, nullptr, s);
    EXPECT_EQ(s.end, LoopEnd::kInterrupted);
    EXPECT_NEAR(double(s.ticks), 350.0, 2.0);
    EXPECT_EQ(dev.forces.back(), Vec3(0.0));
}

TEST(Loop, DeviceEndOrFailureStopsAtOnceWithZeroForce) {
    for (bool fail : {false, true}) {
        RecordingDevice dev;
        (fail ? dev.fail_at_s : dev.end_at_s) = 0.25;
        ConstantHandler h;
        FakeLoopClock clock;
        std::atomic<bool> stop{false};
        LoopStats s;
        runHapticLoop(dev, h, clock, LoopOptions{}, stop, nullptr, s);
        EXPECT_EQ(s.end, fail ? LoopEnd::kDeviceFailed : LoopEnd::kDeviceEnded);
        EXPECT_NEAR(double(s.ticks), 250.0, 1.0);
        ASSERT_FALSE(dev.forces.empty());
        EXPECT_EQ(dev.forces.back(), Vec3(0.0));
    }
}

TEST(Loop, RefusedWritesCountAsAFailedDevice) {
    RecordingDevice dev;
    dev.refuse_writes = true;
    ConstantHandler h;
    FakeLoopClock clock;
    std::atomic<bool> stop{false};
    LoopOptions o;
    o.max_failed_writes = 3;
    LoopStats s;
    runHapticLoop(dev, h, clock, o, stop, nullptr, s);
    EXPECT_EQ(s.end, LoopEnd::kDeviceFailed);
    EXPECT_EQ(s.failed_writes, 3u);
    EXPECT_EQ(dev.forces.back(), Vec3(0.0));
}

TEST(Loop, LateWakeUpsCountAsOverrunsAndSkipMissedDeadlines) {
    RecordingDevice dev;
    dev.end_at_s = 1.0;
    ConstantHandler h;
    FakeLoopClock clock;
    // Every 100th wake-up is 3.5 periods late; the others 20 us late.
    clock.lateness_s = [](uint64_t k) { return k % 100 == 50 ? 0.0035 : 20e-6; };
    std::atomic<bool> stop{false};
    LoopStats s;
    runHapticLoop(dev, h, clock, LoopOptions{}, stop, nullptr, s);
    EXPECT_EQ(s.overruns, 10u);
    // Missed deadlines are skipped, not replayed in a burst: no two reads
    // closer than half a period apart.
    for (size_t k = 1; k < dev.read_times.size(); ++k)
        ASSERT_GT(dev.read_times[k] - dev.read_times[k - 1], 0.0005 - 1e-9) << k;
    EXPECT_NEAR(s.lateness.quantile_us(0.5), 21.0, 1.0);  // 1 us bins, upper edge
    EXPECT_NEAR(s.lateness.max_us(), 3500.0, 1.0);
    EXPECT_LT(s.ticks, 1000u);
}

TEST(Loop, UnhomedDeviceGetsZeroForceAndTheHandlerIsNotAsked) {
    RecordingDevice dev;
    dev.homed = false;
    dev.end_at_s = 0.1;
    ConstantHandler h;
    FakeLoopClock clock;
    std::atomic<bool> stop{false};
    LoopOptions o;
    o.start_ramp_s = 0.0;
    LoopStats s;
    runHapticLoop(dev, h, clock, o, stop, nullptr, s);
    EXPECT_TRUE(h.gains.empty());
    for (const Vec3& f : dev.forces) EXPECT_EQ(f, Vec3(0.0));
}

TEST(Loop, ForceRampsInFromTheFirstHomedTick) {
    // A device that homes late (the Falcon after the user moved the grip)
    // must not get full force at once: the start ramp waits for the homing.
    RecordingDevice dev;
    dev.homed_at_s = 3.0;
    ConstantHandler h;
    FakeLoopClock clock;
    LoopOptions o;
    o.duration_s = 5.0;
    std::atomic<bool> stop{false};
    LoopStats s;
    runHapticLoop(dev, h, clock, o, stop, nullptr, s);
    ASSERT_GT(h.gains.size(), 1500u);
    EXPECT_NEAR(h.gains.front(), 0.0, 1e-12);        // the first homed tick
    EXPECT_NEAR(h.gains[500], 0.5, 0.01);            // half-way through the 1 s ramp
    EXPECT_NEAR(h.gains[1500], 1.0, 1e-12);
    for (size_t k = 0; k < 3000; ++k) EXPECT_EQ(dev.forces[k], Vec3(0.0));  // nothing before homing
}

TEST(Loop, AStalledTickRestartsTheStartRamp) {
    // Wake-up 1500 comes 50 ms late (the process was stopped or starved):
    // the gain starts again from zero, whatever it was.
    RecordingDevice dev;
    ConstantHandler h;
    FakeLoopClock clock;
    clock.lateness_s = [](uint64_t k) { return k == 1500 ? 0.05 : 0.0; };
    LoopOptions o;
    o.duration_s = 3.0;
    o.start_ramp_s = 0.5;
    std::atomic<bool> stop{false};
    LoopStats s;
    runHapticLoop(dev, h, clock, o, stop, nullptr, s);
    EXPECT_EQ(s.stalls, 1u);
    ASSERT_GT(h.gains.size(), 1700u);
    EXPECT_DOUBLE_EQ(h.gains[1499], 1.0);
    EXPECT_DOUBLE_EQ(h.gains[1500], 0.0);
    EXPECT_LT(h.gains[1550], 0.1);
    EXPECT_DOUBLE_EQ(h.gains[2100], 1.0);
    // A few ticks late is jitter, not a stall.
    RecordingDevice dev2;
    ConstantHandler h2;
    FakeLoopClock clock2;
    clock2.lateness_s = [](uint64_t k) { return k == 1500 ? 0.003 : 0.0; };
    LoopStats s2;
    runHapticLoop(dev2, h2, clock2, o, stop, nullptr, s2);
    EXPECT_EQ(s2.stalls, 0u);
    EXPECT_DOUBLE_EQ(h2.gains[1500], 1.0);
}

TEST(Loop, AStalePositionRestartsTheStartRamp) {
    // The device's position stops updating for 20 ms (a run of lost
    // replies): once it is stall_ticks old the gain drops to zero and, when
    // positions come again, ramps in anew.
    RecordingDevice dev;
    dev.stale_from_s = 1.5;
    dev.stale_until_s = 1.52;
    ConstantHandler h;
    FakeLoopClock clock;
    LoopOptions o;
    o.duration_s = 3.0;
    o.start_ramp_s = 0.5;
    std::atomic<bool> stop{false};
    LoopStats s;
    runHapticLoop(dev, h, clock, o, stop, nullptr, s);
    EXPECT_EQ(s.stalls, 1u);
    // The handler is asked while homed; gains index the ticks.
    EXPECT_DOUBLE_EQ(h.gains[1502], 1.0);  // 3 ticks stale: jitter
    EXPECT_DOUBLE_EQ(h.gains[1510], 0.0);
    EXPECT_LT(h.gains[1560], 0.1);
    EXPECT_DOUBLE_EQ(h.gains[2200], 1.0);
}

TEST(Loop, APauseRampsOutHoldsZeroCallsPauseAndRampsInAgain) {
    RecordingDevice dev;
    ConstantHandler h;
    FakeLoopClock clock;
    static std::atomic<bool> pause{false};
    static size_t forces_at_pause = 0;
    static RecordingDevice* device = nullptr;
    device = &dev;
    pause.store(false);
    struct Pauser {
        static void paused() noexcept {
            pause.store(false);
            forces_at_pause = device->forces.size();
        }
    };
    LoopOptions o;
    o.duration_s = 3.0;
    o.start_ramp_s = 0.5;
    o.stop_ramp_s = 0.1;
    o.pause_requested = &pause;
    o.pause = &Pauser::paused;
    clock.lateness_s = [](uint64_t k) {
        if (k == 1200) pause.store(true);  // Ctrl-Z at 1.2 s
        return 0.0;
    };
    std::atomic<bool> stop{false};
    LoopStats s;
    runHapticLoop(dev, h, clock, o, stop, nullptr, s);
    EXPECT_EQ(s.pauses, 1u);
    EXPECT_EQ(s.end, LoopEnd::kDuration);
    ASSERT_GT(forces_at_pause, 1250u);
    // Ramped out over 0.1 s, then zero written (and held) before the pause.
    EXPECT_NEAR(dev.forces[1150].y, 2.0, 1e-12);
    EXPECT_LT(dev.forces[forces_at_pause - 4].y, 0.01);
    EXPECT_EQ(dev.forces[forces_at_pause - 1], Vec3(0.0));
    EXPECT_EQ(dev.forces[forces_at_pause - 2], Vec3(0.0));
    // After it: from zero, ramped in over start_ramp_s.
    EXPECT_EQ(dev.forces[forces_at_pause], Vec3(0.0));
    EXPECT_LT(dev.forces[forces_at_pause + 100].y, 0.5);
    EXPECT_NEAR(dev.forces[forces_at_pause + 700].y, 2.0, 1e-12);
}

TEST(Histogram, QuantilesOfKnownSamples) {
    MicrosHistogram hist;
    for (int us = 1; us <= 100; ++us) hist.add(us * 1e-6 - 0.5e-6);  // 0.5, 1.5, ..., 99.5 us
    EXPECT_EQ(hist.count(), 100u);
    EXPECT_NEAR(hist.quantile_us(0.5), 50.0, 1e-9);
    EXPECT_NEAR(hist.quantile_us(0.99), 99.0, 1e-9);
    EXPECT_NEAR(hist.max_us(), 99.5, 1e-9);
    hist.add(1.0);  // one second: beyond the last bin, still the exact max
    EXPECT_NEAR(hist.max_us(), 1e6, 1e-6);
}
