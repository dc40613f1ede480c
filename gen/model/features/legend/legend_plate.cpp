#include "gen/model/features/legend/legend_plate.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "gen/model/features/legend/legend.h"
#include "gen/model/scene.h"

namespace tsf {
namespace {

// Lattice i of the grid box's east edge (hex_grid.cpp gridWidth).
int64_t gridEastI(const HexGrid& g) { return 2 * int64_t(g.cols) + (g.rows > 1 ? 1 : 0); }

// The pieces of [from, to] (a lattice coordinate along one of the box's
// sides) between consecutive breakpoints that no kept span covers, in
// increasing order. Every span's ends are breakpoints.
std::vector<std::pair<int64_t, int64_t>> uncoveredPieces(int64_t from, int64_t to, std::vector<int64_t> breaks,
                                                         const std::vector<std::pair<int64_t, int64_t>>& kept) {
    breaks.push_back(from);
    breaks.push_back(to);
    std::sort(breaks.begin(), breaks.end());
    breaks.erase(std::unique(breaks.begin(), breaks.end()), breaks.end());
    std::vector<std::pair<int64_t, int64_t>> out;
    for (size_t n = 0; n + 1 < breaks.size(); ++n) {
        const int64_t p = breaks[n], q = breaks[n + 1];
        if (p < from || q > to) continue;
        const bool covered = std::any_of(kept.begin(), kept.end(), [&](const auto& s) { return s.first <= p && q <= s.second; });
        if (!covered) out.push_back({p, q});
    }
    return out;
}

// The planar ids along edge `from` -> `to` of a hexagon drawn by a face
// (gen/model/scene_marks.h PlanarFace): its ring may hold points between
// the two corners, where the face's walls are split. Empty when the ring
// leaves the edge (the notch cuts it): no plate can stand there.
std::vector<int64_t> facePath(const Scene& s, int32_t cell, int64_t from, int64_t to) {
    const Vec3 a = s.planarPoint(from, 0), b = s.planarPoint(to, 0);
    const double len2 = (b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y);
    auto onEdge = [&](int64_t id) {
        const Vec3 p = s.planarPoint(id, 0);
        const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        const double along = (b.x - a.x) * (p.x - a.x) + (b.y - a.y) * (p.y - a.y);
        return std::fabs(cross) <= 1e-9 * len2 && along > 0 && along < len2;
    };
    for (const PlanarFace& f : s.faces.faces) {
        if (std::find(f.cells.begin(), f.cells.end(), cell) == f.cells.end()) continue;
        for (const auto& ring : f.rings)
            for (size_t n = 0; n < ring.size(); ++n) {
                if (ring[n] != from) continue;
                std::vector<int64_t> path{from};
                for (size_t m = 1; m < ring.size() && path.back() != to; ++m) {
                    const int64_t id = ring[(n + m) % ring.size()];
                    if (id != to && !onEdge(id)) return {};
                    path.push_back(id);
                }
                if (path.back() == to) return path;
            }
    }
    return {};
}

struct OutlineBuilder {
    const Scene& s;
    PlateOutline out;
    std::map<std::pair<int64_t, int64_t>, uint32_t> at_lattice;  // (i, j) -> point
    std::map<std::pair<int64_t, int64_t>, int64_t> kept_corner;  // (i, j) -> lattice vertex id of a kept cell's corner
    std::map<int64_t, uint32_t> at_planar;                       // a face's own planar id -> point

    uint32_t lattice(const LatticePoint& p) {
        const auto [it, fresh] = at_lattice.try_emplace({p.i, p.j}, uint32_t(out.points.size()));
        if (fresh) {
            const Vec3 q = s.point(p, 0);
            const auto id = kept_corner.find({p.i, p.j});
            out.points.push_back({q.x, q.y, id == kept_corner.end() ? -1 : id->second});
        }
        return it->second;
    }
    uint32_t planar(int64_t id) {
        if (id < latticeVertexIdCount(s.grid)) return lattice(latticeVertexPoint(s.grid, id));
        const auto [it, fresh] = at_planar.try_emplace(id, uint32_t(out.points.size()));
        if (fresh) {
            const Vec3 q = s.planarPoint(id, 0);
            out.points.push_back({q.x, q.y, id});
        }
        return it->second;
    }
    uint32_t own(double x, double y) {
        out.points.push_back({x, y, -1});
        return uint32_t(out.points.size() - 1);
    }
    void edge(uint32_t a, uint32_t b, int32_t cell = -1, int side = -1) { out.edges.push_back({a, b, cell, side}); }
};

}  // namespace

bool legendEastOnLattice(const Scene& s) {
    // placeLegend snaps the east edge to 1 um: the grid's width, or a legend wider than it.
    return sceneLegend(s) && sceneLegend(s)->plate_east_mm <= gridWidth(s.grid, s.pitch_mm) + 1e-3;
}

PlateOutline legendPlateOutline(const Scene& s) {
    if (!sceneLegend(s) || s.keptCount() == 0) return {};
    const SceneLegend& l = *sceneLegend(s);
    const HexGrid& g = s.grid;
    const int32_t reach = std::min(l.reach_row, g.rows - 1);
    const int64_t js = hexCentre(g, 0, reach).j + 1;  // the south edge
    const bool east_lattice = legendEastOnLattice(s);
    const int64_t ie = gridEastI(g);
    OutlineBuilder b{s, {}, {}, {}, {}};
    for (int32_t r = 0; r <= reach; ++r)
        for (int32_t c = 0; c < g.cols; ++c)
            if (s.keptAt(c, r) >= 0)
                for (int k = 0; k < kHexCorners; ++k) {
                    const LatticePoint p = hexCorner(g, c, r, k);
                    b.kept_corner[{p.i, p.j}] = hexCornerId(g, c, r, k);
                }

    // The walls of the kept cells the plate stands against: an edge above
    // the south edge with no kept cell across it, unless it lies on the
    // box's west or east side (the plate is not beyond it). Reversed, so the
    // plate (outside the hexagon) is on its left.
    std::vector<LatticePoint> on_walls;
    for (int32_t r = 0; r <= reach; ++r)
        for (int32_t c = 0; c < g.cols; ++c) {
            const int32_t k = s.keptAt(c, r);
            if (k < 0) continue;
            for (int e = 0; e < kHexCorners; ++e) {
                if (s.keptNeighbour(size_t(k), e) >= 0) continue;
                const LatticePoint p = hexCorner(g, c, r, e), q = hexCorner(g, c, r, (e + 1) % kHexCorners);
                if (p.j < js || q.j < js) continue;
                if ((e == 3 && p.i == 0) || (e == 0 && east_lattice && p.i == ie)) continue;
                if (!s.drawn_by_face.empty() && s.drawn_by_face[size_t(k)]) {
                    // Along a face's ring, through the points it splits the edge at.
                    const std::vector<int64_t> path = facePath(s, k, hexCornerId(g, c, r, e), hexCornerId(g, c, r, (e + 1) % kHexCorners));
                    if (path.empty()) {
                        b.out.meets_cut = true;
                        b.edge(b.lattice(q), b.lattice(p), k, e);
                        continue;
                    }
                    for (size_t n = path.size() - 1; n > 0; --n) b.edge(b.planar(path[n]), b.planar(path[n - 1]), k, e);
                } else {
                    b.edge(b.lattice(q), b.lattice(p), k, e);
                }
                on_walls.push_back(p);
                on_walls.push_back(q);
            }
        }

    // The box's sides, less what kept cells cover, split at every lattice
    // corner on them so the plate's own walls have no T-junction.
    auto breaksOn = [&](bool fixed_i, int64_t value) {
        std::vector<int64_t> v;
        for (const LatticePoint& p : on_walls)
            if ((fixed_i ? p.i : p.j) == value) v.push_back(fixed_i ? p.j : p.i);
        return v;
    };
    // South, west to east: row `reach` spans i in [centre - 1, centre + 1] on it.
    std::vector<int64_t> south_breaks = breaksOn(false, js);
    std::vector<std::pair<int64_t, int64_t>> south_kept;
    for (int32_t c = 0; c < g.cols; ++c) {
        const int64_t ic = hexCentre(g, c, reach).i;
        south_breaks.push_back(ic - 1);
        south_breaks.push_back(ic + 1);
        if (s.keptAt(c, reach) >= 0) south_kept.push_back({ic - 1, ic + 1});
    }
    for (const auto& [p, q] : uncoveredPieces(0, ie, south_breaks, south_kept))
        b.edge(b.lattice({p, js}), b.lattice({q, js}));
    // A vertical side at lattice i: the walls of the cells whose edge lies on
    // it span j in [centre - 1, centre + 1]; from the south edge up to the
    // highest corner on it.
    auto sidePieces = [&](int64_t i, int64_t centre_i) {
        std::vector<int64_t> breaks = breaksOn(true, i);
        std::vector<std::pair<int64_t, int64_t>> kept;
        int64_t top = js;
        for (int32_t r = 0; r <= reach; ++r)
            for (int32_t c = 0; c < g.cols; ++c) {
                const LatticePoint ctr = hexCentre(g, c, r);
                if (ctr.i != centre_i) continue;
                const int64_t lo = std::max(ctr.j - 1, js), hi = ctr.j + 1;
                if (hi <= js) continue;
                breaks.push_back(lo);
                breaks.push_back(hi);
                top = std::max(top, hi);
                if (s.keptAt(c, r) >= 0) kept.push_back({lo, hi});
            }
        for (const int64_t j : breaks) top = std::max(top, j);
        return std::make_pair(uncoveredPieces(js, top, breaks, kept), top);
    };
    const double north = l.plate_north_mm;
    const uint32_t nw = b.own(s.point(LatticePoint{0, js}, 0).x, north);
    uint32_t ne;
    if (east_lattice) {
        const auto [pieces, top] = sidePieces(ie, ie - 1);
        for (const auto& [p, q] : pieces) b.edge(b.lattice({ie, p}), b.lattice({ie, q}));
        const uint32_t from = b.lattice({ie, top});
        ne = b.own(s.point(LatticePoint{ie, js}, 0).x, north);
        b.edge(from, ne);
    } else {
        const uint32_t se = b.own(l.plate_east_mm, s.point(LatticePoint{0, js}, 0).y);
        b.edge(b.lattice({ie, js}), se);
        ne = b.own(l.plate_east_mm, north);
        b.edge(se, ne);
    }
    b.edge(ne, nw);
    {
        const auto [pieces, top] = sidePieces(0, 1);
        b.edge(nw, b.lattice({0, top}));
        for (const auto& [p, q] : pieces) b.edge(b.lattice({0, q}), b.lattice({0, p}));
    }
    return std::move(b.out);
}

}  // namespace tsf
