// The Falcon driver end to end against the fake Falcon: opening (firmware
// loaded, already running, missing), the 1 kHz loop with positions read
// through the kinematics and forces felt by the fake's motors, the homing
// gate, resynchronisation, lost replies, one packet in flight, LEDs, and
// zero force on every way out.
#include <atomic>
#include <cmath>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "haptics/falcon/falcon_device.h"
#include "haptics/haptic_loop.h"
#include "tests/haptics/fake_falcon.h"

using namespace tsf::haptics;
using tsf::haptics::testing::FakeFalcon;
using tsf::haptics::testing::FakeFalconConfig;
using tsf::haptics::testing::FakeFalconHandle;
using tsf::haptics::testing::fakeFirmwareImage;

namespace {

UsbOpener openerFor(FakeFalcon& fake) {
    return [&fake] { return std::make_unique<FakeFalconHandle>(fake); };
}

FalconOptions options(bool with_firmware = true) {
    FalconOptions o;
    if (with_firmware) o.firmware = fakeFirmwareImage();
    o.firmware_check_tries = 5;
    return o;
}

/// A Falcon whose firmware runs, homed after `homing_packets` packets
/// (-1: never).
FakeFalconConfig running(int homing_packets = 0) {
    FakeFalconConfig c;
    c.firmware_running = true;
    c.homing_packets = homing_packets;
    return c;
}

/// A fake Falcon and the driver, opened on it.
struct Rig {
    FakeFalcon fake;
    FalconDevice dev;
    explicit Rig(const FakeFalconConfig& config) : fake(config), dev(openerFor(fake), options(false)) { dev.open(); }
};

/// A slow circle in the middle of the workspace (device frame).
Vec3 circle(double t) { return {0.015 * std::cos(t), -0.005, 0.015 * std::sin(t)}; }

/// Pulls the probe toward a point with a spring, records what it saw.
class SpringHandler final : public TickHandler {
public:
    Vec3 anchor{0.0};
    double stiffness = 200.0;
    std::vector<DeviceState> seen;
    std::vector<Vec3> asked;
    Vec3 tick(const DeviceState& s, double gain, LogRecord& record) noexcept override {
        seen.push_back(s);
        Vec3 f = gain * stiffness * (anchor - s.position_m);
        if (glm::length(f) > 4.0) f *= 4.0 / glm::length(f);
        asked.push_back(f);
        record.flags = 0x01;  // "in contact", for the LEDs
        return f;
    }
};

struct Session {
    LoopStats stats;
    SpringHandler handler;
};

void run(FalconDevice& dev, Session& s, double duration_s, const std::atomic<bool>* stop = nullptr,
         int stall_ticks = LoopOptions{}.stall_ticks) {
    FakeLoopClock clock;
    LoopOptions lo;
    lo.stall_ticks = stall_ticks;
    lo.duration_s = duration_s;
    lo.start_ramp_s = 0.2;
    std::atomic<bool> never{false};
    s.handler.seen.reserve(size_t(duration_s * 1000) + 500);
    s.handler.asked.reserve(size_t(duration_s * 1000) + 500);
    runHapticLoop(dev, s.handler, clock, lo, stop ? *stop : never, nullptr, s.stats);
}

bool zero(const FalconCommand& c) { return c.motor[0] == 0 && c.motor[1] == 0 && c.motor[2] == 0; }

}  // namespace

TEST(FalconDevice, OpenLoadsFirmwareWhenNoneRuns) {
    FakeFalconConfig cfg;
    cfg.firmware_bytes = fakeFirmwareImage().size();
    FakeFalcon fake(cfg);
    FalconDevice dev(openerFor(fake), options());
    dev.open();
    EXPECT_TRUE(fake.firmwareRunning());
    EXPECT_FALSE(dev.stats().firmware_was_running);
    EXPECT_EQ(dev.stats().firmware.bytes, fakeFirmwareImage().size());
    EXPECT_EQ(fake.baudDivisor(), kFtdiBaud1500000);
    EXPECT_EQ(fake.latencyTimer(), 1);
}

TEST(FalconDevice, OpenUsesFirmwareThatAlreadyRuns) {
    FakeFalconConfig cfg;
    cfg.firmware_running = true;
    FakeFalcon fake(cfg);
    FalconDevice dev(openerFor(fake), options(false));
    dev.open();
    EXPECT_TRUE(dev.stats().firmware_was_running);
    EXPECT_EQ(fake.uploads(), 0);
    EXPECT_EQ(fake.handshakes(), 0);  // the running firmware was never reset
}

TEST(FalconDevice, OpenWithoutFirmwareSaysWhatToDo) {
    FakeFalcon fake;
    FalconDevice dev(openerFor(fake), options(false));
    try {
        dev.open();
        FAIL() << "expected a DeviceError";
    } catch (const DeviceError& e) {
        EXPECT_NE(std::string(e.what()).find("--firmware FILE"), std::string::npos) << e.what();
    }
}

TEST(FalconDevice, TracksThePoseAndAppliesTheForceAfterHoming) {
    FakeFalconConfig cfg = running(400);
    cfg.pose = circle;
    Rig rig(cfg);
    Session s;
    s.handler.anchor = Vec3(0.0, 0.01, 0.0);
    run(rig.dev, s, 3.0);
    EXPECT_EQ(s.stats.end, LoopEnd::kDuration);
    ASSERT_FALSE(s.handler.seen.empty());
    // The handler was only asked once the device was homed...
    for (const DeviceState& st : s.handler.seen) EXPECT_TRUE(st.homed);
    // ...and until then every motor command was zero.
    const auto& cmds = rig.fake.commands();
    size_t first_force = cmds.size();
    for (size_t k = 0; k < cmds.size(); ++k)
        if (!zero(cmds[k])) {
            first_force = k;
            break;
        }
    EXPECT_GE(first_force, 400u);
    // Positions follow the grip (a circle of 15 mm at y = -5 mm) to within
    // the encoders' resolution.
    double worst = 0.0;
    for (const DeviceState& st : s.handler.seen) {
        const Vec3& p = st.position_m;
        worst = std::max({worst, std::abs(std::hypot(p.x, p.z) - 0.015), std::abs(p.y + 0.005)});
    }
    EXPECT_LT(worst, 2.0 * kFalconMetresPerCount);
    // The motors pushed with the force the handler asked for: tick k sent
    // command base + k, and the loop's final zero write came last.
    const size_t ticks = s.stats.ticks, asked = s.handler.asked.size();
    ASSERT_EQ(rig.fake.commands().size(), rig.fake.forces().size());
    const size_t base = rig.fake.commands().size() - 1 - ticks;
    double worst_force = 0.0;
    for (size_t j = 0; j < asked; ++j)
        worst_force = std::max(worst_force, glm::length(rig.fake.forces()[base + ticks - asked + j] - s.handler.asked[j]));
    EXPECT_LT(worst_force, 0.05);  // whole motor units and encoder counts
    EXPECT_EQ(rig.dev.stats().resends, 0u);
    EXPECT_EQ(rig.dev.stats().solver_fallbacks, 0u);
    // Zero force at the end: the loop's last write.
    EXPECT_TRUE(zero(rig.fake.commands().back()));
    EXPECT_TRUE(s.stats.zero_force_sent);
}

TEST(FalconDevice, RefusesForceBeforeHoming) {
    Rig rig(running(-1));  // the user never homes it
    DeviceState st;
    ASSERT_EQ(rig.dev.read(0.0, st), ReadStatus::kOk);
    EXPECT_FALSE(st.homed);
    EXPECT_FALSE(rig.dev.writeForce(Vec3(0.0, 3.0, 0.0)));
    EXPECT_TRUE(zero(rig.fake.commands().back()));
    EXPECT_TRUE(rig.fake.commands().back().status & kFalconHoming);
    EXPECT_TRUE(rig.fake.commands().back().status & kFalconLedRed);
    EXPECT_EQ(rig.dev.stats().refused_forces, 1u);
    ASSERT_EQ(rig.dev.read(0.001, st), ReadStatus::kOk);
    EXPECT_TRUE(rig.dev.writeForce(Vec3(0.0)));  // zero is always fine
}

TEST(FalconDevice, ResynchronisesThroughGarbageSplitFramesAndLostReplies) {
    FakeFalconConfig cfg = running(10);
    cfg.pose = circle;
    cfg.garbage_every = 7;
    cfg.split_every = 5;
    cfg.drop_reply_every = 97;
    Rig rig(cfg);
    Session s;
    run(rig.dev, s, 2.0);
    EXPECT_EQ(s.stats.end, LoopEnd::kDuration);
    const FalconLinkStats& ls = rig.dev.stats();
    EXPECT_GT(ls.bytes_discarded, 100u);  // the garbage went
    EXPECT_GT(ls.resends, 5u);            // lost replies were given up on and resent
    EXPECT_GT(ls.frames_received, 1500u);
    EXPECT_EQ(ls.solver_fallbacks, 0u);
    for (size_t k = 100; k < s.handler.seen.size(); ++k)
        ASSERT_LT(glm::length(s.handler.seen[k].position_m), 0.02);  // no wild positions from broken frames
}

TEST(FalconDevice, KeepsOnePacketInFlight) {
    FakeFalconConfig cfg = running();
    // The firmware answers 1.5 ms after a command: the tick's read ends at
    // the chip's 1 ms latency timer without it, the next tick's read has it.
    cfg.reply_turnaround_us = 1500.0;
    Rig rig(cfg);
    Session s;
    run(rig.dev, s, 1.0);
    EXPECT_EQ(s.stats.end, LoopEnd::kDuration);
    // One packet per two ticks: nothing is sent while one is unanswered.
    EXPECT_NEAR(double(rig.dev.stats().packets_sent) / double(s.stats.ticks), 0.5, 0.02);
    EXPECT_EQ(rig.dev.stats().resends, 0u);
    EXPECT_NEAR(double(rig.dev.stats().ticks_without_frame) / double(s.stats.ticks), 0.5, 0.02);
}

TEST(FalconDevice, UnplugMidSessionEndsTheLoopAsFailed) {
    FakeFalconConfig cfg = running();
    cfg.pose = circle;
    cfg.unplug_after_packets = 800;
    Rig rig(cfg);
    Session s;
    run(rig.dev, s, 5.0);
    EXPECT_EQ(s.stats.end, LoopEnd::kDeviceFailed);
    EXPECT_NE(rig.dev.failureReason().find("unplugged"), std::string::npos) << rig.dev.failureReason();
    EXPECT_LT(s.stats.ticks, 900u);
    rig.dev.close();  // must not throw or hang on a vanished device
}

TEST(FalconDevice, SilentDeviceFails) {
    Rig rig(running());
    rig.fake.stopAnswering();  // the firmware hangs
    Session s;
    run(rig.dev, s, 5.0);
    EXPECT_EQ(s.stats.end, LoopEnd::kDeviceFailed);
    EXPECT_NE(rig.dev.failureReason().find("stopped answering"), std::string::npos) << rig.dev.failureReason();
    EXPECT_NEAR(double(s.stats.ticks), 250.0, 2.0);
    EXPECT_EQ(rig.dev.stats().max_silent_ticks, 250u);
}

TEST(FalconDevice, AFalconThatStopsAnsweringIsToldToStopPushing) {
    // A homed Falcon pushed hard (the spring's anchor far away), whose
    // firmware then hangs: it takes commands and answers none.
    FakeFalconConfig cfg = running();
    cfg.pose = circle;
    cfg.silent_after_packets = 600;
    Rig rig(cfg);
    Session s;
    s.handler.anchor = Vec3(0.0, 0.05, 0.0);
    // The driver's own guard, with the loop's stall rule (which zeroes the
    // gain sooner, tested below) switched off.
    run(rig.dev, s, 5.0, nullptr, 0);
    EXPECT_EQ(s.stats.end, LoopEnd::kDeviceFailed);
    const std::vector<FalconCommand>& sent = rig.fake.commands();
    ASSERT_GT(sent.size(), 620u);
    // It was pushing before it fell silent.
    EXPECT_FALSE(zero(sent[590])) << "the test needs a push before the silence";
    // Within stale_ticks_to_zero ticks of the last frame every command is
    // zero: no push from a position that no longer updates.
    const size_t stale = 600 + size_t(FalconOptions{}.stale_ticks_to_zero) + 1;
    for (size_t k = stale; k < sent.size(); ++k) EXPECT_TRUE(zero(sent[k])) << "command " << k << " of " << sent.size();
    EXPECT_GT(rig.dev.stats().stale_zeroed, 0u);
    // And closing after the failure still sends zero packets.
    const size_t before = sent.size();
    rig.dev.close();
    ASSERT_GT(rig.fake.commands().size(), before);
    EXPECT_TRUE(zero(rig.fake.commands().back()));

    // With the loop's stall rule: the gain drops to zero once the position
    // is stall_ticks old, before the driver's own guard.
    Rig again(cfg);
    Session t;
    t.handler.anchor = Vec3(0.0, 0.05, 0.0);
    run(again.dev, t, 5.0);
    EXPECT_EQ(t.stats.stalls, 1u);
    const std::vector<FalconCommand>& sent2 = again.fake.commands();
    ASSERT_GT(sent2.size(), 620u);
    EXPECT_FALSE(zero(sent2[590]));
    for (size_t k = 600 + size_t(LoopOptions{}.stall_ticks) + 1; k < sent2.size(); ++k)
        EXPECT_TRUE(zero(sent2[k])) << "command " << k;
}

TEST(FalconDevice, StopRequestAndDestructionLeaveZeroForce) {
    FakeFalconConfig cfg = running();
    cfg.pose = circle;
    FakeFalcon fake(cfg);
    {
        FalconDevice dev(openerFor(fake), options(false));
        dev.open();
        std::atomic<bool> stop{true};  // Ctrl-C at once
        Session s;
        run(dev, s, 10.0, &stop);
        EXPECT_EQ(s.stats.end, LoopEnd::kInterrupted);
        EXPECT_TRUE(zero(fake.commands().back()));
        // A force left on, then the device destroyed (an exception unwinding
        // the command, say): the destructor zeroes it.
        DeviceState st;
        dev.read(0.0, st);
        ASSERT_TRUE(dev.writeForce(Vec3(0.0, 2.0, 0.0)));
        ASSERT_FALSE(zero(fake.commands().back()));
    }
    EXPECT_TRUE(zero(fake.commands().back()));
}

TEST(FalconDevice, NonFiniteForceSendsZero) {
    Rig rig(running());
    DeviceState st;
    ASSERT_EQ(rig.dev.read(0.0, st), ReadStatus::kOk);
    ASSERT_TRUE(st.homed);
    EXPECT_FALSE(rig.dev.writeForce(Vec3(NAN, 1.0, 0.0)));
    EXPECT_TRUE(zero(rig.fake.commands().back()));
}

TEST(FalconDevice, ClampsTheForceToTheDeviceLimit) {
    Rig rig(running());
    DeviceState st;
    ASSERT_EQ(rig.dev.read(0.0, st), ReadStatus::kOk);
    ASSERT_TRUE(rig.dev.writeForce(Vec3(0.0, 50.0, 0.0)));
    ASSERT_EQ(rig.dev.read(0.001, st), ReadStatus::kOk);
    ASSERT_TRUE(rig.dev.writeForce(Vec3(0.0)));
    const Vec3 felt = rig.fake.forces()[rig.fake.forces().size() - 2];
    EXPECT_NEAR(felt.y, rig.dev.limits().max_force_N, 0.05);
    EXPECT_NEAR(std::hypot(felt.x, felt.z), 0.0, 0.05);
}

TEST(FalconDevice, LedsShowHomingContactAndVolume) {
    Rig rig(running(20));
    DeviceState st;
    auto tick = [&](bool contact, bool volume) {
        rig.dev.read(0.0, st);
        rig.dev.showStatus(contact, volume);
        rig.dev.writeForce(Vec3(0.0));
        return uint8_t(rig.fake.commands().back().status & ~kFalconHoming);
    };
    EXPECT_EQ(tick(false, false), kFalconLedRed);
    for (int k = 0; k < 30; ++k) tick(false, false);
    ASSERT_TRUE(rig.dev.homed());
    EXPECT_EQ(tick(false, false), kFalconLedGreen);
    EXPECT_EQ(tick(true, false), kFalconLedBlue);
    EXPECT_EQ(tick(true, true), kFalconLedGreen | kFalconLedBlue);
}

TEST(FalconDevice, EachTickReportsThePositionOfTheNewestReply) {
    // The grip jumps 4 mm sideways on every packet (on odd packets it is
    // at +4 mm), so a position one packet old is 4 mm off: each reading
    // must be the pose the newest reply carried.
    FakeFalconConfig cfg = running(0);
    cfg.pose = [](double t) {
        const long packet = std::lround(t / 0.001);
        return Vec3(packet % 2 ? 0.004 : 0.0, -0.005, 0.002);
    };
    Rig rig(cfg);
    class Checker final : public TickHandler {
    public:
        explicit Checker(const FakeFalcon& f) : fake(f) {}
        const FakeFalcon& fake;
        double worst_m = 0.0;
        int ticks = 0;
        Vec3 tick(const DeviceState& s, double, LogRecord&) noexcept override {
            const Vec3 newest = fake.replyPositions().back();
            worst_m = std::max(worst_m, glm::length(s.position_m - newest));
            ++ticks;
            return Vec3(0.0);
        }
    } checker(rig.fake);
    FakeLoopClock clock;
    LoopOptions lo;
    lo.duration_s = 0.5;
    std::atomic<bool> never{false};
    LoopStats stats;
    runHapticLoop(rig.dev, checker, clock, lo, never, nullptr, stats);
    EXPECT_GT(checker.ticks, 400);
    EXPECT_LT(checker.worst_m, 2.0 * kFalconMetresPerCount);  // the encoders' resolution, not a packet's lag
}

TEST(FalconDevice, HomingBitInEveryPacketKeepsTheDeviceHomed) {
    // The fake un-homes on a packet without the homing bit (libnifalcon
    // sets it in every packet): a whole session, forces and LEDs included,
    // must keep it.
    FakeFalconConfig cfg = running(50);
    cfg.pose = circle;
    Rig rig(cfg);
    Session s;
    s.handler.anchor = Vec3(0.0, 0.01, 0.0);
    run(rig.dev, s, 1.0);
    EXPECT_TRUE(rig.fake.homed());
    for (const FalconCommand& c : rig.fake.commands()) ASSERT_TRUE(c.status & kFalconHoming);
    EXPECT_GT(rig.dev.stats().ticks_homed, 900u);
}

TEST(FalconDevice, APauseHoldsZeroAndTheForceRampsInAgain) {
    FakeFalconConfig cfg = running(0);
    cfg.pose = circle;
    Rig rig(cfg);
    Session s;
    s.handler.anchor = Vec3(0.0, 0.03, 0.0);  // a steady pull of about 4 N
    static std::atomic<bool> pause{false};
    static size_t commands_at_pause = 0;
    static FakeFalcon* fake = nullptr;
    fake = &rig.fake;
    pause.store(false);
    struct Pauser {
        static void paused() noexcept {
            pause.store(false);
            commands_at_pause = fake->commands().size();
        }
    };
    class PauseAt final : public TickHandler {
    public:
        SpringHandler& inner;
        explicit PauseAt(SpringHandler& h) : inner(h) {}
        Vec3 tick(const DeviceState& st, double gain, LogRecord& r) noexcept override {
            if (st.t_s > 1.5 && st.t_s < 1.5015) pause.store(true);
            return inner.tick(st, gain, r);
        }
    } handler(s.handler);
    FakeLoopClock clock;
    LoopOptions lo;
    lo.duration_s = 3.0;
    lo.start_ramp_s = 0.2;
    lo.pause_requested = &pause;
    lo.pause = &Pauser::paused;
    std::atomic<bool> never{false};
    runHapticLoop(rig.dev, handler, clock, lo, never, nullptr, s.stats);
    EXPECT_EQ(s.stats.pauses, 1u);
    ASSERT_GT(commands_at_pause, 1500u);
    const auto& cmds = rig.fake.commands();
    const auto& forces = rig.fake.forces();
    // What the device held when the process stopped: zero.
    EXPECT_TRUE(zero(cmds[commands_at_pause - 1]));
    // Full force before the pause; after it, the force starts again from
    // nothing and ramps back up over start_ramp_s (0.2 s).
    const double before = glm::length(forces[commands_at_pause - 200]);
    EXPECT_GT(before, 2.0);
    EXPECT_LT(glm::length(forces[commands_at_pause + 5]), 0.05 * before);
    EXPECT_LT(glm::length(forces[commands_at_pause + 60]), 0.5 * before);
    EXPECT_GT(glm::length(forces[commands_at_pause + 400]), 0.9 * before);
}
