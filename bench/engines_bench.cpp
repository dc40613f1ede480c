// OpenSCAD engines: strategy x grid size x engine -> render time, peak
// memory, triangles, and whether the STL is the direct mesher's solid.
//
//   build/bench/tsf_bench --benchmark_filter=Engines
//   TSF_BENCH_ENGINES_MAX_SIDE=160 TSF_BENCH_ENGINES_TIMEOUT_S=900 build/bench/tsf_bench --benchmark_filter=Engines/100
//
// Benchmarks are named Engines/<side>/<strategy>/<engine> for a side x side
// grid (side^2 cells, every cell kept, flat base, 4 mm pitch): sides 10, 20,
// 40, 100, 160; only sides up to TSF_BENCH_ENGINES_MAX_SIDE (default 40) are
// registered (a default run takes several minutes, most of it the
// desktop CGAL union of 1 600 cells). One render per
// benchmark (the time is the engine process's wall time, start-up included);
// a render stopped at TSF_BENCH_ENGINES_TIMEOUT_S (default 600) is reported
// as an error. Counters: peak_MB (the engine process's peak resident
// memory), triangles, same_solid (1 = the engine output check passed against
// the direct mesher's volume AND the verifier passed with the exact kernel:
// closed, manifold, no self-intersections, every cell's height read back). Each run also prints
// one line "N cells -> M triangles in X s" and a Markdown table row to
// stderr for docs/engines.md. A missing engine is a skipped benchmark.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "gen/mesh/direct_mesher.h"
#include "gen/mesh_io/stl_reader.h"
#include "runners/openscad/engine_output_check.h"
#include "gen/scad/scad_emitter.h"
#include "runners/openscad/wasm_engine.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "verify/verify_model.h"

namespace {

namespace fs = std::filesystem;

double envNumber(const char* name, double fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::atof(v) : fallback;
}

// Hills with a fine ripple, so neighbouring pillars differ (the union has real work).
tsf::HexField benchField(int side) {
    tsf::HexField f;
    f.grid = {side, side};
    f.values.resize(size_t(side) * side);
    for (int r = 0; r < side; ++r)
        for (int c = 0; c < side; ++c)
            f.values[size_t(r) * side + c] = 1.0 + std::sin(c * 0.7) * std::cos(r * 0.45) + 0.3 * ((c * 7 + r * 3) % 5);
    f.source = "bench";
    return f;
}

std::unique_ptr<tsf::ScadEngine> makeEngine(const std::string& name, std::string& missing) {
    try {
        return name == "wasm" ? tsf::makeWasmOpenScadEngine() : tsf::makeOpenScadEngine();
    } catch (const tsf::ScadEngineMissing& e) {
        missing = e.what();
        return nullptr;
    }
}

void benchEngine(benchmark::State& state, int side, const std::string& strategy, const std::string& engine_name) {
    std::string missing;
    const std::unique_ptr<tsf::ScadEngine> engine = makeEngine(engine_name, missing);
    if (!engine) {
        state.SkipWithError(("engine not installed: " + missing).c_str());
        return;
    }
    tsf::SceneParams params;
    params.pitch_mm = 4.0;
    params.max_height_mm = 20.0;
    params.base_mm = 2.0;
    params.cull = tsf::Cull::None;
    const tsf::Scene scene = tsf::buildScene(benchField(side), params);
    tsf::ScadOptions opts;
    tsf::parseScadStrategy(strategy, opts.strategy);
    opts.inline_library = false;
    const fs::path dir = fs::temp_directory_path() / "tsf-engines-bench" / (std::to_string(side) + "-" + strategy);
    fs::create_directories(dir);
    tsf::writeScad(scene, opts, (dir / "model.scad").string());
    const double direct_volume_mm3 = tsf::signedVolume(tsf::meshScene(scene));

    tsf::ScadRenderRequest rq;
    rq.scad_path = (dir / "model.scad").string();
    rq.output_path = (dir / (engine_name + ".stl")).string();
    rq.timeout_s = envNumber("TSF_BENCH_ENGINES_TIMEOUT_S", 600);
    tsf::ScadRenderResult result;
    tsf::EngineOutputCheck check;
    for (auto _ : state) {
        result = tsf::renderScadChecked(*engine, rq, {}, {direct_volume_mm3}, &check);
        state.SetIterationTime(result.elapsed_s);
    }
    const size_t cells = scene.keptCount();
    state.counters["peak_MB"] = double(result.peak_memory_kb) / 1024.0;
    state.counters["triangles"] = double(check.triangles);
    bool same_solid = false;
    std::string verdict = result.ok() ? "verifier failed" : result.summary;
    if (result.ok()) {
        tsf::VerifyOptions vo;
        vo.printability = false;
        vo.exact = true;  // the filtered kernel can stop on a CGAL precondition for near-degenerate input
        try {
            const tsf::VerifyReport report = tsf::verifyModel(tsf::readStl(rq.output_path), &scene, vo);
            same_solid = report.passed();
            for (const tsf::Check& c : report.checks)
                if (c.status == tsf::CheckStatus::Fail) verdict = c.id + ": " + std::to_string(c.count);
        } catch (const std::exception& e) {
            verdict = std::string("verifier error: ") + e.what();
        }
    }
    state.counters["same_solid"] = same_solid ? 1 : 0;
    std::fprintf(stderr, "%zu cells -> %zu triangles in %.1f s (%s, %s)\n", cells, check.triangles, result.elapsed_s,
                 strategy.c_str(), engine->name().c_str());
    std::fprintf(stderr, "| %zu | %s | %s | %s%.1f s | %.0f MB | %zu | %s |\n", cells, strategy.c_str(),
                 engine_name.c_str(), result.status == tsf::ScadRenderResult::Status::TimedOut ? "> " : "",
                 result.elapsed_s, double(result.peak_memory_kb) / 1024.0, check.triangles,
                 same_solid ? "y" : ("n (" + verdict + ")").c_str());
    if (!result.ok()) state.SkipWithError(result.summary.c_str());
}

bool registerEngineBenchmarks() {
    const int max_side = int(envNumber("TSF_BENCH_ENGINES_MAX_SIDE", 40));
    for (int side : {10, 20, 40, 100, 160}) {
        if (side > max_side) continue;
        for (const char* strategy : {"polyhedron", "csg"})
            for (const char* engine : {"openscad", "wasm"})
                benchmark::RegisterBenchmark(
                    ("Engines/" + std::to_string(side) + "/" + strategy + "/" + engine).c_str(),
                    [=](benchmark::State& st) { benchEngine(st, side, strategy, engine); })
                    ->Iterations(1)
                    ->UseManualTime()
                    ->Unit(benchmark::kSecond);
    }
    return true;
}

const bool kRegistered = registerEngineBenchmarks();

}  // namespace
