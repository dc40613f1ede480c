// checkPrintability: rays along triangle normals, and the bed. See printability.h.
#include "verify/printability.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <optional>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "verify/mesh_topology.h"
#include "verify/overhang.h"
#include "verify/detail/concurrent_union_find.h"
#include "verify/detail/flat_planes.h"
#include "verify/detail/format.h"
#include "gen/util/workers.h"

namespace tsf {
namespace {

using detail::fmtMm;

// A triangle is "steep" (a wall) when its normal is closer to horizontal than
// to vertical: |n_z| < sin(30 deg) = 1/2.
constexpr double kSteepNormalZ = 0.5;
// Gap rays look this many nozzle widths far: a gap wider than that prints
// whatever the nozzle, and rays that leave the model would otherwise cross it
// entirely (most of the cost).
constexpr double kGapSearchNozzles = 10.0;
// Material rays look this many nozzle widths far, then, if no wall was
// found that near, as far as gap rays, then to the far side; when the mesh
// has no face that slopes (neither steep nor exactly flat). A horizontal ray
// meets no flat face (see verify/column_grid.h), so its first hit is then a
// steep face, which wallWidth takes as it is, and a ray with nothing within
// the search measures a wall wider than it, whatever lies beyond: the walls
// under the nozzle, the samples and the thinnest wall are the same as with
// one unbounded ray. Through a model of merged pillars the unbounded ray
// crosses the solid to its far side (12 of the 15 s this check took on a
// 1000 x 1000 model). With sloped faces the far hit may be a tilted top
// whose rim is re-measured, so the ray is unbounded there.
constexpr double kMaterialSearchNozzles[] = {2.0, kGapSearchNozzles};

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// True when the triangle certainly has area: its normal is far longer than
// the rounding of its computation (a relative 1e-12 of the edges' product,
// where rounding is below 1e-15). False means "ask the exact predicate".
bool clearlyHasArea(const Vec3& a, const Vec3& b, const Vec3& c) {
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const double n2 = nx * nx + ny * ny + nz * nz;
    const double scale2 = (ux * ux + uy * uy + uz * uz) * (vx * vx + vy * vy + vz * vz);
    return n2 > 1e-24 * scale2;
}

// Joins the triangles of each planar region in `regions`: neighbours across
// an edge when the far corner of one lies exactly in the plane of the other
// (exact predicate) and they face the same way. On the worker threads, a
// contiguous range of triangles each: the sets, and their roots (each set's
// smallest member), are the same as on one thread.
void joinCoplanarNeighbours(const Mesh& mesh, detail::ConcurrentUnionFind& regions) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    const size_t nt = mesh.triangles.size();
    auto P = [&](uint32_t v) {
        const Vec3& p = mesh.positions[v];
        return K::Point_3(p.x, p.y, p.z);
    };
    // A consistently oriented neighbour across a -> b runs b -> a: a corner
    // at b whose next vertex is a, among b's few corners.
    const VertexCorners at = cornersByVertex(mesh);
    auto nextVertex = [&](uint32_t corner) { return mesh.triangles[corner / 3][(corner % 3 + 1) % 3]; };
    const unsigned workers = nt < 20000 ? 1u : detail::workerCount(0);
    detail::runOnWorkers(workers, [&](unsigned w, const auto&) {
        for (uint32_t t = uint32_t(nt * w / workers); t < uint32_t(nt * (w + 1) / workers); ++t) {
            const auto& tri = mesh.triangles[t];
            for (int s = 0; s < 3; ++s) {
                const uint32_t a = tri[s], b = tri[(s + 1) % 3], c = tri[(s + 2) % 3];
                uint32_t other_t = UINT32_MAX;  // the triangle with b -> a (on a manifold mesh, at most one)
                for (uint32_t i = at.start[b]; i < at.start[b + 1]; ++i)
                    if (nextVertex(at.list[i]) == a) other_t = std::min(other_t, at.list[i] / 3);
                if (other_t == UINT32_MAX || other_t <= t) continue;  // each pair once
                const auto& other = mesh.triangles[other_t];
                uint32_t d = other[0];
                for (uint32_t v : other)
                    if (v != a && v != b) d = v;
                // Coplanar, and on opposite sides of the shared edge (same facing).
                const Vec3 &qa = mesh.positions[a], &qb = mesh.positions[b], &qc = mesh.positions[c],
                           &qd = mesh.positions[d];
                // Nearly every edge of a terrain model joins two coplanar
                // triangles in an axis or vertical plane: decided from
                // coordinates (CGAL's filtered orientation decides a coplanar
                // quadruple only after falling back to exact arithmetic).
                const std::optional<bool> in_plane = detail::flat::inPlaneOf(qa, qb, qc, qd);
                if (in_plane ? !*in_plane : CGAL::orientation(P(a), P(b), P(c), P(d)) != CGAL::COPLANAR) continue;
                const K::Point_3 pa = P(a), pb = P(b), pc = P(c), pd = P(d);
                if (!clearlyHasArea(qa, qb, qc) && CGAL::collinear(pa, pb, pc)) continue;
                if (!clearlyHasArea(qa, qb, qd) && CGAL::collinear(pa, pb, pd)) continue;
                const K::Vector_3 n = CGAL::cross_product(pb - pa, pc - pa);
                const K::Vector_3 e = CGAL::cross_product(n, pb - pa);  // in-plane, towards c's side
                if ((e * (pc - pa) > 0) == (e * (pd - pa) > 0)) continue;  // folded onto itself
                regions.unite(t, other_t);
            }
        }
    });
}

// One triangle per planar region (joinCoplanarNeighbours). The
// representative is the region's largest triangle; its centroid is where the
// region is sampled. A tsf model has one region per hexagonal top and one per
// wall between two cells, so this cuts the rays several times without losing
// a feature.
std::vector<uint32_t> planarRegionRepresentatives(const Mesh& mesh) {
    const size_t nt = mesh.triangles.size();
    detail::ConcurrentUnionFind regions(nt);
    joinCoplanarNeighbours(mesh, regions);
    std::vector<double> best_area(nt, -1.0);
    std::vector<uint32_t> best(nt, 0);
    // A region's largest triangle, the first in index order among equals:
    // each thread takes a run of triangles and keeps the best of the regions
    // whose root (the smallest member) lies in its run; a triangle of a
    // region rooted in an earlier run is set aside and weighed after, run by
    // run, so every region sees its triangles in index order as on one thread.
    struct SetAside {
        uint32_t root, t;
        double area2;
    };
    auto take = [&](uint32_t r, uint32_t t, double area2) {
        if (area2 > best_area[r]) {
            best_area[r] = area2;
            best[r] = t;
        }
    };
    const unsigned workers = detail::workerCount(0);
    std::vector<std::vector<SetAside>> set_aside(workers);
    std::vector<std::vector<uint32_t>> found(workers);
    detail::runOnRanges(workers, nt, [&](unsigned w, size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t) {
            const auto& tri = mesh.triangles[t];
            const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
            const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
            const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
            const double area2 = nx * nx + ny * ny + nz * nz;
            const uint32_t r = regions.find(uint32_t(t));
            if (r >= begin) take(r, uint32_t(t), area2);
            else set_aside[w].push_back({r, uint32_t(t), area2});
        }
    });
    for (const auto& list : set_aside)
        for (const SetAside& s : list) take(s.root, s.t, s.area2);
    detail::runOnRanges(workers, nt, [&](unsigned w, size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t)
            if (regions.find(uint32_t(t)) == t && best_area[t] > 0) found[w].push_back(best[t]);
    });
    std::vector<uint32_t> out;
    for (const auto& part : found) out.insert(out.end(), part.begin(), part.end());
    return out;
}

/// z of the outward unit normal of a mesh triangle (`sign` -1 on an
/// inside-out mesh).
double faceNormalZ(const Mesh& mesh, uint32_t t, double sign) {
    const auto& tri = mesh.triangles[t];
    const Vec3& a = mesh.positions[tri[0]];
    const Vec3 n = cross(sub(mesh.positions[tri[1]], a), sub(mesh.positions[tri[2]], a));
    const double len = std::sqrt(dot(n, n));
    return len > 0 ? sign * n.z / len : 0.0;
}

/// How far beside a wall the vertical probes start (mm): far below any
/// feature a printer makes, far above float32's rounding at model sizes.
constexpr double kProbeOffsetMm = 1e-3;

/// Where a wall face ends above and below a sample (mm): wallWidth's
/// vertical probes, the same for the material and for the gap, found once.
struct WallEnds {
    bool found = false;
    double top = 0, bottom = 0;
};

/// The width of the material behind a steep triangle (`material`: along
/// -normal) or of the gap in front of it (along the normal), measured where a
/// printer draws the wall, from `at` (the centroid):
///   - when the ray leaves through a face that looks up or down, the material
///     (or the gap) narrows toward the wall's top or bottom: under a tilted
///     top's rim it is a wedge, thinner than any nozzle at its very edge. The
///     layer at that end is that layer's rounding, so a vertical wall is
///     measured a layer in from that end (found by vertical probes beside the
///     wall, on both sides, into `ends` on the first call for a sample and
///     read from it on the second);
///   - a wall face less than a layer tall at this place is one layer's step,
///     not a wall a printer draws, and is not measured;
///   - otherwise (the far side is a wall too: a slab, as thin everywhere) the
///     first width stands.
/// nullopt when nothing was hit (within max_mm) or the wall is not drawn;
/// +inf when nothing was hit within max_mm and `beyond_is_wider` (see
/// kMaterialSearchNozzles: the wall is wider than max_mm).
std::optional<double> wallWidth(const ColumnGrid& caster, const Mesh& mesh, double sign, uint32_t t, const Vec3& at,
                                const Vec3& n, bool material, const PrintabilityOptions& o, WallEnds& ends,
                                double max_mm = std::numeric_limits<double>::infinity(), bool beyond_is_wider = false) {
    const Vec3 dir = material ? Vec3{-n.x, -n.y, -n.z} : n;
    const auto hit = caster.firstHit(at, dir, int64_t(t), max_mm);
    if (!hit) return beyond_is_wider ? std::optional<double>(std::numeric_limits<double>::infinity()) : std::nullopt;
    const double nz = faceNormalZ(mesh, hit->triangle, sign);
    const bool narrows = std::fabs(nz) >= kSteepNormalZ && std::fabs(n.z) < 1e-9;
    if (!narrows && hit->distance_mm >= o.nozzle_mm) return hit->distance_mm;
    // Where the wall face ends above and below this place: the nearer end on
    // either side of it.
    if (!ends.found) {
        const double inf = std::numeric_limits<double>::infinity();
        ends = {true, inf, -inf};
        for (const double side : {-1.0, 1.0}) {
            const Vec3 p{at.x + side * kProbeOffsetMm * n.x, at.y + side * kProbeOffsetMm * n.y, at.z};
            if (const auto up = caster.firstHit(p, {0, 0, 1}, int64_t(t))) ends.top = std::min(ends.top, p.z + up->distance_mm);
            if (const auto down = caster.firstHit(p, {0, 0, -1}, int64_t(t)))
                ends.bottom = std::max(ends.bottom, p.z - down->distance_mm);
        }
    }
    const double top = ends.top, bottom = ends.bottom;
    if (top - bottom < o.layer_mm) return std::nullopt;
    if (!narrows) return hit->distance_mm;
    // Material under a face that looks up narrows upward; a gap over it narrows downward.
    const bool narrows_up = (nz > 0) == material;
    const double z = narrows_up ? top - o.layer_mm : bottom + o.layer_mm;
    // From just off the wall's plane (this place may lie on another triangle
    // of the same wall), along the ray.
    const Vec3 from{at.x + kProbeOffsetMm * dir.x, at.y + kProbeOffsetMm * dir.y, z};
    const auto again = caster.firstHit(from, dir, int64_t(t), max_mm);
    return again ? std::optional<double>(again->distance_mm + kProbeOffsetMm) : std::nullopt;
}

// A ray's length from the centroid of `triangle` (where the ray starts; the
// offenders list it). 16 bytes: a 1000 x 1000 model has 5 million of them.
struct Sample {
    double distance_mm;
    uint32_t triangle;
};

Check thinnest(const Mesh& mesh, const char* id, const char* title, std::vector<Sample>& samples, double limit_mm,
               const char* what, const PrintabilityOptions& o, double& min_out) {
    Check c;
    c.id = id;
    c.title = title;
    c.unit = "mm";
    // The check needs the samples below the limit counted, the thinnest
    // few in order and the thinnest of all, not every sample in order: the
    // few are picked from the whole list (2.9 million wall samples on a
    // 1000 x 1000 model, where the three checks' sorts took 0.6 s on one
    // core). A
    // sample's distance is a number or +inf (nothing within the search),
    // never NaN.
    const auto thinner = [](const Sample& a, const Sample& b) {
        return a.distance_mm != b.distance_mm ? a.distance_mm < b.distance_mm : a.triangle < b.triangle;
    };
    const size_t below = size_t(std::count_if(samples.begin(), samples.end(),
                                              [&](const Sample& s) { return s.distance_mm < limit_mm; }));
    const size_t listed = std::min(below, o.max_offenders);
    std::partial_sort(samples.begin(), samples.begin() + ptrdiff_t(listed), samples.end(), thinner);
    min_out = samples.empty() ? std::numeric_limits<double>::quiet_NaN()
                              : (listed > 0 ? samples.front() : *std::min_element(samples.begin(), samples.end(), thinner))
                                    .distance_mm;
    c.count = int64_t(below);
    for (size_t k = 0; k < listed; ++k) {
        const Sample& s = samples[k];
        c.worst.push_back({triangleCentroid(mesh, s.triangle), s.distance_mm,
                           std::string(what) + " " + fmtMm(s.distance_mm) + " mm (triangle " +
                               std::to_string(s.triangle) + ")"});
    }
    c.status = c.count == 0 ? CheckStatus::Pass : (o.fail_on_warnings ? CheckStatus::Fail : CheckStatus::Warn);
    c.note = samples.empty() ? std::string("nothing to measure")
                             : "thinnest " + fmtMm(min_out) + " mm over " + std::to_string(samples.size()) +
                                   " samples; limit " + fmtMm(limit_mm) + " mm";
    return c;
}

}  // namespace

PrintabilityResult checkPrintability(const Mesh& mesh, bool closed_oriented, const ColumnGrid& caster,
                                     const PrintabilityOptions& o) {
    PrintabilityResult r;
    PrintabilityFigures& f = r.figures;
    f.nozzle_mm = o.nozzle_mm;
    f.layer_mm = o.layer_mm;
    f.bed_mm = o.bed_mm;
    const double nan = std::numeric_limits<double>::quiet_NaN();
    f.min_wall_mm = f.min_gap_mm = f.min_slab_mm = nan;

    const auto t0 = std::chrono::steady_clock::now();
    std::vector<Check> ray_checks;
    if (closed_oriented) {
        // Inside is where the normals point away from; an inside-out mesh
        // (negative volume) has it the other way round.
        const double sign = signedVolume(mesh) < 0 ? -1.0 : 1.0;
        const double gap_search_mm = kGapSearchNozzles * o.nozzle_mm;
        // The regions in contiguous chunks, one per thread, their samples
        // joined in chunk order: the same lists as one thread makes.
        const std::vector<uint32_t> regions = planarRegionRepresentatives(mesh);
        bool sloped = false;  // a face neither steep nor exactly flat
        for (const auto& q : mesh.triangles) {
            const Vec3 &a = mesh.positions[q[0]], &b = mesh.positions[q[1]], &c = mesh.positions[q[2]];
            if (a.z == b.z && b.z == c.z) continue;
            const Vec3 n = cross(sub(b, a), sub(c, a));
            const double len = std::sqrt(dot(n, n));
            if (len > 0 && std::fabs(n.z) >= kSteepNormalZ * len) {
                sloped = true;
                break;
            }
        }
        const double inf = std::numeric_limits<double>::infinity();
        std::vector<double> searches;  // the material rays' lengths, in turn (mm)
        if (!sloped)
            for (const double nozzles : kMaterialSearchNozzles) searches.push_back(nozzles * o.nozzle_mm);
        searches.push_back(inf);
        double material_search_mm = searches.front();
        bool walls_only = false;  // a search again: the gaps and slabs are measured
        struct Samples {
            std::vector<Sample> walls, gaps, slabs;
        };
        const unsigned workers = detail::workerCount(0);
        std::vector<Samples> parts(workers);
        auto measure = [&](unsigned w) {
            Samples& out = parts[w];
            const size_t begin = regions.size() * w / workers, end = regions.size() * (w + 1) / workers;
            for (size_t i = begin; i < end; ++i) {
                const uint32_t t = regions[i];
                const auto& tri = mesh.triangles[t];
                const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
                const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
                const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
                Vec3 n{uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx};
                const double len = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
                if (!(len > 0)) continue;
                n = {sign * n.x / len, sign * n.y / len, sign * n.z / len};
                const Vec3 centroid{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3};
                const Vec3 inward{-n.x, -n.y, -n.z};
                const bool steep = std::fabs(n.z) < kSteepNormalZ;
                if (!steep) {
                    if (walls_only) continue;
                    if (const auto hit = caster.firstHit(centroid, inward, int64_t(t)))
                        out.slabs.push_back({hit->distance_mm, t});
                    continue;
                }
                WallEnds ends;  // shared by the material and the gap
                if (const auto d = wallWidth(caster, mesh, sign, t, centroid, n, true, o, ends, material_search_mm, !sloped))
                    out.walls.push_back({*d, t});
                if (walls_only) continue;
                if (const auto d = wallWidth(caster, mesh, sign, t, centroid, n, false, o, ends, gap_search_mm))
                    out.gaps.push_back({*d, t});
            }
        };
        std::vector<Sample> walls, gaps, slabs;
        auto measureAll = [&] {
            detail::runOnWorkers(workers, [&](unsigned w, const auto&) { measure(w); });
            walls.clear();
            for (Samples& p : parts) {
                walls.insert(walls.end(), p.walls.begin(), p.walls.end());
                gaps.insert(gaps.end(), p.gaps.begin(), p.gaps.end());
                slabs.insert(slabs.end(), p.slabs.begin(), p.slabs.end());
                p = Samples{};
            }
        };
        measureAll();
        // Every wall wider than the search: measured again further, for the
        // thinnest wall's figure (cells of a millimetre or more).
        for (size_t k = 1; k < searches.size(); ++k) {
            if (walls.empty() || std::any_of(walls.begin(), walls.end(), [](const Sample& s) { return std::isfinite(s.distance_mm); }))
                break;
            material_search_mm = searches[k];
            walls_only = true;
            measureAll();
        }
        std::vector<Samples>().swap(parts);
        ray_checks.push_back(thinnest(mesh, "wall_thickness", "walls at least a nozzle wide", walls, o.nozzle_mm,
                                      "material only", o, f.min_wall_mm));
        ray_checks.push_back(thinnest(mesh, "gap_width", "gaps at least a nozzle wide", gaps, o.nozzle_mm, "gap only", o,
                                      f.min_gap_mm));
        if (gaps.empty()) ray_checks.back().note = "no gap narrower than " + fmtMm(gap_search_mm) + " mm";
        ray_checks.push_back(thinnest(mesh, "base_thickness", "base at least two layers thick", slabs, 2 * o.layer_mm,
                                      "slab only", o, f.min_slab_mm));
    } else {
        for (const char* id : {"wall_thickness", "gap_width", "base_thickness"}) {
            Check c;
            c.id = id;
            c.title = id;
            c.status = CheckStatus::Skipped;
            c.note = "skipped: needs a closed, manifold, consistently oriented mesh";
            ray_checks.push_back(std::move(c));
        }
        ray_checks[0].title = "walls at least a nozzle wide";
        ray_checks[1].title = "gaps at least a nozzle wide";
        ray_checks[2].title = "base at least two layers thick";
    }
    const Stage rays{"printability_rays", msSince(t0)};
    r.stages.push_back(rays);
    for (Check& c : ray_checks) {
        c.stage = rays.name;
        c.time_ms = rays.time_ms;
        r.checks.push_back(std::move(c));
    }

    Check over;
    over.id = "overhang";
    over.title = "no overhang steeper than 45 degrees (prints without supports)";
    over.unit = "mm";
    over.stage = "bed";
    if (!closed_oriented) {
        over.status = CheckStatus::Skipped;
        over.note = "skipped: needs a closed, manifold, consistently oriented mesh";
    } else {
        const OverhangFigures oh = measureOverhang(mesh);
        f.overhang_area_mm2 = oh.area_mm2;
        f.overhang_max_height_mm = oh.max_height_mm;
        if (oh.triangles == 0) {
            over.status = CheckStatus::Pass;
            over.note = "nothing overhangs";
        } else {
            over.count = oh.triangles;
            over.status = o.fail_on_warnings ? CheckStatus::Fail : CheckStatus::Warn;
            over.note = fmtMm(oh.area_mm2) + " mm^2 overhangs up to " + fmtMm(oh.max_height_mm) +
                        " mm above the bed: supports needed";
            over.worst.push_back({oh.worst_mm, oh.max_height_mm, "the highest overhang"});
        }
    }
    r.checks.push_back(std::move(over));

    Check bed;
    bed.id = "fits_bed";
    bed.title = "fits the print bed";
    bed.unit = "mm";
    if (!o.bed_mm) {
        bed.status = CheckStatus::Skipped;
        bed.note = "no bed size given";
    } else {
        const Bounds bb = meshBounds(mesh);
        const Vec3 size{bb.max.x - bb.min.x, bb.max.y - bb.min.y, bb.max.z - bb.min.z};
        const Vec3& bs = *o.bed_mm;
        const bool z_ok = size.z <= bs.z;
        f.fits_bed = z_ok && size.x <= bs.x && size.y <= bs.y;
        f.fits_bed_rotated = !f.fits_bed && z_ok && size.y <= bs.x && size.x <= bs.y;
        const std::string dims = fmtMm(size.x) + " x " + fmtMm(size.y) + " x " + fmtMm(size.z) + " mm on a " +
                                 fmtMm(bs.x) + " x " + fmtMm(bs.y) + " x " + fmtMm(bs.z) + " mm bed";
        if (f.fits_bed || f.fits_bed_rotated) {
            bed.status = CheckStatus::Pass;
            bed.note = dims + (f.fits_bed_rotated ? " (turned by 90 degrees)" : "");
        } else {
            bed.count = 1;
            bed.status = o.fail_on_warnings ? CheckStatus::Fail : CheckStatus::Warn;
            bed.note = dims + ": too large";
            const double excess = std::max({size.x - bs.x, size.y - bs.y, size.z - bs.z});
            bed.worst.push_back({bb.max, excess, "the far corner of the model; " + fmtMm(excess) + " mm over the bed"});
        }
    }
    bed.stage = "bed";
    r.checks.push_back(std::move(bed));
    return r;
}

}  // namespace tsf
