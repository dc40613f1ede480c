// The halves checked as a pair. See halves_check.h.
#include "verify/halves_check.h"

#include <algorithm>
#include <cmath>

#include "gen/model/features/bottom_hole_ring.h"
#include "gen/model/features/halves.h"
#include "gen/mesh/halves_mesh.h"
#include "verify/detail/format.h"
#include "verify/triangle_bvh.h"
#include "verify/triangle_samples.h"

namespace tsf {
namespace {

using detail::fmtMm;

// The triangles of a half in the model frame that are neither on its cut
// face nor in a pin hole. `to_model` moves a printed vertex back.
template <class F>
Mesh outerSurface(const Mesh& half, const Scene& s, F to_model) {
    const auto centres = holeCentresMm(s);
    const double hole_r = s.halves->pins.hole_vertex_radius_mm + kXYSnapMm;
    auto inHole = [&](const Vec3& p) {
        if (p.z > s.zMm(s.halves->hole_apex_units) + kXYSnapMm) return false;
        for (const auto& c : centres)
            if (std::hypot(p.x - c.first, p.y - c.second) <= hole_r) return true;
        return false;
    };
    Mesh out;
    out.positions.reserve(half.positions.size());
    for (const Vec3& p : half.positions) out.positions.push_back(to_model(p));
    for (const auto& t : half.triangles) {
        const Vec3 &a = half.positions[t[0]], &b = half.positions[t[1]], &c = half.positions[t[2]];
        const bool on_cut = std::max({a.z, b.z, c.z}) <= kXYSnapMm / 2;
        if (on_cut || (inHole(a) && inHole(b) && inHole(c))) continue;
        out.triangles.push_back(t);
    }
    return out;
}

Mesh concat(const Mesh& a, const Mesh& b) {
    Mesh m = a;
    const uint32_t base = uint32_t(a.positions.size());
    m.positions.insert(m.positions.end(), b.positions.begin(), b.positions.end());
    for (const auto& t : b.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    return m;
}

// Largest distance from samples of `from`'s triangles to `to`.
double largestDistance(const Mesh& from, const Mesh& to, double radius_mm, size_t& samples, Vec3& worst) {
    const TriangleBvh bvh(to);
    double largest = 0;
    std::vector<Vec3> pts;
    int64_t hint = -1;
    for (const auto& t : from.triangles) {
        pts.clear();
        sampleTriangle(from.positions[t[0]], from.positions[t[1]], from.positions[t[2]], radius_mm, pts);
        for (const Vec3& p : pts) {
            const ClosestPoint c = bvh.closest(p, hint, largest);
            hint = c.triangle;
            ++samples;
            if (c.distance_mm > largest) {
                largest = c.distance_mm;
                worst = p;
            }
        }
    }
    return largest;
}

Check makeCheck(const char* id, const char* title, bool ok, const std::string& note) {
    Check c;
    c.id = id;
    c.title = title;
    c.status = ok ? CheckStatus::Pass : CheckStatus::Fail;
    c.count = ok ? 0 : 1;
    c.note = note;
    c.stage = "halves";
    return c;
}

}  // namespace

bool HalvesCheckResult::passed() const {
    return std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.status != CheckStatus::Fail; });
}

HalvesCheckResult checkHalves(const Scene& s, const Mesh& whole, const Mesh& upper, const Mesh& lower) {
    HalvesCheckResult r;
    HalvesJoinFigures& f = r.figures;
    const SceneHalves& h = *s.halves;

    const auto centres = holeCentresMm(s);
    r.checks.push_back(makeCheck("halves_one_way", "the halves join one way only", isChiralLayout(centres, 2 * kPinClearanceMm),
                                 std::to_string(centres.size()) + " pin holes; no rotation or reflection maps them onto "
                                 "themselves within " + fmtMm(2 * kPinClearanceMm) + " mm"));

    f.upper_volume_mm3 = signedVolume(upper);
    f.lower_volume_mm3 = signedVolume(lower);
    f.whole_volume_mm3 = signedVolume(whole);
    for (size_t n = 0; n < h.hole_centres.size(); ++n)
        f.holes_volume_mm3 +=
            2 * bottomHoleVolumeMm3(s, BottomHole{holeRing(s, n), h.hole_centres[n], h.hole_depth_units, h.hole_apex_units});
    f.volume_error_mm3 = f.upper_volume_mm3 + f.lower_volume_mm3 - (f.whole_volume_mm3 - f.holes_volume_mm3);
    // Float sums over the model's triangles: a relative 1e-9 of the volume.
    const double volume_tolerance = 1e-9 * std::max(1.0, std::fabs(f.whole_volume_mm3));
    r.checks.push_back(makeCheck("halves_volume", "upper + lower = whole model less the holes",
                                 std::fabs(f.volume_error_mm3) <= volume_tolerance,
                                 fmtMm(f.upper_volume_mm3) + " + " + fmtMm(f.lower_volume_mm3) + " mm^3 vs " +
                                     fmtMm(f.whole_volume_mm3) + " - " + fmtMm(f.holes_volume_mm3) +
                                     " mm^3 (difference " + detail::fmtNum(f.volume_error_mm3) + " mm^3)"));

    const double cut = s.zMm(h.split_units);
    const Mesh up = outerSurface(upper, s, [&](const Vec3& p) { return Vec3{p.x, p.y, p.z + cut}; });
    // The printed lower half turned back is halfScene's frame, z reflected about the cut.
    const Mesh lower_scene_frame = turnLowerHalf(lower, s);
    Mesh down = outerSurface(lower_scene_frame, s, [&](const Vec3& p) { return Vec3{p.x, p.y, cut - p.z}; });
    for (auto& t : down.triangles) std::swap(t[1], t[2]);
    const Mesh joined = concat(up, down);
    const double radius = s.pitch_mm / 4;
    Vec3 worst_a{}, worst_b{};
    const double a = largestDistance(joined, whole, radius, f.samples, worst_a);
    const double b = largestDistance(whole, joined, radius, f.samples, worst_b);
    f.max_distance_mm = std::max(a, b);
    Check surf = makeCheck("halves_surface", "the halves joined have the whole model's surface",
                           f.max_distance_mm <= kHalvesSurfaceToleranceMm,
                           "largest distance " + detail::fmtNum(a) + " mm (halves to model) / " + detail::fmtNum(b) +
                               " mm (model to halves) over " + std::to_string(f.samples) + " samples; tolerance " +
                               fmtMm(kHalvesSurfaceToleranceMm) + " mm");
    if (surf.status == CheckStatus::Fail) surf.worst.push_back({a >= b ? worst_a : worst_b, f.max_distance_mm, "farthest sample"});
    surf.unit = "mm";
    r.checks.push_back(std::move(surf));
    return r;
}

}  // namespace tsf
