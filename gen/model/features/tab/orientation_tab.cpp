#include "gen/model/features/tab/orientation_tab.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <tuple>

#include "gen/field/hex_grid.h"
#include "gen/geometry/joint_stress.h"
#include "gen/geometry/polygon_triangulation.h"
#include "gen/model/features/foot_contacts.h"
#include "gen/model/features/marks.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/joint_walls.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Hex corners (hex_grid.h): 2 top, 3 upper-left, 4 lower-left, 5 bottom;
// edges: 2 north-west (2 -> 3), 3 west (3 -> 4), 4 south-west (4 -> 5).
constexpr int kTop = 2, kUpperLeft = 3, kLowerLeft = 4, kBottom = 5;
constexpr int kNorthWestEdge = 2, kWestEdge = 3, kSouthWestEdge = 4;

struct Candidate {
    int32_t kept;
    int64_t j;  // the centre's lattice j; its west edge spans j - 1 .. j + 1
    bool ok;
};

// The z band (units) a kept cell holds at every corner.
struct Band {
    int64_t bottom = INT64_MIN, top = INT64_MAX;
    void narrow(const Scene& s, int32_t k) {
        for (int e = 0; e < kHexCorners; ++e) {
            bottom = std::max(bottom, cornerBottom(s, size_t(k), e));
            top = std::min(top, cornerTop(s, size_t(k), e));
        }
    }
};

// Sizes of the tab (mm) for the marks asked for.
struct TabSize {
    double width = 0, depth = 0;  // x, y
    double inset = 0;             // the triangle's right angle from the south-west corner, both ways
};

TabSize tabSize(const MarkParams& m) {
    TabSize t;
    const double apex = m.notch ? m.notch_depth_mm / std::sqrt(2.0) : 0.0;  // the apex's x and y from the corner
    t.inset = m.notch ? apex + kTabNotchClearanceMm : kTabMarginMm;
    if (m.triangle) {
        t.width = t.inset + kTabTriangleLegMm + kTabMarginMm;
        t.depth = t.inset + kTabTriangleLegMm * kTriangleLegRatio + kTabMarginMm;
    } else {
        t.width = t.depth = 2 * apex + kTabMarginMm;
    }
    // Whole hundredths of a millimetre: the width the summary and the bed fit state.
    t.width = std::ceil(t.width * 100 - 1e-9) / 100;
    t.depth = std::ceil(t.depth * 100 - 1e-9) / 100;
    return t;
}

// The southmost footprint claimed before the tab (the braille legend's
// plate north of the pillars): the tab ends kTabLegendClearanceMm south of
// it. Null when none is.
const FootprintClaim* claimNorthOfTab(const Scene& s) {
    const FootprintClaim* south = nullptr;
    for (const FootprintClaim& c : s.claims)
        if (!south || c.box.y0 < south->box.y0) south = &c;
    return south;
}

OutlinePoint corner(const Scene& s, int32_t k, int c) {
    const size_t kk = size_t(k);
    const Vec3 p = s.point(hexCorner(s.grid, s.col[kk], s.row[kk], c), 0);
    return {p.x, p.y, hexCornerId(s.grid, s.col[kk], s.row[kk], c)};
}

// Appends an outline corner; joined_after: the edge from it to the next
// corner is a pillar's wall.
void addCorner(OrientationTab& t, OutlinePoint p, bool joined_after) {
    if (!t.outline.empty() && t.outline.back().x_mm == p.x_mm && t.outline.back().y_mm == p.y_mm) {
        t.joined.back() = joined_after ? 1 : 0;
        return;
    }
    t.outline.push_back(p);
    t.joined.push_back(joined_after ? 1 : 0);
}

// The notch's V: its apex's x and y from the south-west corner, and where
// its sides meet the south and west edges (`mouth` from the corner).
struct NotchShape {
    double apex = 0, mouth = 0;
};
NotchShape notchShape(const MarkParams& m) {
    NotchShape n;
    n.apex = m.notch_depth_mm / std::sqrt(2.0);
    // The V's sides leave the apex at 45 +- opening/2 degrees from the edges.
    n.mouth = n.apex * (1.0 - std::tan((45.0 - kTabNotchOpeningDeg / 2) * kPi / 180.0));
    return n;
}

// The outline's first corner: the notch's mouth on the south edge (or the
// south-west corner without a notch). t's box must be set.
void beginOutline(const Scene& s, OrientationTab& t) {
    const NotchShape v = notchShape(s.params.marks);
    addCorner(t, {s.params.marks.notch ? snapXy(t.x_west_mm + v.mouth) : t.x_west_mm, t.y_south_mm, -1}, false);
}

// Closes the outline from its north-east corner: the north-west corner, the
// west edge down to the notch and the notch's apex; then the triangle.
void endOutline(const Scene& s, OrientationTab& t, const TabSize& size) {
    const MarkParams& m = s.params.marks;
    const NotchShape v = notchShape(m);
    addCorner(t, {t.x_west_mm, t.y_north_mm, -1}, false);
    if (m.notch) {
        addCorner(t, {t.x_west_mm, snapXy(t.y_south_mm + v.mouth), -1}, false);
        addCorner(t, {snapXy(t.x_west_mm + v.apex), snapXy(t.y_south_mm + v.apex), -1}, false);
        t.has_notch = true;
        t.notch_depth_mm = std::hypot(t.outline.back().x_mm - t.x_west_mm, t.outline.back().y_mm - t.y_south_mm);
        t.notch_width_mm = std::hypot(t.outline.front().x_mm - t.x_west_mm, t.outline[t.outline.size() - 2].y_mm - t.y_south_mm);
        t.notch_opening_deg = kTabNotchOpeningDeg;
    }
    if (m.triangle) {
        const double x = snapXy(t.x_west_mm + size.inset), y = snapXy(t.y_south_mm + size.inset);
        t.triangle = {OutlinePoint{x, y, -1}, OutlinePoint{snapXy(x + kTabTriangleLegMm), y, -1},
                      OutlinePoint{x, snapXy(y + kTabTriangleLegMm * kTriangleLegRatio), -1}};
        t.triangle_raise_units = std::max<int64_t>(1, snapUnits(m.triangle_height_mm, s.z_snap_mm));
        t.has_triangle = true;
        t.under_triangle = s.params.bottom == Bottom::Mirrored;
    }
}

// Whether the only kept cell with a corner at `p` (a lattice corner of
// kept cell k) is k: where the tab's own edge meets k's wall there, no
// other pillar's wall (a pit's, whose top is below the tab's) starts at
// that corner.
bool aloneAt(const Scene& s, const OutlinePoint& p, int32_t k) {
    if (p.lattice < 0) return false;
    int32_t cols[3], rows[3];
    latticeVertexCells(s.grid, p.lattice, cols, rows);
    for (int n = 0; n < 3; ++n) {
        const int32_t other = s.grid.contains(cols[n], rows[n]) ? s.keptAt(cols[n], rows[n]) : -1;
        if (other >= 0 && other != k) return false;
    }
    return true;
}

// Builds the tab against `contacts` (a run of cells on the west line, one
// row of the outline's notches apart, south to north, with the `fillers` in
// those notches), from y_south to y_north mm. Beyond the run its east edge is
// set back kTabSetbackMm, so it leaves no slot narrower than that beside a pillar.
OrientationTab buildTab(const Scene& s, int64_t i_west, double y_south, double y_north, const std::vector<int32_t>& contacts,
                        const std::vector<int32_t>& fillers, const TabSize& size, Band band) {
    OrientationTab t;
    t.bottom_units = band.bottom;
    t.top_units = band.top;
    t.x_east_mm = s.point(LatticePoint{i_west, 0}, 0).x;
    t.x_west_mm = snapXy(t.x_east_mm - size.width);
    t.y_south_mm = y_south;
    t.y_north_mm = y_north;
    const double x_back = snapXy(t.x_east_mm - kTabSetbackMm);
    beginOutline(s, t);
    const OutlinePoint first = corner(s, contacts.front(), kLowerLeft), last = corner(s, contacts.back(), kUpperLeft);
    addCorner(t, {x_back, t.y_south_mm, -1}, false);
    addCorner(t, {x_back, first.y_mm, -1}, false);
    // The tab fills the outline's notches between contacts (else a hole
    // would reach down to the bed); a mirrored model's tab has one contact.
    for (size_t n = 0; n < contacts.size(); ++n) {
        const int32_t c = contacts[n];
        addCorner(t, corner(s, c, kLowerLeft), true);  // the west wall, south to north
        if (n + 1 < contacts.size()) {
            // The outline's notch up to the next contact: c's north-west
            // wall, the filler's west wall, the next one's south-west wall.
            addCorner(t, corner(s, c, kUpperLeft), true);
            addCorner(t, corner(s, c, kTop), true);
            addCorner(t, corner(s, contacts[n + 1], kBottom), true);
        } else {
            addCorner(t, corner(s, c, kUpperLeft), false);
        }
    }
    addCorner(t, {x_back, last.y_mm, -1}, false);
    addCorner(t, {x_back, t.y_north_mm, -1}, false);
    for (size_t n = 0; n < contacts.size(); ++n) {
        t.touched.push_back({contacts[n], kWestEdge});
        if (n + 1 < contacts.size()) {
            t.touched.push_back({contacts[n], kNorthWestEdge});
            t.touched.push_back({fillers[n], kWestEdge});
            t.touched.push_back({contacts[n + 1], kSouthWestEdge});
        }
    }
    endOutline(s, t, size);
    return t;
}

// The stress (MPa) on the tab's joint under a hand's push at its far
// corner (gen/geometry/joint_stress.h), as tsf verify --tactile measures it:
// each wall it covers over the band both hold.
double tabJointStressMpa(const Scene& s, const OrientationTab& t) {
    std::vector<JointWall> walls;
    for (const auto& [k, e] : t.touched) walls.push_back(jointWall(s, {k, e, t.bottom_units, t.top_units}));
    const int64_t raise = t.has_triangle ? t.triangle_raise_units : 0;
    const Bounds box{{t.x_west_mm, t.y_south_mm, s.zMm(t.bottom_units - (t.under_triangle ? raise : 0))},
                     {t.x_east_mm, t.y_north_mm, s.zMm(t.top_units + raise)}};
    return jointLoad(walls, box, kHandPushN).stress_MPa;
}

// Where a point lies against a simple polygon (mm): -1 outside, 0 on its
// boundary, 1 inside.
int pointInOutline(const std::vector<OutlinePoint>& poly, double x, double y) {
    bool inside = false;
    for (size_t a = 0, n = poly.size(), b = n - 1; a < n; b = a++) {
        const OutlinePoint &p = poly[a], &q = poly[b];
        const double cross = (q.x_mm - p.x_mm) * (y - p.y_mm) - (q.y_mm - p.y_mm) * (x - p.x_mm);
        const double len2 = (q.x_mm - p.x_mm) * (q.x_mm - p.x_mm) + (q.y_mm - p.y_mm) * (q.y_mm - p.y_mm);
        if (std::fabs(cross) <= 1e-9 * std::max(1.0, len2) && x >= std::min(p.x_mm, q.x_mm) - 1e-9 &&
            x <= std::max(p.x_mm, q.x_mm) + 1e-9 && y >= std::min(p.y_mm, q.y_mm) - 1e-9 && y <= std::max(p.y_mm, q.y_mm) + 1e-9)
            return 0;
        if ((p.y_mm > y) != (q.y_mm > y) && x < (q.x_mm - p.x_mm) * (y - p.y_mm) / (q.y_mm - p.y_mm) + p.x_mm) inside = !inside;
    }
    return inside ? 1 : -1;
}

// Whether the tab's outline is clear of the pillars `near` (kept indices):
// no centre, corner or edge middle of one inside it, and no corner on its
// own edges (on the walls it stands against only at the walk's corners).
bool clearOfPillars(const Scene& s, const OrientationTab& t, const std::vector<OutlinePoint>& walk, const std::vector<int32_t>& near) {
    const double reach_y = s.pitch_mm * s.y_scale;
    for (const int32_t k : near) {
        const size_t kk = size_t(k);
        const Vec3 c = s.point(hexCentre(s.grid, s.col[kk], s.row[kk]), 0);
        if (c.x - s.pitch_mm > t.x_east_mm || c.y + reach_y < t.y_south_mm || c.y - reach_y > t.y_north_mm) continue;
        if (pointInOutline(t.outline, c.x, c.y) >= 0) return false;
        for (int e = 0; e < kHexCorners; ++e) {
            const OutlinePoint p = corner(s, k, e), q = corner(s, k, (e + 1) % kHexCorners);
            const int where = pointInOutline(t.outline, p.x_mm, p.y_mm);
            if (where > 0) return false;
            if (where == 0 && std::none_of(walk.begin(), walk.end(), [&](const OutlinePoint& w) { return w.x_mm == p.x_mm && w.y_mm == p.y_mm; }))
                return false;
            if (pointInOutline(t.outline, 0.5 * (p.x_mm + q.x_mm), 0.5 * (p.y_mm + q.y_mm)) > 0) return false;
        }
    }
    return true;
}

// A flat model's tab that follows the pillars' outline: on an irregular
// west side (a round or diagonal outline) the tab on the westernmost line
// touches one pillar at its north end and would snap off under a hand.
// This one walks the outline from the bottom tip of a southernmost pillar
// (so the notch stays the model's south-west corner) north along the
// pillars it meets, standing against every wall between (the outline's
// notches filled, as the legend's plate fills them), at least size.depth
// north, to the top tip of a pillar whose north-west wall faces out or the
// lower-left corner of one whose west wall does. Of every such walk, the
// shortest whose joint holds a hand's push (gen/geometry/joint_stress.h),
// else the one that holds best. Its south and north edges meet the walk at
// a hexagon's corners, at right angles to the walls beside them (no sliver
// of floor). None when no walk fits.
std::optional<OrientationTab> outlineTab(const Scene& s, int64_t i_west, double y_south, const TabSize& size) {
    const HexGrid& g = s.grid;
    // Every wall facing out, by the lattice corner a northward walk leaves
    // it from (the walk keeps the pillars on its right: corner e + 1 to e).
    std::map<std::pair<int64_t, int64_t>, std::vector<std::pair<int32_t, int>>> leaving;
    const double x_line = s.point(LatticePoint{i_west, 0}, 0).x;
    const double y_cap = y_south + 3 * size.depth;
    std::vector<int32_t> near;  // the pillars a tab up to y_cap could meet
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.point(hexCentre(g, s.col[k], s.row[k]), 0).y - s.pitch_mm * s.y_scale > y_cap) continue;
        near.push_back(int32_t(k));
        for (int e = 0; e < kHexCorners; ++e)
            if (s.keptNeighbour(k, e) < 0) {
                const LatticePoint p = hexCorner(g, s.col[k], s.row[k], (e + 1) % kHexCorners);
                leaving[{p.i, p.j}].push_back({int32_t(k), e});
            }
    }
    std::optional<OrientationTab> best;
    double best_stress = INFINITY;
    for (const int32_t k0 : near) {
        if (s.keptNeighbour(size_t(k0), kSouthWestEdge) >= 0 || !footCanTouch(s, k0)) continue;
        const OutlinePoint start = corner(s, k0, kBottom);
        if (start.y_mm != y_south || !aloneAt(s, start, k0)) continue;
        std::vector<std::pair<int32_t, int>> walk;
        std::vector<OutlinePoint> at{start};
        int32_t k = k0;
        int e = kSouthWestEdge;
        for (int steps = 0; steps < 400; ++steps) {
            if (!footCanTouch(s, k)) break;
            walk.push_back({k, e});
            at.push_back(corner(s, k, e));
            const OutlinePoint& v = at.back();
            if (v.y_mm < start.y_mm || v.y_mm > y_cap) break;
            // The north edge leaves at a right angle to the wall above it:
            // at a top tip, or at a lower-left corner below an open west wall.
            const bool exit = (e == kNorthWestEdge || (e == kSouthWestEdge && s.keptNeighbour(size_t(k), kWestEdge) < 0)) &&
                              aloneAt(s, v, k);
            if (exit && v.y_mm - start.y_mm >= size.depth - 1e-9 &&
                !(claimNorthOfTab(s) && v.y_mm + kTabLegendClearanceMm > claimNorthOfTab(s)->box.y0)) {
                OrientationTab t;
                t.bottom_units = 0;
                t.top_units = s.floor_units;
                t.x_west_mm = snapXy(x_line - size.width);
                t.y_south_mm = start.y_mm;
                t.y_north_mm = v.y_mm;
                beginOutline(s, t);
                bool simple = true;
                double east = x_line;
                for (size_t n = 0; n < at.size(); ++n) {
                    // Between its ends the walk stays strictly between the south and north edges.
                    if (n > 0 && n + 1 < at.size() && !(at[n].y_mm > start.y_mm && at[n].y_mm < v.y_mm)) simple = false;
                    addCorner(t, at[n], n + 1 < at.size());
                    east = std::max(east, at[n].x_mm);
                }
                t.x_east_mm = east;
                t.touched = walk;
                endOutline(s, t, size);
                if (simple && clearOfPillars(s, t, at, near)) {
                    // The shortest that holds; else the one that holds best.
                    const double stress = tabJointStressMpa(s, t);
                    const bool holds = stress <= kPrintedPlaInterlayerMpa, held = best_stress <= kPrintedPlaInterlayerMpa;
                    if (!best || (holds && !held) || (holds && held && t.y_north_mm < best->y_north_mm) ||
                        (!holds && !held && stress < best_stress)) {
                        best_stress = stress;
                        best = std::move(t);
                    }
                }
            }
            const auto next = leaving.find({hexCorner(g, s.col[size_t(k)], s.row[size_t(k)], e).i,
                                            hexCorner(g, s.col[size_t(k)], s.row[size_t(k)], e).j});
            if (next == leaving.end() || next->second.size() != 1) break;  // the outline pinches: stop
            std::tie(k, e) = next->second.front();
        }
    }
    return best;
}

// Inside the triangle (edges included), mm.
bool inTriangle(const std::array<OutlinePoint, 3>& t, double x, double y) {
    auto side = [&](const OutlinePoint& a, const OutlinePoint& b) {
        return (b.x_mm - a.x_mm) * (y - a.y_mm) - (b.y_mm - a.y_mm) * (x - a.x_mm);
    };
    return side(t[0], t[1]) >= 0 && side(t[1], t[2]) >= 0 && side(t[2], t[0]) >= 0;
}

}  // namespace

double tabWidthMm(const MarkParams& m) { return tabSize(m).width; }

void placeTab(Scene& s) {
    s.features.reset<OrientationTab>();
    if (!marksOnTab(s.params) || s.keptCount() == 0) return;
    const TabSize size = tabSize(s.params.marks);

    // The tab's east face: the westernmost hexagon edge of the kept cells.
    int64_t i_west = INT64_MAX, j_min = INT64_MAX;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        const LatticePoint c = hexCentre(s.grid, s.col[k], s.row[k]);
        i_west = std::min(i_west, c.i - 1);
        j_min = std::min(j_min, c.j - 2);
    }
    std::vector<Candidate> cand;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        const LatticePoint c = hexCentre(s.grid, s.col[k], s.row[k]);
        if (c.i - 1 == i_west) cand.push_back({int32_t(k), c.j, footCanTouch(s, int32_t(k))});
    }
    std::sort(cand.begin(), cand.end(), [](const Candidate& a, const Candidate& b) { return a.j < b.j; });
    // The tab reaches as far south as the lowest pillar, so its notch is the
    // model's south-west corner, and at least size.depth north of that.
    const double y_south = s.point(LatticePoint{i_west, j_min}, 0).y;
    const double y_reach = snapXy(y_south + size.depth);
    auto yOf = [&](int64_t j) { return s.point(LatticePoint{i_west, j}, 0).y; };
    // Runs of touchable candidates one row of notches apart (6 lattice j)
    // with a touchable filler in each notch; of each, the contacts up to the
    // first whose wall reaches y_reach. The run with the most contacts is
    // taken (the firmest join), the southernmost of equals. Flat, the tab
    // spans 0 to the floor; mirrored, the band all of them hold, at least
    // `thick` units thick.
    const bool mirrored = s.params.bottom == Bottom::Mirrored;
    const int64_t thick = std::min(s.mirror_thickness_units, std::max<int64_t>(1, snapUnits(kTabMinThicknessMm, s.z_snap_mm)));
    // Cut into halves, the tab is as thick as the base on each side of the
    // cut, so each half carries a tab of its own and the two make one.
    const int64_t half_tab = std::max(thick, snapUnits(s.params.base_mm, s.z_snap_mm));
    const std::optional<Band> cut_band =
        s.halves ? std::optional<Band>(Band{s.halves->split_units - half_tab, s.halves->split_units + half_tab}) : std::nullopt;
    auto fits = [&](Band b) {
        if (cut_band) return b.bottom <= cut_band->bottom && b.top >= cut_band->top;
        return !mirrored || b.top - b.bottom >= thick;
    };
    std::vector<int32_t> best, best_fillers;
    Band best_band;
    std::string blocked = "cells without data, tilted corners below the floor or culled rows";
    for (size_t start = 0; start < cand.size(); ++start) {
        if (!cand[start].ok || (start > 0 && cand[start - 1].ok && cand[start].j - cand[start - 1].j == 6 &&
                                footCanTouch(s, keptAtCentre(s, i_west + 2, cand[start - 1].j + 3))))
            continue;  // not the start of a run
        std::vector<int32_t> contacts{cand[start].kept}, fillers;
        Band band;
        band.narrow(s, cand[start].kept);
        // Mirrored, one contact: the notch between two would be a slot open
        // above and below the tab, so the tab would close a ring around it
        // (a handle: the solid's genus 1), and a ceiling over that slot is
        // what the Manifold engine (OpenSCAD 2025) unions into a
        // non-manifold vertex.
        for (size_t n = start + 1; !mirrored && n < cand.size() && yOf(cand[n - 1].j + 1) < y_reach; ++n) {
            const int32_t filler = keptAtCentre(s, i_west + 2, cand[n - 1].j + 3);
            if (!cand[n].ok || cand[n].j - cand[n - 1].j != 6 || !footCanTouch(s, filler)) break;
            Band wider = band;
            wider.narrow(s, filler);
            wider.narrow(s, cand[n].kept);
            if (!fits(wider)) break;
            band = wider;
            fillers.push_back(filler);
            contacts.push_back(cand[n].kept);
        }
        if (!fits(band)) {
            blocked = cut_band ? std::string("pillars that do not hold the cut's slab")
                               : "pillars thinner than " + formatSignificant(kTabMinThicknessMm) + " mm";
            continue;
        }
        const double y_north = std::max(y_reach, yOf(cand[start + contacts.size() - 1].j + 1));
        if (const FootprintClaim* north = claimNorthOfTab(s); north && y_north + kTabLegendClearanceMm > north->box.y0) {
            blocked = north->what;
            continue;
        }
        if (contacts.size() > best.size()) {
            best = std::move(contacts);
            best_fillers = std::move(fillers);
            best_band = band;
        }
    }
    if (!best.empty()) {
        if (!mirrored) {
            best_band = {0, s.floor_units};
        } else if (cut_band) {
            best_band = *cut_band;
        }
        const int64_t last_j = hexCentre(s.grid, s.col[size_t(best.back())], s.row[size_t(best.back())]).j;
        const double y_north = std::max(y_reach, yOf(last_j + 1));
        if (mirrored && !cut_band) {
            // As thick as a flat model's base (at least `thick`), in the
            // middle of the band: a plate, not a block as tall as the
            // pillars. Its one contact is a short joint: where that plate
            // would snap off under a hand, it is made thicker, a millimetre
            // at a time up to the band, until it holds (the stress falls with
            // the square of the thickness).
            const Band held = best_band;
            auto centred = [&held](int64_t want) {
                Band b = held;
                if (b.top - b.bottom > want) {
                    b.bottom += (b.top - b.bottom - want) / 2;
                    b.top = b.bottom + want;
                }
                return b;
            };
            const int64_t step = std::max<int64_t>(1, snapUnits(1.0, s.z_snap_mm));
            for (int64_t want = std::max(thick, snapUnits(s.params.base_mm, s.z_snap_mm));; want += step) {
                const OrientationTab& t =
                    s.features.set(buildTab(s, i_west, y_south, y_north, best, best_fillers, size, centred(want)));
                if (want >= held.top - held.bottom || tabJointStressMpa(s, t) <= kPrintedPlaInterlayerMpa) break;
            }
        } else {
            s.features.set(buildTab(s, i_west, y_south, y_north, best, best_fillers, size, best_band));
        }
    }
    // On a flat model whose west side is not a straight line, the tab on
    // the westernmost line may touch one pillar and snap off: one that
    // follows the outline stands against more of it.
    if (!mirrored && !cut_band) {
        const OrientationTab* placed = sceneTab(s);
        const double stress = placed ? tabJointStressMpa(s, *placed) : INFINITY;
        if (stress > kPrintedPlaInterlayerMpa)
            if (std::optional<OrientationTab> along = outlineTab(s, i_west, y_south, size);
                along && tabJointStressMpa(s, *along) < stress)
                s.features.set(std::move(*along));
    }
    if (sceneTab(s)) return;
    s.notes.push_back("no orientation tab: the tab that carries the marks (" + formatSignificant(size.width, 3) + " x " +
                      formatSignificant(size.depth, 3) + " mm) finds no pillar on the model's west side to stand "
                      "against, clear of " + blocked);
}

std::optional<int64_t> tabTopAt(const Scene& s, double x, double y) {
    const OrientationTab* tab = sceneTab(s);
    if (!tab) return std::nullopt;
    const OrientationTab& t = *tab;
    // Even-odd test against the outline (points on it count as inside).
    bool inside = false;
    const size_t n = t.outline.size();
    for (size_t a = 0, b = n - 1; a < n; b = a++) {
        const OutlinePoint &p = t.outline[a], &q = t.outline[b];
        if ((p.y_mm > y) != (q.y_mm > y) && x < (q.x_mm - p.x_mm) * (y - p.y_mm) / (q.y_mm - p.y_mm) + p.x_mm) inside = !inside;
    }
    if (!inside) return std::nullopt;
    if (t.has_triangle && inTriangle(t.triangle, x, y)) return t.top_units + t.triangle_raise_units;
    return t.top_units;
}

double tabAreaMm2(const OrientationTab& t) {
    double twice = 0;
    for (size_t a = 0, n = t.outline.size(); a < n; ++a) {
        const OutlinePoint &p = t.outline[a], &q = t.outline[(a + 1) % n];
        twice += p.x_mm * q.y_mm - q.x_mm * p.y_mm;
    }
    return twice / 2;
}

JoinedBody meshTabBody(const Scene& s, bool joined) {
    JoinedBody body;
    const OrientationTab* tab = sceneTab(s);
    if (!tab) return body;
    const OrientationTab& t = *tab;
    Mesh& m = body.mesh;
    const uint32_t n = uint32_t(t.outline.size());
    for (const int64_t z : {t.bottom_units, t.top_units})
        for (const OutlinePoint& p : t.outline) {
            m.positions.push_back({p.x_mm, p.y_mm, s.zMm(z)});
            body.lattice_id.push_back(p.lattice);
        }
    std::vector<uint32_t> lo(n), hi(n);
    for (uint32_t v = 0; v < n; ++v) lo[v] = v, hi[v] = v + n;
    // A triangle prism from z0 to z1 on the plate's face at `base` (z0 or
    // z1); returns the ring of its corners at `base` (counter-clockwise).
    auto prism = [&](int64_t z0, int64_t z1, bool up) {
        const uint32_t first = uint32_t(m.positions.size());
        for (const int64_t z : {z0, z1})
            for (const OutlinePoint& p : t.triangle) {
                m.positions.push_back({p.x_mm, p.y_mm, s.zMm(z)});
                body.lattice_id.push_back(-1);
            }
        const uint32_t a = first, b = first + 3;  // the rings at z0 and z1
        if (up) m.triangles.push_back({b, b + 1, b + 2});  // its top, facing up
        else m.triangles.push_back({a, a + 2, a + 1});     // its bottom, facing down
        for (uint32_t v = 0; v < 3; ++v) {
            const uint32_t w = (v + 1) % 3;
            m.triangles.push_back({a + v, a + w, b + w});
            m.triangles.push_back({a + v, b + w, b + v});
        }
        return up ? std::vector<uint32_t>{a, a + 1, a + 2} : std::vector<uint32_t>{b, b + 1, b + 2};
    };
    // The bottom, facing down, around the underside's triangle (mirrored).
    std::vector<std::vector<uint32_t>> bottom_rings{lo};
    if (t.has_triangle && t.under_triangle) {
        const std::vector<uint32_t> r = prism(t.bottom_units - t.triangle_raise_units, t.bottom_units, /*up=*/false);
        bottom_rings.push_back({r[0], r[2], r[1]});  // a hole: clockwise
    }
    for (const auto& tri : triangulateRings(m.positions, bottom_rings)) m.triangles.push_back({tri[0], tri[2], tri[1]});
    // The top, facing up, around the triangle.
    std::vector<std::vector<uint32_t>> top_rings{hi};
    if (t.has_triangle) {
        const std::vector<uint32_t> r = prism(t.top_units, t.top_units + t.triangle_raise_units, /*up=*/true);
        top_rings.push_back({r[0], r[2], r[1]});
    }
    for (const auto& tri : triangulateRings(m.positions, top_rings)) m.triangles.push_back(tri);
    // The walls: the outline runs with the tab on its left, so the outward
    // normal of edge v -> w is (w - v) x up.
    for (uint32_t v = 0; v < n; ++v) {
        if (joined && t.joined[v]) continue;
        const uint32_t w = (v + 1) % n;
        m.triangles.push_back({lo[v], lo[w], hi[w]});
        m.triangles.push_back({lo[v], hi[w], hi[v]});
    }
    return body;
}

std::optional<BoxMm> tabBoxMm(const Scene& s) {
    const OrientationTab* tab = sceneTab(s);
    if (!tab) return std::nullopt;
    const OrientationTab& t = *tab;
    return BoxMm{t.x_west_mm, t.x_east_mm, t.y_south_mm, t.y_north_mm};
}

std::optional<FootprintClaim> tabClaim(const Scene& s) {
    const std::optional<BoxMm> box = tabBoxMm(s);
    if (!box) return std::nullopt;
    return FootprintClaim{*box, "the orientation tab", "--marks-on data (the marks in the pillars instead of on a tab)"};
}

std::optional<Attachment> tabAttachment(const Scene& s, Assembly assembly) {
    const OrientationTab* tab = sceneTab(s);
    if (!tab) return std::nullopt;
    Attachment a;
    a.part = "marks";
    if (assembly == Assembly::Parts) {
        a.own_part = meshTabBody(s, /*joined=*/false).mesh;  // touching the pillars' west walls
        return a;
    }
    const OrientationTab& t = *tab;
    for (const auto& [k, e] : t.touched) a.walls.push_back({k, e, t.bottom_units, t.top_units});
    a.joined = meshTabBody(s, /*joined=*/true);
    return a;
}

void checkTabInScene(const Scene& s) {
    const OrientationTab* tab = sceneTab(s);
    if (!tab) return;
    const OrientationTab& t = *tab;
    checkTab(s, t);
    // Each wall it covers holds its whole band, so the pillar's wall goes on above and below it.
    for (const auto& [k, e] : t.touched)
        for (const int c : {e, (e + 1) % kHexCorners})
            if ((!s.drawn_by_face.empty() && s.drawn_by_face[size_t(k)]) || cornerBottom(s, size_t(k), c) > t.bottom_units ||
                cornerTop(s, size_t(k), c) < t.top_units)
                throw InputError("scene: orientation tab: it stands against cell (" + std::to_string(s.col[size_t(k)]) +
                                 ", " + std::to_string(s.row[size_t(k)]) + "), whose wall does not hold its z band");
}

void checkTab(const Scene& s, const OrientationTab& t) {
    auto bad = [](const std::string& why) { throw InputError("the orientation tab " + why); };
    if (t.outline.size() < 4 || t.joined.size() != t.outline.size()) bad("has no outline, or joined flags that do not match it");
    if (t.bottom_units >= t.top_units || (s.params.bottom == Bottom::Flat && t.bottom_units != 0))
        bad(t.bottom_units >= t.top_units ? "has no thickness" : "does not stand on the bed");
    if (s.params.bottom == Bottom::Flat && !s.halves && t.top_units != s.floor_units) bad("does not reach the floor");
    if (t.under_triangle && s.params.bottom != Bottom::Mirrored) bad("has a triangle on the underside of a flat model");
    if (t.has_triangle && t.triangle_raise_units <= 0) bad("has a triangle that does not stand above it");
    const int64_t ids = latticeVertexIdCount(s.grid);
    std::set<int64_t> corners;
    for (const auto& [k, e] : t.touched) {
        if (k < 0 || size_t(k) >= s.keptCount() || e < 0 || e >= kHexCorners) bad("touches a cell that is not kept");
        if (s.keptNeighbour(size_t(k), e) >= 0) bad("covers a wall between two pillars");
        for (const int c : {e, (e + 1) % kHexCorners})
            corners.insert(hexCornerId(s.grid, s.col[size_t(k)], s.row[size_t(k)], c));
    }
    for (size_t n = 0; n < t.outline.size(); ++n) {
        const OutlinePoint& p = t.outline[n];
        if (!std::isfinite(p.x_mm) || !std::isfinite(p.y_mm)) bad("has a corner that is not a number");
        if (p.lattice >= ids || p.lattice < -1) bad("names a lattice corner beyond the grid");
        if (p.lattice >= 0) {
            const Vec3 q = s.point(latticeVertexPoint(s.grid, p.lattice), 0);
            if (q.x != p.x_mm || q.y != p.y_mm) bad("has a corner away from the lattice corner it names");
        }
        const OutlinePoint& q = t.outline[(n + 1) % t.outline.size()];
        if (t.joined[n] && (p.lattice < 0 || q.lattice < 0 || !corners.count(p.lattice) || !corners.count(q.lattice)))
            bad("joins a wall that is not one it touches");
    }
}

std::vector<SurfaceProbe> tabProbes(const Scene& s) {
    std::vector<SurfaceProbe> out;
    const OrientationTab* tab = sceneTab(s);
    if (!tab) return out;
    const OrientationTab& t = *tab;
    const double floor_mm = s.zMm(t.top_units);
    out.push_back({"the orientation tab's top", t.x_west_mm + 1.0, t.y_north_mm - 1.0, false, floor_mm});
    if (t.has_triangle) {
        const double z = s.zMm(t.top_units + t.triangle_raise_units);
        const double cx = (t.triangle[0].x_mm + t.triangle[1].x_mm + t.triangle[2].x_mm) / 3;
        const double cy = (t.triangle[0].y_mm + t.triangle[1].y_mm + t.triangle[2].y_mm) / 3;
        const char* names[] = {"the orientation triangle's right-angle corner", "the orientation triangle's east corner",
                               "the orientation triangle's north corner"};
        out.push_back({"the orientation triangle's middle", cx, cy, false, z});
        for (int n = 0; n < 3; ++n)
            out.push_back({names[n], t.triangle[n].x_mm + 0.2 * (cx - t.triangle[n].x_mm),
                           t.triangle[n].y_mm + 0.2 * (cy - t.triangle[n].y_mm), false, z});
    }
    if (t.has_notch) {
        const double along = 1.0 / std::sqrt(2.0);
        for (const double d : {t.notch_depth_mm - 0.3, t.notch_depth_mm + 0.3}) {
            const bool inside = d < t.notch_depth_mm;
            out.push_back({inside ? "inside the orientation notch, 0.3 mm short of its apex" : "the tab just beyond the notch's apex",
                           t.x_west_mm + d * along, t.y_south_mm + d * along, inside, inside ? 0.0 : floor_mm});
        }
    }
    return out;
}

}  // namespace tsf
