#include "runners/openscad/engine_output_check.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "gen/util/error.h"
#include "gen/util/atomic_file.h"
#include "gen/mesh_io/off_reader.h"
#include "gen/mesh_io/stl_reader.h"
#include "gen/mesh_io/three_mf_reader.h"
#include "verify/mesh_topology.h"
#include "verify/solid_checks.h"

namespace tsf {
namespace {

// Surface area (mm^2) and the largest |coordinate| (mm) of the vertices in use.
void surfaceFigures(const Mesh& mesh, double& area_mm2, double& max_abs_mm) {
    area_mm2 = 0;
    max_abs_mm = 0;
    for (const auto& t : mesh.triangles) {
        area_mm2 += triangleArea(mesh, t);
        for (uint32_t v : t) {
            const Vec3& p = mesh.positions[v];
            max_abs_mm = std::max({max_abs_mm, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
        }
    }
}

std::string count(size_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// The first failed solid check with CGAL, as one line ("" = all passed).
std::string solidProblem(const Mesh& mesh) {
    SolidOptions so;
    so.exact = true;
    so.max_offenders = 1;
    const SolidResult r = checkSolid(mesh, so);
    for (const Check& c : r.checks) {
        if (c.status != CheckStatus::Fail) continue;
        std::string what = c.title + " (" + std::to_string(c.count) + ")";
        if (!c.worst.empty()) {
            char at[96];
            std::snprintf(at, sizeof at, " at (%.3f, %.3f, %.3f) mm", c.worst[0].at_mm.x, c.worst[0].at_mm.y,
                          c.worst[0].at_mm.z);
            what += at;
        }
        return what;
    }
    return "";
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
    const MeshTopology topo = analyzeTopology(mesh);
    if (!topo.out_of_range_triangles.empty()) {
        c.problem = "a triangle refers to a vertex that does not exist";
        return c;
    }
    c.degenerate_triangles = topo.index_degenerate_triangles.size();
    c.open_edges = topo.border_edges.size();
    c.overused_edges = topo.nonmanifold_edges.size() + topo.misoriented_edges.size();
    c.pinched_vertices = topo.nonmanifold_vertices.size();
    c.pieces = topo.components.size();

    c.volume_mm3 = signedVolume(mesh);
    double area_mm2 = 0, max_abs_mm = 0;
    surfaceFigures(mesh, area_mm2, max_abs_mm);
    c.volume_tolerance_mm3 = area_mm2 * max_abs_mm * kStlCoordinateRoundoff;

    std::ostringstream why;
    if (!topo.nonfinite_vertices.empty()) {
        why << count(topo.nonfinite_vertices.size(), "vertex has", "vertices have") << " a coordinate that is not a finite number";
    } else if (c.degenerate_triangles > 0) {
        why << count(c.degenerate_triangles, "triangle repeats a vertex", "triangles repeat a vertex");
    } else if (c.open_edges > 0 || c.overused_edges > 0) {
        why << "not a closed, consistently oriented 2-manifold (" << count(c.open_edges, "edge", "edges")
            << " without a matching opposite edge, " << count(c.overused_edges, "edge", "edges") << " used twice)";
    } else if (c.pinched_vertices > 0) {
        why << "not a 2-manifold: " << count(c.pinched_vertices, "vertex joins", "vertices join")
            << " surfaces that only touch there";
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
    if (c.problem.empty() && expect.solid_checks) c.problem = solidProblem(mesh);
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
