#include "gen/mesh/legend_join.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Surface_mesh.h>

#include "gen/geometry/cgal_surface_mesh.h"
#include "gen/mesh/legend_mesh.h"
#include "gen/model/scene.h"
#include "gen/util/number_format.h"
#include "gen/util/error.h"

namespace tsf {
namespace {

using Kernel = CGAL::Exact_predicates_exact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;

double snapUm(double mm) { return std::round(mm * 1000.0) / 1000.0; }

bool onGridXy(const Vec3& p) {
    return std::fabs(p.x * 1000.0 - std::round(p.x * 1000.0)) < 1e-6 &&
           std::fabs(p.y * 1000.0 - std::round(p.y * 1000.0)) < 1e-6;
}

Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
Vec3 cross(const Vec3& a, const Vec3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
Vec3 normalOf(const Mesh& m, const std::array<uint32_t, 3>& t) {
    return cross(sub(m.positions[t[1]], m.positions[t[0]]), sub(m.positions[t[2]], m.positions[t[0]]));
}

// The union adds vertices off the model's 1 um grid where an edge of one
// solid crosses a face of the other inside a plane both share (a wall's
// diagonal crossing the plate's top, two coplanar diagonals crossing). Each
// lies on a straight line through its neighbours, so it is collapsed into a
// neighbour whenever that keeps every remaining triangle facing as before
// (same side, non-zero area) and the mesh 2-manifold (the link condition).
// Returns the number of vertices it could not remove.
size_t collapseOffGridVertices(Mesh& m) {
    size_t left = 0;
    std::vector<std::vector<uint32_t>> tris_of(m.positions.size());
    for (uint32_t t = 0; t < m.triangles.size(); ++t)
        for (const uint32_t v : m.triangles[t]) tris_of[v].push_back(t);
    std::vector<uint8_t> dead(m.triangles.size(), 0);
    for (uint32_t p = 0; p < m.positions.size(); ++p) {
        if (onGridXy(m.positions[p]) || tris_of[p].empty()) continue;
        std::vector<uint32_t> around;
        for (const uint32_t t : tris_of[p])
            if (!dead[t]) around.push_back(t);
        std::vector<uint32_t> nbrs;
        for (const uint32_t t : around)
            for (const uint32_t v : m.triangles[t])
                if (v != p && std::find(nbrs.begin(), nbrs.end(), v) == nbrs.end()) nbrs.push_back(v);
        bool done = false;
        for (const uint32_t a : nbrs) {
            if (!onGridXy(m.positions[a])) continue;
            // Link condition: the common neighbours of p and a are the apexes of the triangles on edge pa.
            size_t on_edge = 0;
            for (const uint32_t t : around) on_edge += std::count(m.triangles[t].begin(), m.triangles[t].end(), a) > 0;
            std::vector<uint32_t> a_nbrs;
            for (const uint32_t t : tris_of[a])
                if (!dead[t])
                    for (const uint32_t v : m.triangles[t]) a_nbrs.push_back(v);
            size_t common = 0;
            for (const uint32_t v : nbrs)
                if (v != a && std::find(a_nbrs.begin(), a_nbrs.end(), v) != a_nbrs.end()) ++common;
            if (common != on_edge) continue;
            bool ok = true;
            for (const uint32_t t : around) {
                if (std::count(m.triangles[t].begin(), m.triangles[t].end(), a)) continue;
                std::array<uint32_t, 3> moved = m.triangles[t];
                for (uint32_t& v : moved)
                    if (v == p) v = a;
                const Vec3 before = normalOf(m, m.triangles[t]), after = normalOf(m, moved);
                const double len_after = std::sqrt(dot(after, after)), len_before = std::sqrt(dot(before, before));
                // Same facing (within 1e-9 rad of parallel) and an area well above the degenerate limit.
                if (len_after < 1e-9 || dot(before, after) < (1 - 1e-12) * len_before * len_after) {
                    ok = false;
                    break;
                }
            }
            if (!ok) continue;
            for (const uint32_t t : around) {
                if (std::count(m.triangles[t].begin(), m.triangles[t].end(), a)) {
                    dead[t] = 1;
                    continue;
                }
                for (uint32_t& v : m.triangles[t])
                    if (v == p) v = a;
                tris_of[a].push_back(t);
            }
            tris_of[p].clear();
            done = true;
            break;
        }
        if (!done) ++left;
    }
    // Drop the collapsed triangles and the vertices no triangle uses.
    std::vector<std::array<uint32_t, 3>> kept;
    for (uint32_t t = 0; t < m.triangles.size(); ++t)
        if (!dead[t]) kept.push_back(m.triangles[t]);
    std::vector<uint32_t> remap(m.positions.size(), UINT32_MAX);
    Mesh out;
    for (auto& t : kept)
        for (uint32_t& v : t) {
            if (remap[v] == UINT32_MAX) {
                remap[v] = uint32_t(out.positions.size());
                out.positions.push_back(m.positions[v]);
            }
            v = remap[v];
        }
    out.triangles = std::move(kept);
    m = std::move(out);
    return left;
}

// The plate's footprint, height and dots in the model frame.
PlateSpec plateSpec(const Scene& s) {
    const SceneLegend& l = *s.legend;
    PlateSpec spec;
    spec.x0_mm = 0;
    spec.y0_mm = l.plate_south_mm;
    spec.x1_mm = l.plate_east_mm;
    spec.y1_mm = l.plate_north_mm;
    spec.height_mm = s.zMm(l.plate_top_units);
    spec.standard = l.layout.standard;
    for (const LegendDot& d : l.layout.dots) spec.dots.push_back({snapUm(d.x_mm + l.x0_mm), snapUm(d.y_mm + l.y0_mm)});
    return spec;
}

}  // namespace

Mesh legendDotsMesh(const Scene& s) {
    if (!s.legend) return {};
    return meshLegendDots(plateSpec(s));
}

Mesh legendPlateMesh(const Scene& s, bool dots) {
    if (!s.legend) return {};
    const SceneLegend& l = *s.legend;
    PlateSpec spec = plateSpec(s);
    if (!dots) spec.dots.clear();
    // Every hexagon edge of a kept cell the plate reaches over becomes an edge
    // of its top, so the union meets the pillars' walls only at lattice corners.
    const int64_t south_j = hexCentre(s.grid, 0, l.reach_row).j + 1;
    for (int32_t r = 0; r <= l.reach_row; ++r)
        for (int32_t c = 0; c < s.grid.cols; ++c) {
            if (s.keptAt(c, r) < 0) continue;
            for (int k = 0; k < kHexCorners; ++k) {
                const LatticePoint a = hexCorner(s.grid, c, r, k), b = hexCorner(s.grid, c, r, (k + 1) % kHexCorners);
                if (a.j < south_j || b.j < south_j) continue;
                const Vec3 pa = s.point(a, 0), pb = s.point(b, 0);
                spec.top_edges.push_back({pa.x, pa.y, pb.x, pb.y});
            }
        }
    return meshLegendPlate(spec);
}

// The join's own failure, on the models it is known to fail on (a few cells,
// the plate reaching over most of them): the input's size, said as such.
[[noreturn]] void joinFailed(const Scene& s, const std::string& why) {
    throw InputError("--title/--units: the braille legend's plate could not be joined to a model this small (" +
                     std::to_string(s.keptCount()) + (s.keptCount() == 1 ? " cell, " : " cells, ") + formatSignificant(gridWidth(s.grid, s.pitch_mm), 4) +
                     " mm wide; " + why +
                     "): give it more cells (more values, a larger --bins) or leave out --title and --units");
}

Mesh unionWithLegend(const Mesh& pillars, const Scene& s, bool dots) {
    SurfaceMesh a = toSurfaceMesh<Kernel>(pillars), b = toSurfaceMesh<Kernel>(legendPlateMesh(s, dots)), out;
    namespace PMP = CGAL::Polygon_mesh_processing;
    try {
        if (!PMP::corefine_and_compute_union(a, b, out)) joinFailed(s, "the exact union failed");
    } catch (const CGAL::Failure_exception& e) {
        joinFailed(s, "a degenerate configuration in the exact union");
    }
    Mesh m;
    std::map<SurfaceMesh::Vertex_index, uint32_t> index;
    for (const auto v : out.vertices()) {
        const Kernel::Point_3& p = out.point(v);
        index[v] = uint32_t(m.positions.size());
        m.positions.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
    }
    for (const auto f : out.faces()) {
        std::array<uint32_t, 3> t{};
        int k = 0;
        for (const auto v : CGAL::vertices_around_face(out.halfedge(f), out)) {
            if (k < 3) t[size_t(k)] = index[v];
            ++k;
        }
        if (k != 3) throw std::runtime_error("the legend union gave a face that is not a triangle");
        m.triangles.push_back(t);
    }
    collapseOffGridVertices(m);
    return m;
}

}  // namespace tsf
