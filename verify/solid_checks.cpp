// checkSolid: topology from the indices, geometry with CGAL. See solid_checks.h.
#include "verify/solid_checks.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

#include "gen/util/union_find.h"
#include "verify/detail/cgal_checks.h"
#include "verify/detail/format.h"
#include "verify/mesh_topology.h"

namespace tsf {
namespace {

using detail::fmtMm;
using detail::fmtNum;
using detail::fmtPoint;

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Check makeCheck(const char* id, const char* title, const Stage& stage) {
    Check c;
    c.id = id;
    c.title = title;
    c.stage = stage.name;
    c.time_ms = stage.time_ms;
    return c;
}

void finish(Check& c, int64_t count, CheckStatus fail_status = CheckStatus::Fail) {
    c.count = count;
    c.status = count == 0 ? CheckStatus::Pass : fail_status;
}

std::string plural(int64_t n, const char* one, const char* many) {
    return std::to_string(n) + " " + (n == 1 ? one : many);
}

// Border edges grouped into holes: edges that share a vertex belong to one hole.
void reportHoles(const Mesh& mesh, const MeshTopology& topo, size_t max_offenders, Check& c) {
    std::map<uint32_t, uint32_t> compact;  // vertex -> dense id
    for (const EdgeUse& e : topo.border_edges) {
        compact.emplace(e.a, uint32_t(compact.size()));
        compact.emplace(e.b, uint32_t(compact.size()));
    }
    UnionFind rims(compact.size());
    for (const EdgeUse& e : topo.border_edges) rims.unite(compact[e.a], compact[e.b]);
    struct Hole {
        size_t edges = 0;
        Vec3 sum;
        double length_mm = 0;
    };
    std::map<uint32_t, Hole> holes;
    for (const EdgeUse& e : topo.border_edges) {
        Hole& h = holes[rims.find(compact[e.a])];
        const Vec3 m = edgeMidpoint(mesh, e);
        const Vec3 &p = mesh.positions[e.a], &q = mesh.positions[e.b];
        ++h.edges;
        h.sum = {h.sum.x + m.x, h.sum.y + m.y, h.sum.z + m.z};
        h.length_mm += std::sqrt((p.x - q.x) * (p.x - q.x) + (p.y - q.y) * (p.y - q.y) + (p.z - q.z) * (p.z - q.z));
    }
    std::vector<Hole> list;
    for (auto& [root, h] : holes) list.push_back(h);
    std::stable_sort(list.begin(), list.end(), [](const Hole& a, const Hole& b) { return a.length_mm > b.length_mm; });
    for (const Hole& h : list) {
        if (c.worst.size() >= max_offenders) break;
        const Vec3 at{h.sum.x / double(h.edges), h.sum.y / double(h.edges), h.sum.z / double(h.edges)};
        c.worst.push_back({at, h.length_mm,
                           "hole bounded by " + plural(int64_t(h.edges), "border edge", "border edges") + ", " +
                               fmtMm(h.length_mm) + " mm of rim"});
    }
    c.unit = "mm";
    c.note = plural(int64_t(topo.border_edges.size()), "border edge", "border edges") + " in " +
             plural(int64_t(holes.size()), "hole", "holes");
}

}  // namespace

SolidResult checkSolid(const Mesh& mesh, const SolidOptions& options) {
    SolidResult r;
    const size_t max_off = options.max_offenders;

    auto t0 = std::chrono::steady_clock::now();
    const MeshTopology topo = analyzeTopology(mesh);
    const Stage topo_stage{"topology", msSince(t0)};
    r.stages.push_back(topo_stage);

    MeshSummary& s = r.mesh;
    s.vertex_count = topo.vertex_count;
    s.triangle_count = topo.triangle_count;
    s.edge_count = topo.edge_count;
    s.bounds = meshBounds(mesh);
    s.signed_volume_mm3 = signedVolume(mesh);
    s.volume_mm3 = std::numeric_limits<double>::quiet_NaN();
    s.component_count = topo.components.size();
    s.unreferenced_vertices = topo.unreferenced_vertices;
    s.duplicate_position_vertices = topo.duplicate_position_vertices;
    {
        std::vector<uint8_t> skip(mesh.triangles.size(), 0);
        for (uint32_t t : topo.out_of_range_triangles) skip[t] = 1;
        for (size_t t = 0; t < mesh.triangles.size(); ++t)
            if (!skip[t]) s.area_mm2 += triangleArea(mesh, mesh.triangles[t]);
    }

    // [valid_input]
    {
        Check c = makeCheck("valid_input", "coordinates finite, indices in range", topo_stage);
        for (uint32_t v : topo.nonfinite_vertices) {
            if (c.worst.size() >= max_off) break;
            c.worst.push_back({mesh.positions[v], NAN, "vertex " + std::to_string(v) + " has a NaN or infinite coordinate"});
        }
        for (uint32_t t : topo.out_of_range_triangles) {
            if (c.worst.size() >= max_off) break;
            c.worst.push_back({Vec3{NAN, NAN, NAN}, NAN,
                               "triangle " + std::to_string(t) + " uses a vertex index beyond the " +
                                   std::to_string(mesh.positions.size()) + " vertices"});
        }
        finish(c, int64_t(topo.nonfinite_vertices.size() + topo.out_of_range_triangles.size()));
        if (c.count) c.note = plural(int64_t(topo.nonfinite_vertices.size()), "non-finite vertex", "non-finite vertices") +
                              ", " + plural(int64_t(topo.out_of_range_triangles.size()), "bad triangle", "bad triangles");
        r.checks.push_back(std::move(c));
    }

    // [closed]
    {
        Check c = makeCheck("closed", "closed (no border edges)", topo_stage);
        finish(c, int64_t(topo.border_edges.size()));
        if (c.count) reportHoles(mesh, topo, max_off, c);
        r.checks.push_back(std::move(c));
    }

    // [manifold_edges]
    {
        Check c = makeCheck("manifold_edges", "every edge has exactly two triangles", topo_stage);
        c.unit = "triangles";
        std::vector<const EdgeUse*> order;
        for (const EdgeUse& e : topo.nonmanifold_edges) order.push_back(&e);
        std::stable_sort(order.begin(), order.end(),
                         [](const EdgeUse* a, const EdgeUse* b) { return a->triangles.size() > b->triangles.size(); });
        for (const EdgeUse* e : order) {
            if (c.worst.size() >= max_off) break;
            c.worst.push_back({edgeMidpoint(mesh, *e), double(e->triangles.size()),
                               "edge " + std::to_string(e->a) + "-" + std::to_string(e->b) + " is shared by " +
                                   std::to_string(e->triangles.size()) + " triangles (first " +
                                   std::to_string(e->triangles[0]) + ")"});
        }
        finish(c, int64_t(topo.nonmanifold_edges.size()));
        r.checks.push_back(std::move(c));
    }

    // [manifold_vertices]
    {
        Check c = makeCheck("manifold_vertices", "every vertex has one fan of triangles", topo_stage);
        for (uint32_t v : topo.nonmanifold_vertices) {
            if (c.worst.size() >= max_off) break;
            c.worst.push_back({mesh.positions[v], NAN,
                               "vertex " + std::to_string(v) + " joins surfaces that share no edge there"});
        }
        finish(c, int64_t(topo.nonmanifold_vertices.size()));
        r.checks.push_back(std::move(c));
    }

    // [consistent_orientation]
    {
        Check c = makeCheck("consistent_orientation", "neighbouring triangles consistently oriented", topo_stage);
        c.unit = "edges";
        std::map<uint32_t, int> disagreements;  // triangle -> misoriented edges it has
        for (const EdgeUse& e : topo.misoriented_edges)
            for (uint32_t t : e.triangles) ++disagreements[t];
        std::vector<std::pair<uint32_t, int>> order(disagreements.begin(), disagreements.end());
        std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.second > b.second; });
        for (const auto& [t, n] : order) {
            if (c.worst.size() >= max_off) break;
            c.worst.push_back({triangleCentroid(mesh, t), double(n),
                               "triangle " + std::to_string(t) + ": " + std::to_string(n) + " of its edges run the " +
                                   "same way as the neighbour's" + (n >= 2 ? " (flipped?)" : "")});
        }
        finish(c, int64_t(topo.misoriented_edges.size()));
        if (c.count) c.note = plural(c.count, "edge", "edges") + " traversed twice in the same direction";
        r.checks.push_back(std::move(c));
    }

    // [single_piece]
    {
        Check c = makeCheck("single_piece", "one piece", topo_stage);
        c.unit = "triangles";
        if (topo.components.empty()) {
            c.status = CheckStatus::Fail;
            c.count = 1;
            c.note = "the mesh has no usable triangles";
        } else {
            for (size_t i = 1; i < topo.components.size() && c.worst.size() < max_off; ++i) {
                const MeshComponent& m = topo.components[i];
                c.worst.push_back({detail::boundsCentre(m.bounds), double(m.triangles.size()),
                                   "separate piece of " + plural(int64_t(m.triangles.size()), "triangle", "triangles") +
                                       ", box " + fmtPoint(m.bounds.min) + " to " + fmtPoint(m.bounds.max) +
                                       ", volume " + fmtNum(m.signed_volume_mm3) + " mm^3"});
            }
            finish(c, int64_t(topo.components.size() - 1));
            c.note = plural(int64_t(topo.components.size()), "piece", "pieces") + " (edge-connected)";
            if (options.pieces_allowed && c.status == CheckStatus::Fail) {
                // A part of an assembly that stands on another (the braille dots): its pieces are held by that part.
                c.status = CheckStatus::Pass;
                c.worst.clear();
                c.count = 0;
                c.note += ", allowed for this part";
            }
        }
        r.checks.push_back(std::move(c));
    }

    // [distinct_vertices] (warning: unmerged vertices usually also open the mesh)
    {
        Check c = makeCheck("distinct_vertices", "no two vertices at the same position", topo_stage);
        finish(c, int64_t(topo.duplicate_position_vertices), CheckStatus::Warn);
        if (c.count) c.note = plural(c.count, "vertex sits", "vertices sit") + " exactly on another vertex (not merged)";
        r.checks.push_back(std::move(c));
    }

    // Geometry with CGAL.
    const bool finite = topo.nonfinite_vertices.empty();
    detail::GeometricFindings g;
    std::string exact_fallback_reason;  // non-empty: the filtered kernel failed and the exact one was used
    std::unique_ptr<ColumnGrid> own_grid;
    if (finite) {
        const ColumnGrid* grid = options.grid;
        if (!grid && options.self_intersections) {
            own_grid = std::make_unique<ColumnGrid>(mesh);
            grid = own_grid.get();
            r.stages.push_back({"grid", own_grid->buildMs()});
        }
        if (options.exact) {
            g = detail::geometricChecksEpeck(mesh, topo, max_off, options.self_intersections, grid);
        } else {
            try {
                g = detail::geometricChecksEpick(mesh, topo, max_off, options.self_intersections, grid);
            } catch (const std::exception& e) {
                // The filtered kernel constructs intersection points in doubles;
                // on near-degenerate contacts (a corner touching a face) CGAL's
                // own preconditions can fail there. The exact kernel decides
                // those cases, so the check is redone with it rather than lost.
                g = detail::geometricChecksEpeck(mesh, topo, max_off, options.self_intersections, grid);
                exact_fallback_reason = e.what();
                exact_fallback_reason = exact_fallback_reason.substr(0, exact_fallback_reason.find('\n'));
            }
        }
        r.stages.push_back({"degenerate", g.degenerate_ms});
        if (g.cgal_mesh_used) r.stages.push_back({"cgal_mesh", g.build_ms});
        if (g.mesh_built) r.stages.push_back({"self_intersections", g.self_intersection_ms});
        if (g.volumes_computed) r.stages.push_back({"volume", g.volume_ms});
    }
    auto stage = [&](const char* name) {
        for (const Stage& st : r.stages)
            if (st.name == name) return st;
        return Stage{name, 0.0};
    };

    // [degenerate_faces]
    {
        Check c = makeCheck("degenerate_faces", "no degenerate (zero-area) triangles", stage("degenerate"));
        for (uint32_t t : topo.index_degenerate_triangles) {
            if (c.worst.size() >= max_off) break;
            c.worst.push_back({triangleCentroid(mesh, t), NAN, "triangle " + std::to_string(t) + " uses a vertex twice"});
        }
        for (uint32_t t : g.zero_area_triangles) {
            if (c.worst.size() >= max_off) break;
            c.worst.push_back({triangleCentroid(mesh, t), NAN, "triangle " + std::to_string(t) + " has three collinear corners"});
        }
        finish(c, int64_t(topo.index_degenerate_triangles.size() + g.zero_area_triangles.size()));
        if (!finite) {
            c.status = topo.index_degenerate_triangles.empty() ? CheckStatus::Skipped : CheckStatus::Fail;
            c.note = "zero-area test skipped: non-finite coordinates";
        }
        r.checks.push_back(std::move(c));
    }

    // [self_intersections]
    {
        Check c = makeCheck("self_intersections", "no self-intersections", stage("self_intersections"));
        if (!finite) {
            c.note = "skipped: non-finite coordinates";
        } else if (!g.self_intersections_requested) {
            c.note = "skipped on request (" + plural(int64_t(mesh.triangles.size()), "triangle", "triangles") +
                     "); run tsf verify to test them";
        } else if (!g.mesh_built) {
            c.note = "skipped: CGAL could not build a polygon mesh from the triangles";
        } else {
            for (size_t i = 0; i < g.intersecting_pairs.size() && c.worst.size() < max_off; ++i) {
                const auto& [a, b] = g.intersecting_pairs[i];
                c.worst.push_back({g.intersection_points[i], NAN,
                                   "triangles " + std::to_string(a) + " and " + std::to_string(b) + " intersect"});
            }
            finish(c, int64_t(g.intersecting_pair_count));
            if (c.count) c.note = plural(c.count, "pair", "pairs") + " of intersecting triangles";
            if (g.soup_repaired)
                c.note += std::string(c.note.empty() ? "" : "; ") + "tested on a re-oriented copy (" +
                          plural(int64_t(g.points_duplicated), "vertex", "vertices") + " split at non-manifold places)";
            if (!exact_fallback_reason.empty())
                c.note += std::string(c.note.empty() ? "" : "; ") + "decided with the exact kernel (the filtered one stopped: " +
                          exact_fallback_reason + ")";
        }
        r.checks.push_back(std::move(c));
    }

    // [outward_orientation]
    {
        Check c = makeCheck("outward_orientation", "normals point outward (positive volume)", stage("volume"));
        c.unit = "mm^3";
        if (!g.volumes_computed) {
            c.note = "skipped: needs a closed, manifold, consistently oriented mesh";
        } else {
            s.volume_mm3 = g.volume_mm3;
            int64_t inward = 0;
            for (size_t i = 0; i < topo.components.size(); ++i) {
                const double v = g.component_volume_mm3[i];
                if (g.component_volume_sign[i] > 0) continue;
                ++inward;
                if (c.worst.size() < max_off)
                    c.worst.push_back({detail::boundsCentre(topo.components[i].bounds), v,
                                       "piece of " + plural(int64_t(topo.components[i].triangles.size()), "triangle", "triangles") +
                                           " has volume " + fmtNum(v) + " mm^3 (inside out, or the inner wall of a cavity)"});
            }
            finish(c, inward);
            c.note = "volume " + fmtNum(g.volume_mm3) + " mm^3";
        }
        r.checks.push_back(std::move(c));
    }

    r.closed_oriented_manifold = topo.isClosedOrientedManifold();
    r.grid = std::move(own_grid);
    return r;
}

}  // namespace tsf
