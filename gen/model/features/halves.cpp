// Support-free halves: the cut, the pin layout, the halves as Scenes. See halves.h.
#include "gen/model/features/halves.h"
#include "gen/model/features/bottom_hole_ring.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <sstream>

#include "gen/model/feature_registry.h"
#include "gen/model/scene.h"
#include "gen/util/error.h"

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;

// z units of a length, rounded up (a hole is never shallower than asked).
int64_t unitsUp(double mm, double z_snap_mm) { return int64_t(std::ceil(mm / z_snap_mm - 1e-9)); }

double distanceMm(const std::pair<double, double>& a, const std::pair<double, double>& b) {
    return std::hypot(a.first - b.first, a.second - b.second);
}

struct Candidate {
    int32_t kept;
    LatticePoint centre;
    double x_mm, y_mm;
};

// Kept data cells around which a hole fits: every cell whose hexagon can
// reach within `reach_mm` of the centre (centre distance up to reach_mm plus
// the circumradius) is kept and drawn as a plain hexagon (no mark face), so
// the disc of radius reach_mm lies inside the model and clear of the marks.
std::vector<Candidate> holeCandidates(const Scene& s, double reach_mm, double hole_mm, int64_t room_units) {
    const double circumradius = hexCircumradius(s.pitch_mm, s.y_scale);
    const double limit = reach_mm + circumradius;
    const int32_t rows = int32_t(std::ceil(limit / (s.pitch_mm * kSqrt3 / 2))) + 1;
    const int32_t cols = int32_t(std::ceil(limit / s.pitch_mm)) + 1;
    std::vector<Candidate> out;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.kind[k] != CellKind::Data) continue;
        const LatticePoint c = hexCentre(s.grid, s.col[k], s.row[k]);
        const double cx = latticeX(c, s.pitch_mm), cy = latticeY(c, s.pitch_mm, s.y_scale);
        bool clear = true;
        const int64_t cut = s.halves->split_units;
        for (int32_t dr = -rows; dr <= rows && clear; ++dr)
            for (int32_t dc = -cols; dc <= cols && clear; ++dc) {
                const int32_t nc = s.col[k] + dc, nr = s.row[k] + dr;
                const LatticePoint n = hexCentre(s.grid, nc, nr);
                const double d = std::hypot(latticeX(n, s.pitch_mm) - cx, latticeY(n, s.pitch_mm, s.y_scale) - cy);
                if (d > limit) continue;
                const int32_t other = s.keptAt(nc, nr);
                clear = other >= 0 && (s.drawn_by_face.empty() || !s.drawn_by_face[size_t(other)]);
                // A pillar the hole reaches into has room for it on both sides of the cut.
                if (clear && d <= hole_mm + circumradius)
                    clear = cut - s.bottom[size_t(other)] >= room_units && s.top[size_t(other)] - cut >= room_units;
            }
        if (clear) out.push_back({int32_t(k), c, cx, cy});
    }
    return out;
}

}  // namespace

PinGeometry pinGeometry() {
    PinGeometry g;
    g.hole_vertex_radius_mm = g.hole_radius_mm / std::cos(kPi / kHoleSides);
    g.cone_mm = kHoleConeRatio * g.hole_vertex_radius_mm;
    g.pin_length_mm = 2 * (g.hole_depth_mm - kPinClearanceMm);
    return g;
}

double halvesSlabMm() {
    const PinGeometry g = pinGeometry();
    return 2 * (g.hole_depth_mm + g.cone_mm + kHoleRoofMm);
}

int64_t halvesSlabUnits(double z_snap_mm) {
    const PinGeometry g = pinGeometry();
    // Rounded per side, so the cut at the slab's middle leaves each side its room.
    return 2 * (unitsUp(g.hole_depth_mm + g.cone_mm, z_snap_mm) + unitsUp(kHoleRoofMm, z_snap_mm));
}

bool isChiralLayout(const std::vector<std::pair<double, double>>& c, double tolerance_mm) {
    if (c.size() != 3) return false;
    const double d[3] = {distanceMm(c[0], c[1]), distanceMm(c[1], c[2]), distanceMm(c[2], c[0])};
    for (int a = 0; a < 3; ++a)
        if (std::fabs(d[a] - d[(a + 1) % 3]) <= 2 * tolerance_mm) return false;
    // Twice the area over the longest side: the height of the triangle. On one
    // line (within the play) a reflection in that line maps the set onto itself.
    const double cross = (c[1].first - c[0].first) * (c[2].second - c[0].second) -
                         (c[1].second - c[0].second) * (c[2].first - c[0].first);
    return std::fabs(cross) / std::max({d[0], d[1], d[2]}) > 2 * tolerance_mm;
}

bool placeHalves(Scene& s, bool or_throw) {
    assert(s.halves && "buildScene sets the cut before the holes");
    SceneHalves& h = *s.halves;
    h.pins = pinGeometry();
    const PinGeometry& g = h.pins;
    // A neighbouring cell's centre must stay outside the hole (its pillar is
    // read there), with a clearance of material.
    if (s.pitch_mm < g.hole_vertex_radius_mm + kPinClearanceMm) {
        std::ostringstream m;
        m.precision(3);
        m << "--halves: cells of " << s.pitch_mm << " mm are too small for the " << 2 * g.hole_radius_mm
          << " mm pin holes; give --cell " << std::ceil((g.hole_vertex_radius_mm + kPinClearanceMm) * 10) / 10
          << " or larger (or fewer --bins)";
        throw InputError(m.str());
    }
    const double reach = g.hole_vertex_radius_mm + kHoleEdgeMarginMm;
    h.hole_depth_units = unitsUp(g.hole_depth_mm, s.z_snap_mm);
    h.hole_apex_units = unitsUp(g.hole_depth_mm + g.cone_mm, s.z_snap_mm);
    const int64_t room = h.hole_apex_units + unitsUp(kHoleRoofMm, s.z_snap_mm);
    const std::vector<Candidate> all = holeCandidates(s, reach, g.hole_vertex_radius_mm, room);
    // At most this many candidates are tried three at a time (evenly spread
    // over the model): 120 choose 3 = 280 840 triangles, a few milliseconds.
    constexpr size_t kMaxTried = 120;
    std::vector<Candidate> tried;
    const size_t stride = all.size() > kMaxTried ? (all.size() + kMaxTried - 1) / kMaxTried : 1;
    for (size_t n = 0; n < all.size(); n += stride) tried.push_back(all[n]);
    const double min_apart = 2 * reach;  // two holes keep the edge margin between them too
    double best_area = 0;
    size_t best[3] = {0, 0, 0};
    bool found = false;
    for (size_t a = 0; a < tried.size(); ++a)
        for (size_t b = a + 1; b < tried.size(); ++b) {
            const std::pair<double, double> pa{tried[a].x_mm, tried[a].y_mm}, pb{tried[b].x_mm, tried[b].y_mm};
            if (distanceMm(pa, pb) < min_apart) continue;
            for (size_t c = b + 1; c < tried.size(); ++c) {
                const std::pair<double, double> pc{tried[c].x_mm, tried[c].y_mm};
                if (distanceMm(pb, pc) < min_apart || distanceMm(pc, pa) < min_apart) continue;
                const double area =
                    std::fabs((pb.first - pa.first) * (pc.second - pa.second) - (pb.second - pa.second) * (pc.first - pa.first)) / 2;
                if (area <= best_area || !isChiralLayout({pa, pb, pc}, kPinLayoutMinSideDifferenceMm / 2)) continue;
                best_area = area;
                best[0] = a, best[1] = b, best[2] = c;
                found = true;
            }
        }
    if (!found) {
        if (!or_throw) return false;
        std::ostringstream m;
        m.precision(3);
        m << "--halves: the model has no room for " << kPinCount << " pin holes in a scalene triangle (each hole needs a "
          << 2 * reach << " mm circle of pillars clear of the edge and the orientation marks; " << all.size()
          << " places found); make the model larger (--width, --cell) or leave out --halves";
        throw InputError(m.str());
    }
    for (size_t n : best) {
        h.hole_cells.push_back(tried[n].kept);
        h.hole_centres.push_back(tried[n].centre);
    }
    return true;
}

std::vector<PlanarPoint> holeRing(const Scene& s, size_t n) {
    return bottomHoleRing(s, s.halves->hole_centres[n], s.halves->pins.hole_vertex_radius_mm);
}

std::vector<BottomHole> halfBottomHoles(const Scene& s) {
    std::vector<BottomHole> holes;
    if (!s.halves || s.halves->kind == HalfKind::Whole) return holes;
    const SceneHalves& h = *s.halves;
    for (size_t n = 0; n < h.hole_centres.size(); ++n)
        holes.push_back({holeRing(s, n), h.hole_centres[n], h.hole_depth_units, h.hole_apex_units});
    return holes;
}

std::vector<std::pair<double, double>> holeCentresMm(const Scene& s) {
    std::vector<std::pair<double, double>> out;
    if (!s.halves) return out;
    for (const LatticePoint& c : s.halves->hole_centres) {
        const Vec3 p = s.point(c, 0);
        out.push_back({p.x, p.y});
    }
    return out;
}

bool isHoleCell(const Scene& s, size_t kept) {
    if (!s.halves || s.halves->kind == HalfKind::Whole) return false;
    const auto& cells = s.halves->hole_cells;
    return std::find(cells.begin(), cells.end(), int32_t(kept)) != cells.end();
}

Scene halfScene(const Scene& s, HalfKind kind) {
    assert(s.halves && kind != HalfKind::Whole && s.shapes.empty());
    Scene h = s;
    const int64_t cut = s.halves->split_units;
    h.params.bottom = Bottom::Flat;
    h.halves->kind = kind;
    h.mirror_thickness_units = 0;
    for (size_t k = 0; k < h.keptCount(); ++k) {
        h.top[k] = kind == HalfKind::Upper ? s.top[k] - cut : cut - s.bottom[k];
        h.bottom[k] = 0;
    }
    if (kind == HalfKind::Upper) {
        // A value at height 0 has its top at the thickness above its bottom (0).
        h.floor_units = s.mirror_thickness_units - cut;
    } else {
        // The lower half shows the underside: higher values are lower. It
        // carries no flat-model value mapping, so its heights are read back
        // as heights only; the triangle is on the upper half's top alone.
        h.floor_units = cut;
        h.mapping.value_max = h.mapping.baseline;
        for (PlanarFace& f : h.faces.faces) f.raise_units = 0;
        if (h.marks.triangle) h.marks.triangle->raise_units = 0;
    }
    // A feature that lies across the cut keeps its side of it (gen/model/feature.h).
    for (const Feature* f : features())
        if (f->cut_into_half) f->cut_into_half(s, h, kind);
    return h;
}

}  // namespace tsf
