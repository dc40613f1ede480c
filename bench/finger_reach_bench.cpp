// The fingertip's reach (verify/finger_reach.h, tactile_finger_reach) on the
// sampled top of a generated model: the ball's closing for the adult's and
// the child's fingertip, then the places left unreached.
//   build/bench/tsf_bench --benchmark_filter=FingerReach
// Models: an n x n field of smooth bumps with a little noise, flat bottom,
// 150 mm, one pillar per value; the top sampled every 0.5 mm as tsf verify
// does (coarser above a million samples).
#include <benchmark/benchmark.h>

#include <cmath>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "verify/finger_reach.h"
#include "verify/tactile.h"

namespace {

tsf::Mesh bumps(int n) {
    tsf::HexField f;
    f.grid = {n, n};
    f.values.resize(size_t(n) * size_t(n));
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c)
            f.values[size_t(r) * size_t(n) + size_t(c)] =
                std::sin(c * 0.21) * std::cos(r * 0.17) + 0.05 * std::sin(c * r * 1.3) + 1.2;
    tsf::SceneParams p;
    p.fit_width_mm = 150;
    p.fit_depth_mm = 150;
    p.cull = tsf::Cull::None;
    return tsf::meshScene(tsf::buildScene(f, p));
}

void BM_FingerReach(benchmark::State& state) {
    const tsf::Mesh mesh = bumps(int(state.range(0)));
    const tsf::TopHeightField top = tsf::sampledTop(mesh, 0.5, tsf::kAdultFingertipRadiusMm);
    const double table = tsf::meshBounds(mesh).min.z;
    for (auto _ : state)
        benchmark::DoNotOptimize(
            tsf::fingerReach(top, table, {tsf::kAdultFingertipRadiusMm, tsf::kChildFingertipRadiusMm}));
    state.counters["samples"] = double(top.z.size());
}

void BM_BallClosing(benchmark::State& state) {
    const tsf::Mesh mesh = bumps(int(state.range(0)));
    const tsf::TopHeightField top = tsf::sampledTop(mesh, 0.5, tsf::kAdultFingertipRadiusMm);
    const double table = tsf::meshBounds(mesh).min.z;
    for (auto _ : state) benchmark::DoNotOptimize(tsf::closedByBall(top, tsf::kAdultFingertipRadiusMm, table));
    state.counters["samples"] = double(top.z.size());
}

}  // namespace

BENCHMARK(BM_FingerReach)->Arg(100)->Arg(300)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
BENCHMARK(BM_BallClosing)->Arg(100)->Unit(benchmark::kMillisecond)->MeasureProcessCPUTime();
