#include "verify/render/engine_output_check.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <vector>

#include "gen/error.h"
#include "gen/mesh_io/atomic_file.h"
#include "gen/mesh_io/off_reader.h"
#include "gen/mesh_io/stl_reader.h"
#include "gen/mesh_io/three_mf_reader.h"

namespace tsf {
namespace {

uint64_t edgeKey(uint32_t from, uint32_t to) { return (uint64_t(from) << 32) | to; }

// Union-find over vertex indices (path halving).
uint32_t findRoot(std::vector<uint32_t>& parent, uint32_t v) {
    while (parent[v] != v) v = parent[v] = parent[parent[v]];
    return v;
}

// Surface area (mm^2) and the largest |coordinate| (mm) of the vertices in use.
void surfaceFigures(const Mesh& mesh, double& area_mm2, double& max_abs_mm) {
    area_mm2 = 0;
    max_abs_mm = 0;
    for (const auto& t : mesh.triangles) {
        const Vec3& a = mesh.positions[t[0]];
        const Vec3& b = mesh.positions[t[1]];
        const Vec3& c = mesh.positions[t[2]];
        const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
        const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
        const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
        area_mm2 += 0.5 * std::sqrt(nx * nx + ny * ny + nz * nz);
        for (const Vec3* p : {&a, &b, &c})
            max_abs_mm = std::max({max_abs_mm, std::abs(p->x), std::abs(p->y), std::abs(p->z)});
    }
}

std::string count(size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

}  // namespace

EngineOutputCheck checkEngineMesh(const Mesh& mesh, const EngineOutputExpectation& expect) {
    EngineOutputCheck c;
    c.checked = true;
    c.triangles = mesh.triangleCount();
    if (mesh.triangles.empty()) {
        c.problem = "the mesh has no triangles";
        return c;
    }
    const uint32_t n_vertices = uint32_t(mesh.positions.size());
    std::vector<uint64_t> edges;
    edges.reserve(3 * mesh.triangles.size());
    std::vector<uint32_t> parent(n_vertices);
    std::iota(parent.begin(), parent.end(), 0u);
    for (const auto& t : mesh.triangles) {
        if (t[0] >= n_vertices || t[1] >= n_vertices || t[2] >= n_vertices) {
            c.problem = "a triangle refers to a vertex that does not exist";
            return c;
        }
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) {
            ++c.degenerate_triangles;
            continue;
        }
        for (int k = 0; k < 3; ++k) {
            edges.push_back(edgeKey(t[k], t[(k + 1) % 3]));
            const uint32_t a = findRoot(parent, t[k]), b = findRoot(parent, t[(k + 1) % 3]);
            if (a != b) parent[a] = b;
        }
    }
    std::sort(edges.begin(), edges.end());
    for (size_t i = 0; i < edges.size();) {
        size_t j = i;
        while (j < edges.size() && edges[j] == edges[i]) ++j;
        if (j - i > 1) c.overused_edges += j - i - 1;
        const uint64_t reverse = (edges[i] << 32) | (edges[i] >> 32);
        if (!std::binary_search(edges.begin(), edges.end(), reverse)) ++c.open_edges;
        i = j;
    }
    std::vector<bool> used(n_vertices, false);
    for (const auto& t : mesh.triangles)
        for (uint32_t v : t) used[v] = true;
    for (uint32_t v = 0; v < n_vertices; ++v)
        if (used[v] && findRoot(parent, v) == v) ++c.pieces;

    c.volume_mm3 = signedVolume(mesh);
    double area_mm2 = 0, max_abs_mm = 0;
    surfaceFigures(mesh, area_mm2, max_abs_mm);
    c.volume_tolerance_mm3 = area_mm2 * max_abs_mm * kStlCoordinateRoundoff;

    std::ostringstream why;
    if (c.degenerate_triangles > 0) {
        why << count(c.degenerate_triangles, "triangle repeats a vertex", "triangles repeat a vertex");
    } else if (c.open_edges > 0 || c.overused_edges > 0) {
        why << "not a closed, consistently oriented 2-manifold (" << count(c.open_edges, "edge", "edges")
            << " without a matching opposite edge, " << count(c.overused_edges, "edge", "edges") << " used twice)";
    } else if (c.pieces != 1) {
        why << "the mesh falls apart into " << c.pieces << " pieces";
    } else if (!(c.volume_mm3 > 0)) {
        why << "the volume is " << c.volume_mm3 << " mm^3 (normals point inward)";
    } else if (expect.volume_mm3 && !(std::abs(c.volume_mm3 - *expect.volume_mm3) <= c.volume_tolerance_mm3)) {
        why.precision(10);
        why << "the volume is " << c.volume_mm3 << " mm^3, the model's is " << *expect.volume_mm3
            << " mm^3 (more than the coordinates' rounding, " << c.volume_tolerance_mm3 << " mm^3, apart)";
    }
    c.problem = why.str();
    if (c.problem.empty() && expect.solid_check) c.problem = expect.solid_check(mesh);
    c.ok = c.problem.empty();
    return c;
}

EngineOutputCheck checkEngineOutputFile(const std::string& path, ScadExportFormat format,
                                        const EngineOutputExpectation& expect) {
    Mesh mesh;
    try {
        switch (format) {
            case ScadExportFormat::Stl: mesh = readStl(path); break;
            case ScadExportFormat::Off: mesh = readOff(path); break;
            case ScadExportFormat::ThreeMf: mesh = read3mf(path); break;
            default: return EngineOutputCheck{};  // AMF, PNG: nothing to read back
        }
    } catch (const std::exception& e) {
        EngineOutputCheck c;
        c.checked = true;
        c.problem = std::string("the file cannot be read back: ") + e.what();
        return c;
    }
    return checkEngineMesh(mesh, expect);
}

ScadRenderResult renderScadChecked(const ScadEngine& engine, const ScadRenderRequest& request,
                                   const ScadProgress& progress, const EngineOutputExpectation& expect,
                                   EngineOutputCheck* check) {
    // renderScad commits into `staged`'s temporary file; `staged` moves it to
    // the real output only after the check.
    AtomicFile staged(request.output_path);
    ScadRenderRequest rq = request;
    rq.output_path = staged.tempPath();
    ScadRenderResult r = renderScad(engine, rq, progress);
    EngineOutputCheck c;
    if (r.ok()) {
        c = checkEngineOutputFile(staged.tempPath(), request.format, expect);
        if (c.checked && !c.ok) {
            r.status = ScadRenderResult::Status::Failed;
            r.summary = engine.name() + " reported success but wrote a broken mesh: " + c.problem +
                        "; treated as an engine failure, nothing written";
        } else {
            staged.commit();
        }
    }
    if (check) *check = c;
    return r;
}

}  // namespace tsf
