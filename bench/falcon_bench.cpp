// Falcon driver costs: the kinematics solve (warm and cold), force -> motor
// commands, frame parsing, one device tick over an in-memory transport, and
// the 1 kHz loop with the driver in it on the real clock. Plus the startup
// cost of the printed relief tsf feel renders. Results: docs/benchmarks.md.
//
//   build/bench/tsf_bench --benchmark_filter='Falcon|FeelRelief'
#include <atomic>
#include <cmath>
#include <cstring>
#include <deque>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "gen/readers/load_field.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "haptics/falcon/falcon_device.h"
#include "haptics/falcon/falcon_kinematics.h"
#include "haptics/falcon/falcon_packet.h"
#include "haptics/feel_renderer.h"
#include "haptics/haptic_loop.h"
#include "haptics/printed_relief.h"
#include "haptics/scale_space.h"

using namespace tsf::haptics;

namespace {

/// The probe on a 15 mm circle at 30 mm/s, sampled at 1 kHz.
Vec3 circle(double t) { return {0.015 * std::cos(2.0 * t), -0.005, 0.015 * std::sin(2.0 * t)}; }

void BM_FalconForwardKinematics(benchmark::State& state) {
    const bool warm = state.range(0) != 0;
    std::vector<FalconAngles> angles(1000);
    std::vector<Vec3> truth(1000);
    for (size_t k = 0; k < angles.size(); ++k) {
        truth[k] = circle(double(k) * 1e-3);
        falconInverseKinematics(truth[k], angles[k]);
    }
    size_t k = 0;
    double iterations = 0.0, calls = 0.0, worst = 0.0;
    Vec3 previous = truth.back();
    for (auto _ : state) {
        const size_t i = k++ % angles.size();
        const FalconFkResult r = falconForwardKinematics(angles[i], warm ? previous : Vec3(0.0));
        previous = r.position_m;
        iterations += r.iterations;
        calls += 1.0;
        worst = std::max(worst, glm::length(r.position_m - truth[i]));
        benchmark::DoNotOptimize(r);
    }
    state.counters["iterations"] = iterations / calls;
    state.counters["worst_error_um"] = worst * 1e6;
    state.SetLabel(warm ? "warm start (previous tick)" : "cold start (centre)");
}
BENCHMARK(BM_FalconForwardKinematics)->Arg(1)->Arg(0);

void BM_FalconMotorCommands(benchmark::State& state) {
    FalconAngles t;
    const Vec3 p(0.01, -0.01, 0.02);
    falconInverseKinematics(p, t);
    const Vec3 f(0.5, 3.0, -1.0);
    for (auto _ : state) benchmark::DoNotOptimize(falconMotorCommands(p, t, f));
}
BENCHMARK(BM_FalconMotorCommands);

void BM_FalconFrameParser(benchmark::State& state) {
    FalconReport r;
    r.encoder = {100, -200, 300};
    r.homed_mask = kFalconAllHomed;
    const FalconPacket frame = encodeFalconReport(r);
    FalconFrameParser parser;
    FalconReport out;
    for (auto _ : state) {
        parser.push(frame);
        benchmark::DoNotOptimize(parser.next(out));
    }
}
BENCHMARK(BM_FalconFrameParser);

/// A Falcon answering at once from memory: every 16-byte command gets one
/// frame of the circle pose. Measures the driver, not USB.
class LoopbackFalcon final : public UsbTransport {
public:
    UsbResult control(uint8_t, uint16_t, uint16_t, int) noexcept override { return {}; }
    UsbResult bulkWrite(std::span<const uint8_t> data, int) noexcept override {
        if (data.size() == kFalconPacketBytes && data[0] == '<') {
            FalconAngles a;
            FalconReport r;
            if (falconInverseKinematics(circle(double(packets_++) * 1e-3), a))
                for (size_t i = 0; i < 3; ++i) r.encoder[i] = int16_t(std::lround(falconAngleToEncoder(a[i])));
            r.homed_mask = kFalconAllHomed;
            pending_ = encodeFalconReport(r);
            has_ = true;
        }
        return {UsbStatus::kOk, data.size()};
    }
    UsbResult bulkRead(std::span<uint8_t> buffer, int) noexcept override {
        buffer[0] = 0x31;
        buffer[1] = 0x60;
        if (!has_) return {UsbStatus::kOk, 2};
        std::memcpy(buffer.data() + 2, pending_.data(), pending_.size());
        has_ = false;
        return {UsbStatus::kOk, 2 + pending_.size()};
    }

private:
    FalconPacket pending_{};
    bool has_ = false;
    uint64_t packets_ = 0;
};

UsbOpener loopback() {
    return [] { return std::make_unique<LoopbackFalcon>(); };
}

void BM_FalconDeviceTick(benchmark::State& state) {
    FalconDevice dev(loopback(), {});
    dev.open();
    DeviceState s;
    double t = 0.0;
    for (auto _ : state) {
        dev.read(t, s);
        dev.writeForce(Vec3(0.0, 1.5, 0.2));
        t += 1e-3;
    }
    state.counters["frames"] = double(dev.stats().frames_received);
}
BENCHMARK(BM_FalconDeviceTick);

/// Two seconds of `tsf feel --device falcon`'s loop on the steady clock
/// (sleep + 100 us spin, SCHED_FIFO when granted): the real renderer and
/// force model on the volcano, the driver over the in-memory Falcon. The
/// achieved rate and late ticks as counters.
void BM_FalconLoopRealTime(benchmark::State& state) {
    tsf::FieldLoadOptions in;
    in.input = std::string(TSF_SOURCE_DIR) + "/examples/volcano.csv";
    const tsf::Scene scene = tsf::buildScene(tsf::loadField(in), tsf::SceneParams{});
    ReliefInfo info;
    const HeightGrid grid = printedRelief(scene, &info);
    const ScaleSpace space = buildScaleSpace(grid, 4, ScaleSpaceKind::kGaussian, info.samples_per_pitch);
    const DeviceLimits limits;
    const FieldMapping m = mapFieldToWorkspace(grid.cols, grid.rows, limits.workspace);
    const ForceModel model = makeForceModel(space, m, ForceParams{}, limits, 1000.0);
    LoopStats stats;
    FalconLinkStats link;
    for (auto _ : state) {
        FalconDevice dev(loopback(), {});
        dev.open();
        FeelRenderer renderer(model);
        SteadyLoopClock clock(100e-6);
        LoopOptions o;
        o.duration_s = 2.0;
        std::atomic<bool> stop{false};
        stats = LoopStats{};
        runHapticLoopThread(dev, renderer, clock, o, stop, nullptr, stats, true);
        link = dev.stats();
    }
    state.counters["rate_Hz"] = stats.rate_Hz;
    state.counters["frames_per_s"] = double(link.frames_received) / stats.elapsed_s;
    state.counters["late_p99_us"] = stats.lateness.quantile_us(0.99);
    state.counters["late_max_us"] = stats.lateness.max_us();
    state.counters["overruns"] = double(stats.overruns);
    state.counters["tick_p99_us"] = stats.compute.quantile_us(0.99);
}
BENCHMARK(BM_FalconLoopRealTime)->Iterations(1)->Unit(benchmark::kMillisecond);

/// tsf feel's start-up for the volcano (61 x 101 hexagons): the printed
/// relief grid, then its 4 Gaussian levels.
void BM_FeelReliefVolcano(benchmark::State& state) {
    tsf::FieldLoadOptions in;
    in.input = std::string(TSF_SOURCE_DIR) + "/examples/volcano.csv";
    const tsf::Scene scene = tsf::buildScene(tsf::loadField(in), tsf::SceneParams{});
    const bool levels = state.range(0) != 0;
    ReliefInfo info;
    HeightGrid grid = printedRelief(scene, &info);
    for (auto _ : state) {
        if (levels) benchmark::DoNotOptimize(buildScaleSpace(grid, 4, ScaleSpaceKind::kGaussian, info.samples_per_pitch));
        else benchmark::DoNotOptimize(grid = printedRelief(scene, &info));
    }
    state.counters["samples"] = double(grid.cols) * double(grid.rows);
    state.SetLabel(levels ? "4 Gaussian levels" : "printed relief grid");
}
BENCHMARK(BM_FeelReliefVolcano)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace
