// The one test that needs a real Novint Falcon: skipped (and reported as
// skipped) when none is plugged in. It opens the device (loading firmware
// from $TSF_FALCON_FIRMWARE if none runs) and runs the 1 kHz loop for 2 s
// commanding zero force only, so it is safe with a hand on the grip or
// without one; it checks that the link keeps up.
#include <atomic>
#include <cstdlib>

#include <gtest/gtest.h>

#include "haptics/falcon/falcon_device.h"
#include "haptics/falcon/libusb_transport.h"
#include "haptics/haptic_loop.h"

using namespace tsf::haptics;

namespace {

class ZeroForce final : public TickHandler {
public:
    Vec3 tick(const DeviceState&, double, LogRecord&) noexcept override { return Vec3(0.0); }
};

}  // namespace

TEST(FalconHardware, TheLinkKeepsUpWithTheLoop) {
    if (countFalconsOnUsb() == 0) GTEST_SKIP() << "no Novint Falcon on USB (0403:cb48)";
    FalconOptions o;
    if (const char* fw = std::getenv("TSF_FALCON_FIRMWARE")) o.firmware = readFalconFirmware(fw);
    FalconDevice dev(openFalconUsb, o);
    dev.open();
    ZeroForce handler;
    SteadyLoopClock clock(100e-6);
    LoopOptions lo;
    lo.duration_s = 2.0;
    std::atomic<bool> stop{false};
    LoopStats stats;
    runHapticLoopThread(dev, handler, clock, lo, stop, nullptr, stats, true);
    dev.close();
    EXPECT_EQ(stats.end, LoopEnd::kDuration) << dev.failureReason();
    const FalconLinkStats& ls = dev.stats();
    const double frames_per_s = double(ls.frames_received) / stats.elapsed_s;
    RecordProperty("loop_rate_Hz", std::to_string(stats.rate_Hz));
    RecordProperty("frames_per_s", std::to_string(frames_per_s));
    std::printf("[ falcon   ] loop %.1f Hz, %.1f frames/s, %llu ticks without a frame, %llu overruns\n", stats.rate_Hz,
                frames_per_s, (unsigned long long)ls.ticks_without_frame, (unsigned long long)stats.overruns);
    EXPECT_GT(frames_per_s, 400.0);  // at least every other tick
}
