// Haptics costs: per-step sampling and force cost, scale-space precompute and
// its error against the exact Gaussian scale space, and loop timing on this
// machine. Results and the commands that produced them: docs/haptics.md.
//
//   build/bench/tsf_bench --benchmark_filter='Haptics'
#include <atomic>
#include <cmath>
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include "haptics/feel_renderer.h"
#include "haptics/field_mapping.h"
#include "haptics/force_model.h"
#include "haptics/haptic_loop.h"
#include "haptics/height_sampling.h"
#include "haptics/loop_clock.h"
#include "haptics/scale_space.h"

using namespace tsf::haptics;

namespace {

/// A smooth random field (sum of bumps) of n x n cells, values in [0, 1].
HeightGrid terrain(int n, unsigned seed = 1) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    struct Bump {
        double x, y, r, a;
    };
    std::vector<Bump> bumps;
    for (int k = 0; k < 24; ++k) bumps.push_back({u(rng) * n, u(rng) * n, (0.03 + 0.12 * u(rng)) * n, u(rng)});
    std::vector<float> h(size_t(n) * size_t(n));
    double hi = 0.0;
    std::vector<double> v(h.size());
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            double s = 0.0;
            for (const Bump& b : bumps) s += b.a * std::exp(-((i - b.x) * (i - b.x) + (j - b.y) * (j - b.y)) / (2 * b.r * b.r));
            v[size_t(j) * n + i] = s;
            hi = std::max(hi, s);
        }
    for (size_t k = 0; k < h.size(); ++k) h[k] = float(v[k] / hi);
    return makeHeightGrid(n, n, h);
}

void BM_HapticsSample(benchmark::State& state) {
    const HeightGrid g = terrain(256);
    const Interpolation interp = state.range(0) ? Interpolation::kBicubic : Interpolation::kBilinear;
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(0.0, 255.0);
    std::vector<double> pts(4096);
    for (double& p : pts) p = u(rng);
    size_t k = 0;
    for (auto _ : state) {
        const HeightSample s = sampleHeight(g, pts[k & 4095], pts[(k + 1) & 4095], interp);
        benchmark::DoNotOptimize(s);
        ++k;
    }
    state.SetLabel(interp == Interpolation::kBicubic ? "bicubic" : "bilinear");
}
BENCHMARK(BM_HapticsSample)->Arg(0)->Arg(1);

/// One computeForce call with the probe sliding in contact (the common case).
void BM_HapticsForceStep(benchmark::State& state) {
    const HeightGrid g = terrain(128);
    const ScaleSpace space = buildScaleSpace(g, 4, ScaleSpaceKind::kGaussian);
    const DeviceLimits limits;
    const FieldMapping m = mapFieldToWorkspace(g.cols, g.rows, limits.workspace);
    ForceParams p;
    p.sampling.interpolation = state.range(0) ? Interpolation::kBicubic : Interpolation::kBilinear;
    const bool volume = state.range(1) != 0;
    const ForceModel model = makeForceModel(space, m, p, limits, 1000.0);
    ForceState st;
    double t = 0.0;
    for (auto _ : state) {
        const double a = t * 0.7;
        Vec3 pos = gridToDevice(m, 64 + 40 * std::cos(a), 64 + 40 * std::sin(a), 0.0);
        const SurfacePoint s = surfaceAt(model, pos, 0.0);
        pos.y = volume ? 0.5 * (m.volume_bottom_y_m + m.volume_top_y_m) : s.height_y_m - 0.0015;
        ForceInput in;
        in.t_s = t;
        in.position_m = pos;
        in.velocity_m_per_s = Vec3(0.02, 0.0, 0.0);
        in.volume = volume;
        const ForceOutput out = computeForce(model, st, in);
        st = out.state;
        benchmark::DoNotOptimize(out.force_N);
        t += 0.001;
    }
    state.SetLabel(std::string(p.sampling.interpolation == Interpolation::kBicubic ? "bicubic" : "bilinear") +
                   (volume ? ", volume" : ", surface contact"));
}
BENCHMARK(BM_HapticsForceStep)->Args({0, 0})->Args({1, 0})->Args({0, 1})->Args({1, 1});

/// Precompute of `levels` levels for an n x n field.
void BM_HapticsScaleSpaceBuild(benchmark::State& state) {
    const int n = int(state.range(0));
    const ScaleSpaceKind kind = state.range(1) ? ScaleSpaceKind::kGaussian : ScaleSpaceKind::kMipmap;
    const HeightGrid g = terrain(n);
    for (auto _ : state) benchmark::DoNotOptimize(buildScaleSpace(g, 5, kind));
    state.SetLabel(std::string(kind == ScaleSpaceKind::kGaussian ? "gaussian" : "mipmap") + ", 5 levels, " +
                   std::to_string(n) + "x" + std::to_string(n));
}
BENCHMARK(BM_HapticsScaleSpaceBuild)
    ->Args({128, 0})->Args({128, 1})->Args({512, 0})->Args({512, 1})
    ->Unit(benchmark::kMillisecond);

/// Error of mipmap level n and of the cascaded Gaussian level n against the
/// exact scale space at t = 4^n (direct convolution from the base with the
/// kernel cut at 8 sigma), over base cell centres at least 4 sigma from the
/// border; heights in [0, 1]. mipmap_* is mipmap level n (the thesis's
/// stand-in for level n), mip_next_* is mipmap level n + 1. Reported as counters; the timing is the error
/// computation and means nothing.
void BM_HapticsScaleSpaceError(benchmark::State& state) {
    const int level = int(state.range(0));
    const int n = 256;
    const HeightGrid g = terrain(n, 7);
    const ScaleSpace mip = buildScaleSpace(g, level + 2, ScaleSpaceKind::kMipmap);
    const ScaleSpace gau = buildScaleSpace(g, level + 1, ScaleSpaceKind::kGaussian);
    const double t = gaussianLevelVariance(level);
    const HeightGrid exact = gaussianBlur(g, t, 8.0);
    const int margin = int(std::ceil(4.0 * std::sqrt(t)));
    const SamplingParams lin{Interpolation::kBilinear, false, 0.5};
    double mip_max = 0, mip_sq = 0, gau_max = 0, gau_sq = 0, next_max = 0, next_sq = 0;
    size_t count = 0;
    for (auto _ : state) {
        mip_max = mip_sq = gau_max = gau_sq = next_max = next_sq = 0;
        count = 0;
        for (int j = margin; j < n - margin; ++j)
            for (int i = margin; i < n - margin; ++i) {
                const double e = exact.at(i, j);
                const double a = sampleLevel(mip, level, i, j, lin).height - e;
                const double b = gau.levels[size_t(level)].grid.at(i, j) - e;
                // Mipmap level n + 1 (a 2^(n+1) box, then bilinear: variance
                // about 4^n) is the one whose blur matches t = 4^n.
                const double c = sampleLevel(mip, level + 1, i, j, lin).height - e;
                next_max = std::max(next_max, std::abs(c));
                next_sq += c * c;
                mip_max = std::max(mip_max, std::abs(a));
                gau_max = std::max(gau_max, std::abs(b));
                mip_sq += a * a;
                gau_sq += b * b;
                ++count;
            }
    }
    state.counters["mipmap_max"] = mip_max;
    state.counters["mipmap_rms"] = std::sqrt(mip_sq / double(count));
    state.counters["mip_next_max"] = next_max;
    state.counters["mip_next_rms"] = std::sqrt(next_sq / double(count));
    state.counters["gauss_max"] = gau_max;
    state.counters["gauss_rms"] = std::sqrt(gau_sq / double(count));
    state.SetLabel("level " + std::to_string(level) + " (t = " + std::to_string(int(t)) + ")");
}
BENCHMARK(BM_HapticsScaleSpaceError)->DenseRange(1, 4)->Iterations(1)->Unit(benchmark::kMillisecond);

/// A device that stands still and accepts every force: the loop's own cost.
class StillDevice final : public HapticDevice {
public:
    std::string name() const override { return "still"; }
    DeviceLimits limits() const override { return {}; }
    bool needsRealtime() const override { return true; }
    void open() override {}
    void close() noexcept override {}
    ReadStatus read(double t, DeviceState& out) noexcept override {
        out.t_s = t;
        out.position_m = Vec3(0.0, 0.001 * std::sin(t), 0.0);
        return ReadStatus::kOk;
    }
    bool writeForce(const Vec3&) noexcept override { return true; }
};

/// Two seconds of the real loop at 1 kHz on the steady clock with the real
/// force model; lateness (wake-up minus deadline) as counters, in us.
/// Arg 0: sleep only; arg > 0: spin that many us before each deadline.
void BM_HapticsLoopJitter(benchmark::State& state) {
    const HeightGrid g = terrain(128);
    const ScaleSpace space = buildScaleSpace(g, 4, ScaleSpaceKind::kGaussian);
    const DeviceLimits limits;
    const FieldMapping m = mapFieldToWorkspace(g.cols, g.rows, limits.workspace);
    const ForceModel model = makeForceModel(space, m, ForceParams{}, limits, 1000.0);
    LoopStats stats;
    for (auto _ : state) {
        FeelRenderer renderer(model);
        StillDevice dev;
        SteadyLoopClock clock(double(state.range(0)) * 1e-6);
        LoopOptions o;
        o.duration_s = 2.0;
        std::atomic<bool> stop{false};
        stats = LoopStats{};
        runHapticLoopThread(dev, renderer, clock, o, stop, nullptr, stats, true);
    }
    state.counters["rate_Hz"] = stats.rate_Hz;
    state.counters["late_p50_us"] = stats.lateness.quantile_us(0.5);
    state.counters["late_p99_us"] = stats.lateness.quantile_us(0.99);
    state.counters["late_max_us"] = stats.lateness.max_us();
    state.counters["overruns"] = double(stats.overruns);
    state.counters["tick_p99_us"] = stats.compute.quantile_us(0.99);
    state.SetLabel(state.range(0) ? "sleep + spin " + std::to_string(state.range(0)) + " us" : "sleep");
}
BENCHMARK(BM_HapticsLoopJitter)->Arg(0)->Arg(100)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace
