// compareMeshes: exact surface comparison, then sampled distances where it
// could not prove 0, then volumes. See agreement.h.
#include "verify/agreement.h"

#include <algorithm>
#include <array>
#include <bit>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <unordered_set>

#include "gen/util/error.h"
#include "verify/triangle_bvh.h"
#include "verify/detail/format.h"
#include "verify/surface_chains.h"
#include "verify/triangle_samples.h"

namespace tsf {
namespace {

using detail::fmtNum;
using detail::fmtPoint;

// Samples per unit area for radius r, to first order: rows sqrt(3)/2 r apart,
// points r apart along them (triangle_samples.h): 2 / (sqrt(3) r^2).
constexpr double kSamplesPerAreaTimesR2 = 1.1547005383792515;
// How far the radius search overshoots the budget's estimate on each step;
// the count is close to its estimate, so a few steps suffice.
constexpr double kRadiusGrowth = 1.05;
constexpr int kMaxRadiusSteps = 60;
// A rounded comparison is used only if the rounding moved the two meshes'
// vertices by at most this share of the tolerance in all (the rest is left
// for what sampling adds); the grid is chosen to meet it.
constexpr double kRoundingShareOfTolerance = 0.5;
// Safety factor on a distance computed with one rounding (hypot is accurate
// to 1 ulp), so that a bound derived from it is a bound.
constexpr double kNormRoundingPad = 1.0 + 4 * std::numeric_limits<double>::epsilon();

// A rounding of coordinates applied to both meshes before comparing again.
struct Rounding {
    std::string name;
    double (*round)(double v, double grid_mm);
    double grid_mm;  // 0 for float32
};
double toFloat32(double v, double) { return double(float(v)); }
double toGrid(double v, double grid_mm) { return std::nearbyint(v / grid_mm) * grid_mm; }  // grid: a power of 2, exact

// float32 first (a binary STL of the other mesh is exactly that), then the
// coarsest power-of-two grid whose rounding (at most grid * sqrt(3) / 2 per
// vertex, two meshes) stays within kRoundingShareOfTolerance of the tolerance.
std::vector<Rounding> roundings(double tolerance_mm) {
    std::vector<Rounding> out{{"float32", &toFloat32, 0.0}};
    if (tolerance_mm > 0 && std::isfinite(tolerance_mm)) {
        const double grid = std::exp2(std::floor(std::log2(kRoundingShareOfTolerance * tolerance_mm / std::sqrt(3.0))));
        out.push_back({"a " + detail::fmtNum(grid) + " mm grid", &toGrid, grid});
    }
    return out;
}

Mesh roundedCopy(const Mesh& m, const Rounding& r) {
    Mesh out = m;
    for (Vec3& p : out.positions) p = {r.round(p.x, r.grid_mm), r.round(p.y, r.grid_mm), r.round(p.z, r.grid_mm)};
    return out;
}

// Largest distance a vertex moved (an upper bound: padded for the rounding of
// the norm). Every point of a triangle moves by at most its corners' largest
// move, so this bounds the distance between the two surfaces.
double largestMove(const Mesh& m, const Mesh& moved) {
    double worst = 0;
    for (size_t i = 0; i < m.positions.size(); ++i) {
        const Vec3 &p = m.positions[i], &q = moved.positions[i];
        worst = std::max(worst, std::hypot(q.x - p.x, q.y - p.y, q.z - p.z));  // differences exact (Sterbenz)
    }
    return worst * kNormRoundingPad;
}

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool usable(const Mesh& m, const std::array<uint32_t, 3>& t) {
    const size_t n = m.positions.size();
    return t[0] < n && t[1] < n && t[2] < n && t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
}

bool finiteMesh(const Mesh& m) {
    for (const Vec3& p : m.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return false;
    return true;
}

size_t usableCount(const Mesh& m) {
    size_t n = 0;
    for (const auto& t : m.triangles) n += usable(m, t);
    return n;
}

// One direction of the distance: from the triangles of `from` (those flagged)
// to the surface in `to_tree`.
struct Direction {
    const Mesh* from = nullptr;
    std::vector<uint8_t>* flags = nullptr;  // triangles to sample
    double max_mm = 0;                      // largest sampled distance
    double area_mm2 = 0;                    // flagged area
    struct Place {
        double distance_mm;
        Vec3 at_mm;
    };
    std::vector<Place> places;  // per sampled triangle: its farthest sample
    double rounded_bound_mm = 0;    // bound proven on triangles resolved by a rounded comparison
    std::vector<uint8_t> rounded;   // per triangle: resolved by a rounded comparison
    bool premise_broken = false;
    double premise_off_mm = 0;
    Vec3 premise_at_mm;
};

// The closest-point tree of a mesh, built on first use: the common case (two
// surfaces with the same vertices, proven identical) needs none.
class LazyTree {
public:
    explicit LazyTree(const Mesh& mesh) : mesh_(mesh) {}
    const TriangleBvh& get() {
        if (!tree_) tree_ = std::make_unique<TriangleBvh>(mesh_);
        return *tree_;
    }

private:
    const Mesh& mesh_;
    std::unique_ptr<TriangleBvh> tree_;
};

// The exact positions of the corners of a mesh's usable triangles (a corner
// of a triangle lies on the mesh's surface).
class CornerSet {
public:
    explicit CornerSet(const Mesh& m) {
        keys_.reserve(m.positions.size());
        std::vector<uint8_t> used(m.positions.size(), 0);
        for (const auto& t : m.triangles)
            if (usable(m, t)) used[t[0]] = used[t[1]] = used[t[2]] = 1;
        for (size_t i = 0; i < m.positions.size(); ++i)
            if (used[i]) keys_.insert(key(m.positions[i]));
    }
    bool contains(const Vec3& p) const { return keys_.count(key(p)) > 0; }

private:
    using Key = std::array<uint64_t, 3>;
    struct Hash {
        size_t operator()(const Key& k) const {
            uint64_t h = 0;
            for (uint64_t w : k) {
                h ^= w + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
                h = (h ^ (h >> 31)) * 0xbf58476d1ce4e5b9ULL;
            }
            return size_t(h);
        }
    };
    static uint64_t bits(double v) { return std::bit_cast<uint64_t>(v == 0 ? 0.0 : v); }  // -0 == +0
    static Key key(const Vec3& p) { return {bits(p.x), bits(p.y), bits(p.z)}; }
    std::unordered_set<Key, Hash> keys_;
};

// Measures every vertex of the unflagged triangles of `d.from`: each must lie
// on the other surface (the exact comparison says so). A vertex at exactly
// the position of one of the other mesh's corners does; the others are
// measured, and so is the centroid of each triangle matched only after
// rounding (few, and where noise and overlapping sheets show up together).
// One that is off breaks the comparison's premise (overlapping triangles),
// and then every triangle is flagged for sampling.
void checkPremise(Direction& d, const CornerSet& other_corners, LazyTree& to, double allowance_mm) {
    const Mesh& m = *d.from;
    std::vector<uint8_t> seen(m.positions.size(), 0);
    int64_t hint = -1;
    auto check = [&](const Vec3& p) {
        const ClosestPoint c = to.get().closest(p, hint, allowance_mm);
        hint = c.triangle;
        if (c.distance_mm > allowance_mm && c.distance_mm > d.premise_off_mm) {
            d.premise_broken = true;
            d.premise_off_mm = c.distance_mm;
            d.premise_at_mm = p;
        }
    };
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        if ((*d.flags)[t] || !usable(m, m.triangles[t])) continue;
        for (uint32_t v : m.triangles[t]) {
            if (seen[v]) continue;
            seen[v] = 1;
            if (other_corners.contains(m.positions[v])) continue;
            check(m.positions[v]);
        }
        if (t < d.rounded.size() && d.rounded[t]) {
            const auto& tri = m.triangles[t];
            const Vec3 &a = m.positions[tri[0]], &b = m.positions[tri[1]], &c = m.positions[tri[2]];
            check({(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3});
        }
    }
    if (d.premise_broken)
        for (size_t t = 0; t < m.triangles.size(); ++t) (*d.flags)[t] = usable(m, m.triangles[t]);
}

// The vertices of the flagged triangles, each once.
std::vector<uint32_t> flaggedVertices(const Direction& d) {
    const Mesh& m = *d.from;
    std::vector<uint8_t> seen(m.positions.size(), 0);
    std::vector<uint32_t> out;
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        if (!(*d.flags)[t]) continue;
        for (uint32_t v : m.triangles[t])
            if (!seen[v]) {
                seen[v] = 1;
                out.push_back(v);
            }
    }
    return out;
}

// Samples at radius r: every vertex of a flagged triangle once, and each
// flagged triangle's samples without its corners.
size_t sampleCount(const Direction& d, size_t vertices, double r) {
    const Mesh& m = *d.from;
    size_t n = vertices;
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        if (!(*d.flags)[t]) continue;
        const auto& tri = m.triangles[t];
        n += triangleSampleCount(m.positions[tri[0]], m.positions[tri[1]], m.positions[tri[2]], r, Corners::Omit);
    }
    return n;
}

// Longest edge of the flagged triangles: at a radius this long every triangle
// is covered by its corners alone (triangle_samples.h).
double longestFlaggedEdge(const Direction& d) {
    const Mesh& m = *d.from;
    double longest = 0;
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        if (!(*d.flags)[t]) continue;
        const auto& tri = m.triangles[t];
        for (int e = 0; e < 3; ++e) {
            const Vec3 &p = m.positions[tri[size_t(e)]], &q = m.positions[tri[size_t((e + 1) % 3)]];
            longest = std::max(longest, std::hypot(q.x - p.x, q.y - p.y, q.z - p.z));
        }
    }
    return longest;
}

// The smallest radius (not below `finest`) whose samples fit in `budget`, or
// the radius that samples the vertices only when even that does not fit.
double chooseRadius(const Direction& a, size_t a_vertices, const Direction& b, size_t b_vertices, double finest,
                    size_t budget) {
    const double area = a.area_mm2 + b.area_mm2;
    double r = std::max(finest, std::sqrt(kSamplesPerAreaTimesR2 * area / double(std::max<size_t>(budget, 1))));
    const double coarsest = std::max({longestFlaggedEdge(a), longestFlaggedEdge(b), finest});
    for (int step = 0; step < kMaxRadiusSteps && r < coarsest; ++step) {
        const size_t n = sampleCount(a, a_vertices, r) + sampleCount(b, b_vertices, r);
        if (n <= budget) return r;
        r *= std::max(kRadiusGrowth, std::sqrt(double(n) / double(budget)));
    }
    return std::min(r, coarsest);
}

// Measures the samples of `d` against `to`. A search stops early at the
// first triangle nearer than the largest distance so far, or than the
// tolerance (below which no place is listed): such a sample cannot change
// the figures, and the places above the tolerance stay exact.
void sampleDirection(Direction& d, const std::vector<uint32_t>& vertices, const TriangleBvh& to, double r,
                     double tolerance_mm, size_t& samples) {
    const Mesh& m = *d.from;
    std::vector<double> vertex_mm(m.positions.size(), 0.0);
    int64_t hint = -1;
    auto measure = [&](const Vec3& p) {
        const ClosestPoint c = to.closest(p, hint, std::min(d.max_mm, tolerance_mm));
        hint = c.triangle;
        d.max_mm = std::max(d.max_mm, c.distance_mm);
        ++samples;
        return c.distance_mm;
    };
    for (uint32_t v : vertices) vertex_mm[v] = measure(m.positions[v]);
    std::vector<Vec3> points;
    for (size_t t = 0; t < m.triangles.size(); ++t) {
        if (!(*d.flags)[t]) continue;
        const auto& tri = m.triangles[t];
        Direction::Place worst{-1, {}};
        for (uint32_t v : tri)
            if (vertex_mm[v] > worst.distance_mm) worst = {vertex_mm[v], m.positions[v]};
        points.clear();
        sampleTriangle(m.positions[tri[0]], m.positions[tri[1]], m.positions[tri[2]], r, points, Corners::Omit);
        for (const Vec3& p : points) {
            const double dist_mm = measure(p);
            if (dist_mm > worst.distance_mm) worst = {dist_mm, p};
        }
        d.places.push_back(worst);
    }
}

}  // namespace

AgreementResult compareMeshes(const Mesh& model, const Mesh& reference, const std::string& reference_name,
                              const AgreementOptions& options) {
    if (!(options.distance_tolerance_mm > 0 && std::isfinite(options.distance_tolerance_mm)))
        throw InputError("the distance tolerance must be a positive number of mm, got " +
                         fmtNum(options.distance_tolerance_mm));
    if (!(options.error_bound_mm >= 0 && std::isfinite(options.error_bound_mm)))
        throw InputError("the error bound must be 0 (automatic) or a positive number of mm, got " +
                         fmtNum(options.error_bound_mm));
    AgreementResult r;
    AgreementFigures& f = r.figures;
    f.reference = reference_name;
    f.reference_triangles = reference.triangleCount();
    f.distance_tolerance_mm = options.distance_tolerance_mm;
    f.sample_budget = options.sample_budget;
    f.volume_mm3 = signedVolume(model);
    f.reference_volume_mm3 = signedVolume(reference);
    f.volume_difference_mm3 = f.volume_mm3 - f.reference_volume_mm3;
    f.hausdorff_to_reference_mm = f.hausdorff_from_reference_mm = f.hausdorff_error_bound_mm = NAN;

    Check dist;
    dist.id = "reference_distance";
    dist.title = "same surface as the reference (Hausdorff distance)";
    dist.unit = "mm";
    Check vol;
    vol.id = "reference_volume";
    vol.title = "same volume as the reference";
    vol.unit = "mm^3";

    const bool finite = finiteMesh(model) && finiteMesh(reference);
    if (!finite || usableCount(model) == 0 || usableCount(reference) == 0) {
        dist.status = vol.status = CheckStatus::Fail;
        dist.count = vol.count = 1;
        dist.note = vol.note = finite ? "one of the meshes has no triangles" : "non-finite coordinates";
        r.checks = {dist, vol};
        return r;
    }

    // 1. Exact comparison.
    auto t0 = std::chrono::steady_clock::now();
    ChainComparison chains = compareSurfaceChains(model, reference, options.max_offenders);
    Direction to, from;
    to.from = &model;
    to.flags = &chains.model_differs;
    from.from = &reference;
    from.flags = &chains.reference_differs;
    f.surfaces_compared = chains.compared;
    f.planes = chains.planes;
    f.differing_planes = chains.differing_planes;
    f.opposite_planes = chains.opposite_planes;

    // 1b. Where they differ, compare again after rounding both meshes: a
    // triangle whose rounded copy lies on the other rounded surface is within
    // the two roundings' moves of the other surface (rounding to float32 is
    // what writing an STL does to the other mesh).
    auto flaggedCount = [&] {
        return size_t(std::count(chains.model_differs.begin(), chains.model_differs.end(), 1) +
                      std::count(chains.reference_differs.begin(), chains.reference_differs.end(), 1));
    };
    size_t rounded_resolved = 0;
    double rounded_bound_mm = 0;
    std::string rounded_to;
    if (flaggedCount() > 0) {  // also when the exact comparison could not run: a grid has few bits
        for (const Rounding& level : roundings(options.distance_tolerance_mm)) {
            const Mesh a = roundedCopy(model, level), b = roundedCopy(reference, level);
            const double bound = largestMove(model, a) + largestMove(reference, b);
            if (!(bound <= kRoundingShareOfTolerance * options.distance_tolerance_mm)) continue;
            const ChainComparison c = compareSurfaceChains(a, b, 0);
            if (!c.compared) continue;
            size_t resolved = 0;
            for (auto [mine, theirs, d] : {std::tuple{&chains.model_differs, &c.model_differs, &to},
                                           std::tuple{&chains.reference_differs, &c.reference_differs, &from}})
                for (size_t t = 0; t < mine->size(); ++t)
                    if ((*mine)[t] && !(*theirs)[t]) {
                        (*mine)[t] = 0;
                        d->rounded.resize(mine->size(), 0);
                        d->rounded[t] = 1;
                        d->rounded_bound_mm = std::max(d->rounded_bound_mm, bound);
                        ++resolved;
                    }
            if (resolved) {
                rounded_resolved += resolved;
                rounded_bound_mm = std::max(rounded_bound_mm, bound);
                rounded_to += (rounded_to.empty() ? "" : ", then ") + level.name;
            }
            if (flaggedCount() == 0) break;
        }
    }
    f.rounded_to = rounded_to;
    f.rounding_bound_mm = rounded_bound_mm;
    const Stage exact{"reference_exact", msSince(t0)};
    r.stages.push_back(exact);

    // 2. Distances where the exact comparison could not prove 0.
    t0 = std::chrono::steady_clock::now();
    LazyTree model_tree(model), reference_tree(reference);
    const double finest = options.error_bound_mm > 0 ? options.error_bound_mm
                                                     : options.distance_tolerance_mm * kHausdorffBoundFraction;
    // A vertex lying exactly on the other surface measures a little off it:
    // the closest point is rounded, by up to ~1e-10 mm next to the long
    // slivers of a fan-triangulated face. The finest sampling radius is far
    // above that and is as close as the sampling ever tells points apart. A
    // vertex of a triangle resolved after rounding may be off by the rounding.
    checkPremise(to, CornerSet(reference), reference_tree, finest + rounded_bound_mm);
    checkPremise(from, CornerSet(model), model_tree, finest + rounded_bound_mm);
    for (Direction* d : {&to, &from})
        for (size_t t = 0; t < d->from->triangles.size(); ++t)
            if ((*d->flags)[t]) d->area_mm2 += triangleArea(*d->from, d->from->triangles[t]);
    f.differing_area_mm2 = to.area_mm2;
    f.reference_differing_area_mm2 = from.area_mm2;

    const bool any_flagged = std::count(to.flags->begin(), to.flags->end(), 1) +
                                 std::count(from.flags->begin(), from.flags->end(), 1) >
                             0;
    f.surfaces_identical = chains.identical() && !to.premise_broken && !from.premise_broken;
    const std::vector<uint32_t> to_vertices = flaggedVertices(to), from_vertices = flaggedVertices(from);
    const double radius =
        any_flagged ? chooseRadius(to, to_vertices.size(), from, from_vertices.size(), finest, options.sample_budget)
                    : 0.0;
    if (any_flagged) {
        sampleDirection(to, to_vertices, reference_tree.get(), radius, options.distance_tolerance_mm, f.samples);
        sampleDirection(from, from_vertices, model_tree.get(), radius, options.distance_tolerance_mm, f.samples);
    }
    f.hausdorff_to_reference_mm = to.max_mm;
    f.hausdorff_from_reference_mm = from.max_mm;
    // true <= max(rounded bound, figure + r) <= figure + max(rounded bound, r)
    f.hausdorff_error_bound_mm = std::max(radius, rounded_bound_mm);
    const Stage distances{"reference_distances", msSince(t0)};
    r.stages.push_back(distances);

    // Verdict on the distance.
    const double tol = options.distance_tolerance_mm;
    const bool to_proven = std::max(to.rounded_bound_mm, to.max_mm + radius) <= tol;
    const bool from_proven = std::max(from.rounded_bound_mm, from.max_mm + radius) <= tol;
    const bool to_over = to.max_mm > tol, from_over = from.max_mm > tol;
    dist.stage = distances.name;
    dist.time_ms = exact.time_ms + distances.time_ms;
    if (to_proven && from_proven) {
        dist.status = CheckStatus::Pass;
    } else if (to_over || from_over) {
        dist.status = CheckStatus::Fail;
        dist.count = int64_t(to_over) + int64_t(from_over);
        // The farthest places, each direction's in turn, worst first.
        std::vector<std::pair<Direction::Place, bool>> worst;  // (place, from the model)
        for (const Direction::Place& p : to.places)
            if (p.distance_mm > tol) worst.push_back({p, true});
        for (const Direction::Place& p : from.places)
            if (p.distance_mm > tol) worst.push_back({p, false});
        std::sort(worst.begin(), worst.end(),
                  [](const auto& x, const auto& y) { return x.first.distance_mm > y.first.distance_mm; });
        for (const auto& [place, model_side] : worst) {
            // A plain reference: clang 14 does not let a lambda capture a structured binding.
            const Direction::Place& p = place;
            if (dist.worst.size() >= options.max_offenders) break;
            // Neighbouring triangles share their farthest corner: list a
            // place once (places closer than two sampling radii are one).
            const bool listed = std::any_of(dist.worst.begin(), dist.worst.end(), [&](const Offender& o) {
                return std::hypot(o.at_mm.x - p.at_mm.x, o.at_mm.y - p.at_mm.y, o.at_mm.z - p.at_mm.z) <= 2 * radius;
            });
            if (listed) continue;
            dist.worst.push_back({p.at_mm, p.distance_mm,
                                  model_side ? "this model is " + fmtNum(p.distance_mm) + " mm from the reference here"
                                             : "the reference is " + fmtNum(p.distance_mm) +
                                                   " mm from this model here"});
        }
    } else {
        dist.status = options.fail_on_warnings ? CheckStatus::Fail : CheckStatus::Warn;
        dist.count = int64_t(!to_proven) + int64_t(!from_proven);
        for (const Vec3& p : chains.difference_points)
            dist.worst.push_back({p, NAN, "the two surfaces differ here (exact comparison)"});
    }

    const std::string opposite =
        chains.opposite_planes ? " (facing the other way in " + std::to_string(chains.opposite_planes) + " of them)"
                               : "";
    if (chains.samePointSet() && !to.premise_broken && !from.premise_broken && !any_flagged) {
        dist.note = "identical surfaces: proven by exact comparison of " + std::to_string(chains.planes) + " planes" +
                    opposite + ", distance 0";
    } else {
        dist.note = !chains.compared         ? "no exact comparison (" + chains.note + ")"
                    : chains.differing_planes ? "the surfaces differ in " + std::to_string(chains.differing_planes) +
                                                    " of " + std::to_string(chains.planes) + " planes" + opposite
                                              : "the surfaces are the same" + opposite;
        if (rounded_resolved)
            dist.note += "; rounded to " + rounded_to + ", " + std::to_string(rounded_resolved) +
                         " triangles lie on the other surface: within " + fmtNum(rounded_bound_mm) + " mm";
        if (any_flagged)
            dist.note += "; sampled the rest (" + fmtNum(to.area_mm2) + " + " + fmtNum(from.area_mm2) +
                         " mm^2) at radius " + fmtNum(radius) + " mm: to reference " + fmtNum(to.max_mm) +
                         " mm, from reference " + fmtNum(from.max_mm) + " mm, true distance at most " +
                         fmtNum(radius) + " mm more, " + std::to_string(f.samples) + " samples";
        if (!(to_proven && from_proven) && !(to_over || from_over))
            dist.note += "; not proven within the tolerance: the sampling budget (" +
                         std::to_string(options.sample_budget) + ") allows radius " + fmtNum(radius) + " mm only";
    }
    dist.note += "; tolerance " + fmtNum(tol) + " mm";
    for (const Direction* d : {&to, &from})
        if (d->premise_broken)
            dist.note += std::string("; ") + (d == &to ? "this model" : "the reference") +
                         " has a point " + fmtNum(d->premise_off_mm) + " mm off the other surface at " +
                         fmtPoint(d->premise_at_mm) +
                         " although its plane matches (overlapping triangles?): sampled everywhere";

    // 3. Volumes.
    const double area = [&] {
        double a = 0;
        for (const auto& t : model.triangles)
            if (usable(model, t)) a += triangleArea(model, t);
        return a;
    }();
    f.volume_tolerance_mm3 = area * options.distance_tolerance_mm;
    vol.stage = exact.name;
    vol.time_ms = exact.time_ms;
    vol.count = std::fabs(f.volume_difference_mm3) <= f.volume_tolerance_mm3 ? 0 : 1;
    vol.status = vol.count ? CheckStatus::Fail : CheckStatus::Pass;
    vol.note = "volume " + fmtNum(f.volume_mm3) + " vs " + fmtNum(f.reference_volume_mm3) + " mm^3 (difference " +
               fmtNum(f.volume_difference_mm3) + ", tolerance " + fmtNum(f.volume_tolerance_mm3) + ")";
    if (vol.count) vol.worst.push_back({Vec3{NAN, NAN, NAN}, f.volume_difference_mm3, vol.note});
    r.checks = {dist, vol};
    return r;
}

}  // namespace tsf
