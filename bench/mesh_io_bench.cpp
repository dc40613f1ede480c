// Binary STL write and read throughput on closed synthetic meshes.
//   build/bench/tsf_bench --benchmark_filter=Stl
// Mesh: a box whose six faces are each an n x n grid of squares (two
// triangles each), 12 n^2 triangles, vertices shared along the box edges.
// n = 112 -> 150 528 triangles; n = 500 -> 3 000 000 triangles.
//   *File  : writeStl / readMesh on a real file (write includes fsync+rename)
//   *Memory: the same bytes to/from memory, isolating formatting and parsing
// Rates are per wall-clock second (UseRealTime): file I/O is what a user waits for.
#include <benchmark/benchmark.h>

#include <array>
#include <filesystem>
#include <sstream>
#include <string>
#include <unistd.h>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/exact_vertex_index.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/stl_reader.h"
#include "gen/mesh_io/stl_writer.h"

namespace {

// Grid step, a power of two so every coordinate is exact in float32.
constexpr double kStepMm = 0.25;

tsf::Mesh subdividedBox(int n) {
    tsf::mesh_io::ExactVertexIndex index(size_t(6) * (n + 1) * (n + 1));
    tsf::Mesh mesh;
    mesh.triangles.reserve(size_t(12) * n * n);
    // Each face: a fixed axis at 0 or n, spanned by axes u and v in the order
    // that makes the normal point outward.
    struct Face {
        int axis, u, v;
        bool high;
    };
    const std::array<Face, 6> faces = {{{2, 1, 0, false}, {2, 0, 1, true}, {1, 0, 2, false},
                                        {1, 2, 0, true},  {0, 2, 1, false}, {0, 1, 2, true}}};
    for (const Face& f : faces) {
        auto vertex = [&](int i, int j) {
            double p[3];
            p[f.axis] = f.high ? n * kStepMm : 0.0;
            p[f.u] = i * kStepMm;
            p[f.v] = j * kStepMm;
            return index.insert({p[0], p[1], p[2]});
        };
        for (int i = 0; i < n; ++i) {
            for (int j = 0; j < n; ++j) {
                const uint32_t a = vertex(i, j), b = vertex(i + 1, j), c = vertex(i + 1, j + 1), d = vertex(i, j + 1);
                mesh.triangles.push_back({a, b, c});
                mesh.triangles.push_back({a, c, d});
            }
        }
    }
    mesh.positions = index.takePositions();
    return mesh;
}

const tsf::Mesh& boxFor(int n) {
    static int cached_n = -1;
    static tsf::Mesh cached;
    if (cached_n != n) {
        cached = subdividedBox(n);
        cached_n = n;
    }
    return cached;
}

std::string scratchFile() {
    const auto dir = std::filesystem::temp_directory_path() / ("tsf_mesh_io_bench_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return (dir / "box.stl").string();
}

void setCounters(benchmark::State& state, const tsf::Mesh& mesh) {
    state.counters["triangles"] = double(mesh.triangleCount());
    state.counters["triangles/s"] =
        benchmark::Counter(double(mesh.triangleCount()), benchmark::Counter::kIsIterationInvariantRate);
    state.SetBytesProcessed(int64_t(state.iterations()) * int64_t(84 + 50 * mesh.triangleCount()));
}

void BM_StlBinaryWriteFile(benchmark::State& state) {
    const tsf::Mesh& mesh = boxFor(int(state.range(0)));
    const std::string path = scratchFile();
    for (auto _ : state) tsf::writeStl(mesh, path);
    setCounters(state, mesh);
    std::filesystem::remove_all(std::filesystem::path(path).parent_path());
}

void BM_StlBinaryReadFile(benchmark::State& state) {
    const tsf::Mesh& mesh = boxFor(int(state.range(0)));
    const std::string path = scratchFile();
    tsf::writeStl(mesh, path);
    for (auto _ : state) {
        tsf::Mesh read = tsf::readMesh(path);
        if (read.vertexCount() != mesh.vertexCount()) state.SkipWithError("vertex count changed in the round trip");
        benchmark::DoNotOptimize(read);
    }
    setCounters(state, mesh);
    std::filesystem::remove_all(std::filesystem::path(path).parent_path());
}

void BM_StlBinaryWriteMemory(benchmark::State& state) {
    const tsf::Mesh& mesh = boxFor(int(state.range(0)));
    for (auto _ : state) {
        std::ostringstream out;
        tsf::writeStlBinary(mesh, out, "bench");
        benchmark::DoNotOptimize(out);
    }
    setCounters(state, mesh);
}

void BM_StlBinaryParseMemory(benchmark::State& state) {
    const tsf::Mesh& mesh = boxFor(int(state.range(0)));
    std::ostringstream out;
    tsf::writeStlBinary(mesh, out, "bench");
    const std::string bytes = out.str();
    for (auto _ : state) {
        tsf::Mesh read = tsf::parseStl(bytes, "bench.stl");
        benchmark::DoNotOptimize(read);
    }
    setCounters(state, mesh);
}

}  // namespace

BENCHMARK(BM_StlBinaryWriteMemory)->Arg(112)->Arg(500)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StlBinaryWriteFile)->Arg(112)->Arg(500)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StlBinaryParseMemory)->Arg(112)->Arg(500)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_StlBinaryReadFile)->Arg(112)->Arg(500)->Unit(benchmark::kMillisecond)->UseRealTime();
