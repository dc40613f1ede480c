// OpenSCAD strategies (desktop OpenSCAD): strategy x grid size -> render
// time, peak memory, triangles, and whether the STL is the direct mesher's
// solid. The table in docs/openscad.md comes from this benchmark.
//
//   build/bench/tsf_bench --benchmark_filter=ScadStrategy
//   TSF_BENCH_SCAD_MAX_SIDE=200 TSF_BENCH_SCAD_TIMEOUT_S=1800 build/bench/tsf_bench --benchmark_filter=ScadStrategy
//
// Benchmarks are ScadStrategy/<side>/<strategy>/<bottom> for a side x side
// grid of a hilly field (every cell kept, 4 mm pitch, 20 mm relief on a
// 2 mm base); sides 10, 20, 40, 100, 160, 200, only those up to
// TSF_BENCH_SCAD_MAX_SIDE (default 10: a default run takes seconds). The CSG
// strategy is registered up to side 100 (10 000 prisms; CGAL takes the better
// part of an hour). One render per benchmark, the time is openscad's wall
// time; a render stopped at TSF_BENCH_SCAD_TIMEOUT_S (default 1800) is
// reported as an error.
//
// Counters: peak_MB (openscad's peak resident memory), triangles (of the
// exported STL), same_solid: 1 when the STL is closed, manifold and
// outward, its volume equals the direct mesher's within 1e-6 (relative), and
// every kept cell's top and bottom read back at its height (verify/readback.h).
// Each run also prints "N cells -> M triangles in X s" and a Markdown table row
// to stderr.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "gen/mesh/direct_mesher.h"
#include "gen/mesh_io/mesh_reader.h"
#include "runners/openscad/openscad_runner.h"
#include "gen/scad/scad_emitter.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "verify/mesh_topology.h"
#include "verify/column_grid.h"
#include "verify/readback.h"

namespace {

namespace fs = std::filesystem;

// The task's bar for "the same solid" from two float32 STLs.
constexpr double kVolumeRelTolerance = 1e-6;

double envNumber(const char* name, double fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::atof(v) : fallback;
}

// Hills with a ripple: neighbouring pillars differ, as in real data.
tsf::HexField hillyField(int side) {
    tsf::HexField f;
    f.grid = {side, side};
    f.values.resize(size_t(side) * size_t(side));
    for (int r = 0; r < side; ++r)
        for (int c = 0; c < side; ++c)
            f.values[size_t(r) * size_t(side) + size_t(c)] =
                2.0 + std::sin(c * 0.31) * std::cos(r * 0.27) + 0.25 * std::sin(c * 1.7 + r * 2.3);
    f.source = "bench";
    return f;
}

void benchStrategy(benchmark::State& state, int side, tsf::ScadOptions::Strategy strategy, tsf::Bottom bottom) {
    std::unique_ptr<tsf::ScadEngine> engine;
    try {
        engine = tsf::makeOpenScadEngine();
    } catch (const tsf::ScadEngineMissing& e) {
        state.SkipWithError(e.what());
        return;
    }
    tsf::SceneParams params;
    params.pitch_mm = 4.0;
    params.max_height_mm = 20.0;
    params.base_mm = 2.0;
    params.cull = tsf::Cull::None;
    params.bottom = bottom;
    const tsf::Scene scene = tsf::buildScene(hillyField(side), params);
    tsf::ScadOptions opts;
    opts.strategy = strategy;
    const std::string name = std::to_string(side) + "-" + tsf::toString(strategy) + "-" + tsf::toString(bottom);
    const fs::path dir = fs::temp_directory_path() / "tsf-scad-bench";
    fs::create_directories(dir);
    const std::string scad = (dir / (name + ".scad")).string();
    tsf::writeScad(scene, opts, scad);

    tsf::ScadRenderRequest rq;
    rq.scad_path = scad;
    rq.output_path = (dir / (name + ".stl")).string();
    rq.timeout_s = envNumber("TSF_BENCH_SCAD_TIMEOUT_S", 1800);
    tsf::ScadRenderResult result;
    for (auto _ : state) {
        result = tsf::renderScad(*engine, rq);
        state.SetIterationTime(result.elapsed_s);
    }
    size_t triangles = 0;
    bool same_solid = false;
    std::string verdict = result.summary;
    if (result.ok()) {
        const tsf::Mesh mesh = tsf::readMesh(rq.output_path);
        triangles = mesh.triangleCount();
        const double v = tsf::signedVolume(mesh), v_direct = tsf::signedVolume(tsf::meshScene(scene));
        const tsf::ColumnGrid caster(mesh);
        const tsf::ReadbackResult rb = tsf::readBack(mesh, scene, caster, {});
        const bool solid = tsf::analyzeTopology(mesh).isClosedOrientedManifold();
        const bool volume = std::fabs(v - v_direct) <= kVolumeRelTolerance * v_direct;
        const bool heights = rb.figures.over_tolerance == 0 && rb.figures.missed == 0;
        same_solid = solid && volume && heights;
        verdict = !solid ? "not a closed solid" : !volume ? "volume differs" : !heights ? "heights differ" : "";
    }
    state.counters["peak_MB"] = double(result.peak_memory_kb) / 1024.0;
    state.counters["triangles"] = double(triangles);
    state.counters["same_solid"] = same_solid ? 1 : 0;
    const size_t cells = scene.keptCount();
    std::fprintf(stderr, "%zu cells -> %zu triangles in %.2f s (%s, %s)\n", cells, triangles, result.elapsed_s,
                 tsf::toString(strategy), tsf::toString(bottom));
    std::fprintf(stderr, "| %d^2 = %zu | %s | %s | %s%.2f s | %.0f MB | %zu | %s |\n", side, cells, tsf::toString(strategy),
                 tsf::toString(bottom), result.status == tsf::ScadRenderResult::Status::TimedOut ? "> " : "",
                 result.elapsed_s, double(result.peak_memory_kb) / 1024.0, triangles,
                 same_solid ? "y" : ("n (" + verdict + ")").c_str());
    if (!result.ok()) state.SkipWithError(result.summary.c_str());
}

bool registerScadBenchmarks() {
    using Strategy = tsf::ScadOptions::Strategy;
    const int max_side = int(envNumber("TSF_BENCH_SCAD_MAX_SIDE", 10));
    constexpr int kCsgMaxSide = 100;
    for (int side : {10, 20, 40, 100, 160, 200}) {
        if (side > max_side) continue;
        for (Strategy strategy : {Strategy::Polyhedron, Strategy::Csg}) {
            if (strategy == Strategy::Csg && side > kCsgMaxSide) continue;
            for (tsf::Bottom bottom : {tsf::Bottom::Flat, tsf::Bottom::Mirrored}) {
                const std::string name = "ScadStrategy/" + std::to_string(side) + "/" + tsf::toString(strategy) + "/" +
                                         tsf::toString(bottom);
                benchmark::RegisterBenchmark(name.c_str(), [=](benchmark::State& st) {
                    benchStrategy(st, side, strategy, bottom);
                })->Iterations(1)->UseManualTime()->Unit(benchmark::kSecond);
            }
        }
    }
    return true;
}

const bool kRegistered = registerScadBenchmarks();

}  // namespace
