// Direct mesher throughput: "N cells -> M triangles in X ms".
//   build/bench/tsf_bench --benchmark_filter=Mesh
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"

namespace {

// plateaus: the wave clipped to [0.47, 1.57] and quantised to 256 levels,
// like an 8-bit raster with flat regions (about 40 % of the cells).
tsf::HexField wavyField(int n, bool plateaus = false) {
    tsf::HexField f;
    f.grid = {n, n};
    f.values.resize(size_t(n) * n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            double v = std::sin(c * 0.05) * std::cos(r * 0.03) + 1.0;
            if (plateaus) v = std::round(std::clamp(v, 0.47, 1.57) * 127.5);
            f.values[size_t(r) * n + c] = v;
        }
    return f;
}

tsf::SceneParams params(bool mirrored) {
    tsf::SceneParams p;
    p.fit_width_mm = 200;
    p.fit_depth_mm = 200;
    p.cull = tsf::Cull::None;
    p.bottom = mirrored ? tsf::Bottom::Mirrored : tsf::Bottom::Flat;
    return p;
}

void BM_BuildScene(benchmark::State& state) {
    const tsf::HexField f = wavyField(int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(tsf::buildScene(f, params(false)));
    state.counters["cells/s"] = benchmark::Counter(double(f.values.size()), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_MeshScene(benchmark::State& state) {
    const tsf::Scene s = tsf::buildScene(wavyField(int(state.range(0)), state.range(2) != 0), params(state.range(1) != 0));
    size_t triangles = 0;
    for (auto _ : state) {
        tsf::Mesh m = tsf::meshScene(s);
        triangles = m.triangleCount();
        benchmark::DoNotOptimize(m);
    }
    state.counters["cells/s"] = benchmark::Counter(double(s.keptCount()), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["triangles/s"] = benchmark::Counter(double(triangles), benchmark::Counter::kIsIterationInvariantRate);
    state.counters["triangles"] = double(triangles);
}

}  // namespace

BENCHMARK(BM_BuildScene)->Arg(100)->Arg(1000)->Unit(benchmark::kMillisecond);
// Args: grid size, mirrored, plateaus. The mesher runs on every core above
// 20 000 cells: real time and the CPU time of the whole process.
BENCHMARK(BM_MeshScene)
    ->Args({100, 0, 0})
    ->Args({100, 1, 0})
    ->Args({1000, 0, 0})
    ->Args({1000, 1, 0})
    ->Args({1000, 0, 1})
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Unit(benchmark::kMillisecond);
