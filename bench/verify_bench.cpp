// Verifier cost per check on generated models: "N cells -> M triangles in X ms".
// CPU time is the whole process's (the tree, the self-intersection test and the
// ray checks run on every core).
//   build/bench/tsf_bench --benchmark_filter=Verify
// Models: an n x n field of smooth bumps with a little noise, so nearly every
// pair of neighbours differs in height (walls everywhere), flat bottom, 150 mm.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "verify/agreement.h"
#include "verify/printability.h"
#include "verify/column_grid.h"
#include "verify/triangle_bvh.h"
#include "verify/readback.h"
#include "verify/solid_checks.h"
#include "verify/verify_model.h"

namespace {

struct Model {
    tsf::Scene scene;
    tsf::Mesh mesh;
};

const Model& model(int n) {
    static std::map<int, std::unique_ptr<Model>> cache;
    auto& slot = cache[n];
    if (!slot) {
        tsf::HexField f;
        f.grid = {n, n};
        f.values.resize(size_t(n) * n);
        for (int r = 0; r < n; ++r)
            for (int c = 0; c < n; ++c)
                f.values[size_t(r) * n + c] = std::sin(c * 0.21) * std::cos(r * 0.17) + 0.05 * std::sin(c * r * 1.3) + 1.2;
        tsf::SceneParams p;
        p.fit_width_mm = 150;
        p.fit_depth_mm = 150;
        p.cull = tsf::Cull::None;
        slot = std::make_unique<Model>();
        slot->scene = tsf::buildScene(f, p);
        slot->mesh = tsf::meshScene(slot->scene);
    }
    return *slot;
}

void label(benchmark::State& state, const Model& m) {
    state.counters["cells"] = double(m.scene.keptCount());
    state.counters["triangles"] = double(m.mesh.triangleCount());
}

void BM_VerifySolid(benchmark::State& state) {
    const Model& m = model(int(state.range(0)));
    tsf::SolidOptions o;
    o.exact = state.range(1) != 0;
    std::map<std::string, double> stage_ms;
    for (auto _ : state) {
        tsf::SolidResult r = tsf::checkSolid(m.mesh, o);
        for (const tsf::Stage& s : r.stages) stage_ms[s.name] += s.time_ms;
        benchmark::DoNotOptimize(r);
    }
    for (const auto& [name, ms] : stage_ms) state.counters[name + "_ms"] = ms / double(state.iterations());
    label(state, m);
}

void BM_VerifyRayTree(benchmark::State& state) {
    const Model& m = model(int(state.range(0)));
    for (auto _ : state) benchmark::DoNotOptimize(std::make_unique<tsf::TriangleBvh>(m.mesh));
    label(state, m);
}

// Arg 1: 0 a grid for any ray, 1 for vertical rays (no walls listed).
tsf::ColumnGrid::Rays gridRays(const benchmark::State& state) {
    return state.range(1) != 0 ? tsf::ColumnGrid::Rays::Vertical : tsf::ColumnGrid::Rays::Any;
}

void BM_VerifyColumnGrid(benchmark::State& state) {
    const Model& m = model(int(state.range(0)));
    for (auto _ : state)
        benchmark::DoNotOptimize(std::make_unique<tsf::ColumnGrid>(m.mesh, tsf::ColumnGrid::kTrianglesPerColumn, gridRays(state)));
    label(state, m);
}

void BM_VerifyReadback(benchmark::State& state) {
    const Model& m = model(int(state.range(0)));
    const tsf::ColumnGrid caster(m.mesh, tsf::ColumnGrid::kTrianglesPerColumn, gridRays(state));
    for (auto _ : state) benchmark::DoNotOptimize(tsf::readBack(m.mesh, m.scene, caster, {}));
    label(state, m);
}

void BM_VerifyPrintability(benchmark::State& state) {
    const Model& m = model(int(state.range(0)));
    const tsf::ColumnGrid caster(m.mesh);
    for (auto _ : state) benchmark::DoNotOptimize(tsf::checkPrintability(m.mesh, true, caster, {}));
    label(state, m);
}

void BM_VerifyAgreement(benchmark::State& state) {
    const Model& m = model(int(state.range(0)));
    // The reference is the same solid with its triangles in reverse order and
    // each triangle starting at another corner, as another writer might list it.
    tsf::Mesh ref = m.mesh;
    std::reverse(ref.triangles.begin(), ref.triangles.end());
    for (auto& t : ref.triangles) std::rotate(t.begin(), t.begin() + 1, t.end());
    for (auto _ : state) benchmark::DoNotOptimize(tsf::compareMeshes(m.mesh, ref, "reversed copy", {}));
    label(state, m);
}

// The whole default run, as `tsf verify model --scene model.scene.json` does after reading.
void BM_VerifyModel(benchmark::State& state) {
    const Model& m = model(int(state.range(0)));
    tsf::VerifyOptions o;
    o.exact = state.range(1) != 0;
    for (auto _ : state) {
        const tsf::VerifyReport r = tsf::verifyModel(m.mesh, &m.scene, o);
        if (!r.passed()) state.SkipWithError("the generated model did not verify");
        benchmark::DoNotOptimize(r);
    }
    label(state, m);
}

}  // namespace

BENCHMARK(BM_VerifySolid)->Args({100, 0})->Args({100, 1})->Args({300, 0})->Args({300, 1})->Args({1000, 0})->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_VerifyRayTree)->Arg(100)->Arg(300)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_VerifyColumnGrid)->Args({100, 0})->Args({100, 1})->Args({300, 0})->Args({300, 1})->Args({1000, 0})->Args({1000, 1})->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_VerifyReadback)->Args({100, 0})->Args({100, 1})->Args({300, 0})->Args({300, 1})->Args({1000, 0})->Args({1000, 1})->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_VerifyPrintability)->Arg(100)->Arg(300)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_VerifyAgreement)->Arg(100)->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
BENCHMARK(BM_VerifyModel)->Args({100, 0})->Args({100, 1})->Args({300, 0})->Unit(benchmark::kMillisecond)->Iterations(1)->MeasureProcessCPUTime();
