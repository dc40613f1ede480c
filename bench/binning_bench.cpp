// Point binning throughput: N random points (uniform over a lon/lat-like box)
// into a 200-column hexagon grid, count per hexagon.
//   build/bench/tsf_bench --benchmark_filter=BinPoints
#include <benchmark/benchmark.h>

#include <random>

#include "gen/readers/point_binning.h"

namespace {

tsf::PointTable randomPoints(size_t n) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> d(-180.0, 180.0);
    tsf::PointTable t;
    t.x.resize(n);
    t.y.resize(n);
    for (size_t k = 0; k < n; ++k) {
        t.x[k] = d(rng);
        t.y[k] = d(rng) * 0.5;
    }
    t.source = "random points";
    t.x_name = "x";
    t.y_name = "y";
    return t;
}

void BM_BinPoints(benchmark::State& state) {
    const tsf::PointTable pts = randomPoints(size_t(state.range(0)));
    tsf::BinOptions opts;
    opts.hex_cols = 200;
    for (auto _ : state) benchmark::DoNotOptimize(tsf::binPoints(pts, opts));
    state.counters["points/s"] = benchmark::Counter(double(pts.x.size()), benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(BM_BinPoints)->Arg(100'000)->Arg(1'000'000)->Unit(benchmark::kMillisecond);
