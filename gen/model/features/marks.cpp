// placeMarks / buildMarkFaces: see marks.h.
//
// Faces are made with a constrained triangulation under an exact kernel
// (CGAL Epeck, exact intersections) in lattice coordinates, where hex corners
// are integers: every crossing of a mark's edge with a hex edge is ONE vertex
// of the triangulation, shared by the faces on both sides by construction.
// Only then is each new point converted to double (PlanarFaces::extra).
#include "gen/model/features/marks.h"

#include <algorithm>
#include <cmath>
#include <deque>
#include <map>
#include <optional>
#include <sstream>
#include <unordered_map>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "gen/geometry/cdt_parity.h"
#include "gen/util/error.h"
#include "gen/model/scene.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
struct VertexInfo {
    int64_t id = -1;  // planar id once known
};
using Vb = CGAL::Triangulation_vertex_base_with_info_2<VertexInfo, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_intersections_tag>;

struct Xy {
    double x = 0, y = 0;
};

// Lattice coordinates <-> mm in the Scene's frame (its pitch and north-south stretch).
Xy toMm(const Scene& s, const PlanarPoint& p) { return {planarX(p, s.pitch_mm), planarY(p, s.pitch_mm, s.y_scale)}; }
Xy toMm(const Scene& s, const LatticePoint& p) { return {latticeX(p, s.pitch_mm), latticeY(p, s.pitch_mm, s.y_scale)}; }
PlanarPoint toPlanar(const Scene& s, const Xy& p) {
    return {p.x / (s.pitch_mm * 0.5), p.y * (2.0 * kSqrt3) / (s.pitch_mm * s.y_scale)};
}
PlanarPoint toPlanar(const LatticePoint& p) { return {double(p.i), double(p.j)}; }

double dist(const Xy& a, const Xy& b) { return std::hypot(a.x - b.x, a.y - b.y); }

// Distance from p to segment ab (mm).
double segmentDistance(const Xy& p, const Xy& a, const Xy& b) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return dist(p, {a.x + t * dx, a.y + t * dy});
}

double cross(const Xy& o, const Xy& a, const Xy& b) { return (a.x - o.x) * (b.y - o.y) - (a.y - o.y) * (b.x - o.x); }

// Strictly inside the counter-clockwise triangle abc.
bool insideTriangle(const Xy& p, const Xy& a, const Xy& b, const Xy& c) {
    return cross(a, b, p) > 0 && cross(b, c, p) > 0 && cross(c, a, p) > 0;
}

// Distance from p to the closed triangle abc (0 inside).
double triangleDistance(const Xy& p, const Xy& a, const Xy& b, const Xy& c) {
    if (insideTriangle(p, a, b, c)) return 0.0;
    return std::min({segmentDistance(p, a, b), segmentDistance(p, b, c), segmentDistance(p, c, a)});
}

bool segmentsCross(const Xy& a, const Xy& b, const Xy& c, const Xy& d) {
    const double d1 = cross(a, b, c), d2 = cross(a, b, d), d3 = cross(c, d, a), d4 = cross(c, d, b);
    return ((d1 > 0) != (d2 > 0)) && ((d3 > 0) != (d4 > 0));
}

// Do the hexagon of a cell and the triangle abc (ccw) overlap with positive area?
bool hexMeetsTriangle(const Scene& s, int32_t c, int32_t r, const Xy& a, const Xy& b, const Xy& t) {
    Xy h[kHexCorners];
    for (int k = 0; k < kHexCorners; ++k) h[k] = toMm(s, hexCorner(s.grid, c, r, k));
    const Xy tri[3] = {a, b, t};
    for (const Xy& p : h)
        if (insideTriangle(p, a, b, t)) return true;
    for (const Xy& p : tri) {
        bool in = true;
        for (int k = 0; k < kHexCorners; ++k) in = in && cross(h[k], h[(k + 1) % kHexCorners], p) > 0;
        if (in) return true;
    }
    for (int k = 0; k < kHexCorners; ++k)
        for (int e = 0; e < 3; ++e)
            if (segmentsCross(h[k], h[(k + 1) % kHexCorners], tri[e], tri[(e + 1) % 3])) return true;
    return false;
}

// ---------------------------------------------------------------- notch ---

// The kept-cell corner furthest towards the south-west (smallest x + y; then
// smallest x): the model's origin corner.
LatticePoint originCorner(const Scene& s) {
    LatticePoint best{};
    double best_score = INFINITY, best_x = INFINITY;
    for (size_t k = 0; k < s.keptCount(); ++k)
        for (int e = 0; e < kHexCorners; ++e) {
            const LatticePoint p = hexCorner(s.grid, s.col[k], s.row[k], e);
            const Xy m = toMm(s, p);
            const double score = m.x + m.y;
            if (score < best_score - 1e-9 || (score < best_score + 1e-9 && m.x < best_x)) {
                best_score = score;
                best_x = m.x;
                best = p;
            }
        }
    return best;
}

// Kept cells near a point: centres within `radius_mm` of `at` (the only
// cells a mark of that reach can touch).
std::vector<int32_t> cellsNear(const Scene& s, const Xy& at, double radius_mm) {
    std::vector<int32_t> out;
    for (size_t k = 0; k < s.keptCount(); ++k)
        if (dist(at, toMm(s, hexCentre(s.grid, s.col[k], s.row[k]))) <= radius_mm) out.push_back(int32_t(k));
    return out;
}

// Cells of `near` whose hexagon meets the V (mm triangle apex, m1, m2, ccw).
std::vector<int32_t> cellsMeeting(const Scene& s, const std::vector<int32_t>& near, const Xy& a, const Xy& b, const Xy& c) {
    std::vector<int32_t> out;
    for (int32_t k : near)
        if (hexMeetsTriangle(s, s.col[size_t(k)], s.row[size_t(k)], a, b, c)) out.push_back(k);
    return out;
}

// The part of a convex polygon on the left of the directed line a -> b.
std::vector<Xy> clipLeft(const std::vector<Xy>& poly, const Xy& a, const Xy& b) {
    std::vector<Xy> out;
    for (size_t n = 0; n < poly.size(); ++n) {
        const Xy& p = poly[n];
        const Xy& q = poly[(n + 1) % poly.size()];
        const double dp = cross(a, b, p), dq = cross(a, b, q);
        if (dp >= 0) out.push_back(p);
        if ((dp >= 0) != (dq >= 0)) {
            const double t = dp / (dp - dq);
            out.push_back({p.x + t * (q.x - p.x), p.y + t * (q.y - p.y)});
        }
    }
    return out;
}

double polygonArea(const std::vector<Xy>& poly) {
    double a = 0;
    for (size_t n = 0; n < poly.size(); ++n) {
        const Xy& p = poly[n];
        const Xy& q = poly[(n + 1) % poly.size()];
        a += p.x * q.y - q.x * p.y;
    }
    return 0.5 * a;
}

std::vector<Xy> hexPolygon(const Scene& s, size_t k) {
    std::vector<Xy> h;
    for (int e = 0; e < kHexCorners; ++e) h.push_back(toMm(s, hexCorner(s.grid, s.col[k], s.row[k], e)));
    return h;
}

// Where the height of kept cell k is read when the notch (apex, m1, m2) cuts
// it: its centre when that stays kMarkClearanceMm from the V, else the point
// of the rest of its hexagon farthest from the V (a 13 x 13 search), kept
// kReadEdgeMm inside the hexagon. Empty if no point is clear enough.
constexpr double kReadEdgeMm = 0.4;
std::optional<Xy> notchReadPoint(const Scene& s, size_t k, const Xy& apex, const Xy& m1, const Xy& m2) {
    const Xy c = toMm(s, hexCentre(s.grid, s.col[k], s.row[k]));
    if (triangleDistance(c, apex, m1, m2) >= kMarkClearanceMm) return c;
    const std::vector<Xy> hex = hexPolygon(s, k);
    std::optional<Xy> best;
    double best_d = kMarkClearanceMm;
    constexpr int kSteps = 13;
    for (int u = 0; u < kSteps; ++u)
        for (int v = 0; v < kSteps; ++v) {
            const Xy p{c.x + (u / double(kSteps - 1) - 0.5) * s.pitch_mm, c.y + (v / double(kSteps - 1) - 0.5) * s.pitch_mm};
            bool inside = true;
            for (size_t e = 0; e < hex.size() && inside; ++e)
                inside = cross(hex[e], hex[(e + 1) % hex.size()], p) > 0 &&
                         segmentDistance(p, hex[e], hex[(e + 1) % hex.size()]) >= kReadEdgeMm;
            if (!inside) continue;
            const double d = triangleDistance(p, apex, m1, m2);
            if (d >= best_d) {
                best_d = d;
                best = p;
            }
        }
    return best;
}

// Is the notch with this apex usable? Every pillar it cuts keeps at least
// half its hexagon and a point to be read at (notchReadPoint); its apex and
// edges keep clear of every corner and edge of the hexagons it cuts.
bool notchIsClean(const Scene& s, const Xy& apex, const Xy& m1, const Xy& m2, const std::vector<int32_t>& cut) {
    const double clear = kMarkClearanceMm;
    for (int32_t k : cut) {
        const std::vector<Xy> hex = hexPolygon(s, size_t(k));
        const std::vector<Xy> lost = clipLeft(clipLeft(clipLeft(hex, apex, m1), m1, m2), m2, apex);
        if (polygonArea(lost) > 0.5 * polygonArea(hex)) return false;
        if (!notchReadPoint(s, size_t(k), apex, m1, m2)) return false;
        for (int e = 0; e < kHexCorners; ++e) {
            const Xy& p = hex[size_t(e)];
            const Xy& q = hex[size_t(e + 1) % hex.size()];
            if (segmentDistance(p, apex, m1) < clear || segmentDistance(p, apex, m2) < clear) return false;
            if (segmentDistance(apex, p, q) < clear) return false;
        }
    }
    return true;
}

// Openings tried, widest first: 60 degrees reads as a clear V; 45 threads
// deeper between the centres of small corner pillars.
constexpr double kNotchOpeningsDeg[] = {60.0, 45.0};

// The V of a notch: apex `depth` from the corner o along direction `bisector`
// (radians), opening `opening_deg`, mouth one pitch behind the corner.
// Counter-clockwise apex, m1, m2.
void notchTriangle(const Scene& s, const Xy& o, double bisector, double opening_deg, double depth, Xy& apex, Xy& m1,
                   Xy& m2) {
    const double half = opening_deg / 2.0 * M_PI / 180.0;
    apex = {o.x + depth * std::cos(bisector), o.y + depth * std::sin(bisector)};
    // Every kept point lies on the far side of the corner (it is the extreme
    // one towards the south-west), so a mouth a pitch behind it leaves no skin.
    const double back = (depth + s.pitch_mm) / std::cos(half);
    m1 = {apex.x - back * std::cos(bisector - half), apex.y - back * std::sin(bisector - half)};
    m2 = {apex.x - back * std::cos(bisector + half), apex.y - back * std::sin(bisector + half)};
}

// Reach of a notch of this depth around its corner, for cellsNear.
double notchReach(const Scene& s, double depth) { return (depth + s.pitch_mm) / std::cos(M_PI / 6.0) + 2 * s.pitch_mm; }

void placeNotch(Scene& s) {
    const MarkParams& mp = s.params.marks;
    // The apex must keep kMarkClearanceMm from the edges of the hexagon it
    // stands in: impossible when the cells are narrower than twice that.
    if (s.pitch_mm < 2 * kMarkClearanceMm) {
        s.notes.push_back("orientation notch left out: cells of " + formatSignificant(s.pitch_mm, 3) +
                          " mm are too small to cut a notch into without thin slivers (use larger cells)");
        return;
    }
    const Xy o = toMm(s, originCorner(s));
    const std::vector<int32_t> near = cellsNear(s, o, notchReach(s, mp.notch_depth_mm) + mp.notch_depth_mm);
    // Into the model towards the north-east; the direction is turned (up to
    // 30 degrees either way) when that lets the V go deeper between the
    // centres of the corner pillars. Deepest wins, then the one nearest 45.
    double best_depth = 0, best_bisector = 0, best_opening = 0;
    const double step = 0.25;
    for (double opening : kNotchOpeningsDeg) {
        for (int turn : {0, -5, 5, -10, 10, -15, 15, -20, 20, -25, 25, -30, 30}) {
            const double bisector = (45.0 + turn) * M_PI / 180.0;
            // A narrower V must go clearly deeper to be worth it.
            const double better = best_opening > opening ? best_depth + 1.0 : best_depth;
            const double shallowest = std::min(mp.notch_min_depth_mm, mp.notch_depth_mm);
            for (double depth = mp.notch_depth_mm; depth >= shallowest - 1e-9; depth -= step) {
                if (depth <= better + 1e-9) break;
                Xy apex, m1, m2;
                notchTriangle(s, o, bisector, opening, depth, apex, m1, m2);
                const std::vector<int32_t> cut = cellsMeeting(s, near, apex, m1, m2);
                if (cut.empty() || !notchIsClean(s, apex, m1, m2, cut)) continue;
                best_depth = depth;
                best_bisector = bisector;
                best_opening = opening;
                break;
            }
            if (best_depth >= mp.notch_depth_mm - 1e-9) break;
        }
        if (best_depth >= mp.notch_depth_mm - 1e-9) break;
    }
    if (best_depth == 0) {
        s.notes.push_back("orientation notch left out: a V at least " + formatSignificant(mp.notch_min_depth_mm, 3) +
                          " mm deep would cut away more than half of a corner pillar (use larger cells)");
        return;
    }
    Xy apex, m1, m2;
    notchTriangle(s, o, best_bisector, best_opening, best_depth, apex, m1, m2);
    Notch n;
    n.apex = toPlanar(s, apex);
    n.mouth_a = toPlanar(s, m1);
    n.mouth_b = toPlanar(s, m2);
    n.depth_mm = best_depth;
    n.width_mm = 2.0 * best_depth * std::tan(best_opening / 2.0 * M_PI / 180.0);
    n.opening_deg = best_opening;
    s.marks.notch = n;
    if (best_depth < mp.notch_depth_mm - 1e-9)
        s.notes.push_back("orientation notch: " + formatSignificant(best_depth, 3) + " mm deep (asked " + formatSignificant(mp.notch_depth_mm, 3) +
                          " mm): a deeper V would cut away more than half of a corner pillar");
}

// ------------------------------------------------------------- triangle ---

// Connected regions of kept data cells with equal spans; -1 for other cells.
std::vector<int32_t> flatRegions(const Scene& s) {
    const size_t n = s.keptCount();
    std::vector<int32_t> label(n, -1);
    int32_t next = 0;
    std::vector<int32_t> stack;
    for (size_t start = 0; start < n; ++start) {
        if (label[start] >= 0 || s.kind[start] != CellKind::Data || s.drawn_by_face[start]) continue;
        label[start] = next;
        stack.push_back(int32_t(start));
        while (!stack.empty()) {
            const size_t k = size_t(stack.back());
            stack.pop_back();
            for (int e = 0; e < kHexCorners; ++e) {
                const int32_t o = s.keptNeighbour(k, e);
                if (o < 0 || label[size_t(o)] >= 0 || s.kind[size_t(o)] != CellKind::Data || s.drawn_by_face[size_t(o)])
                    continue;
                if (s.top[size_t(o)] != s.top[k] || s.bottom[size_t(o)] != s.bottom[k]) continue;
                label[size_t(o)] = next;
                stack.push_back(o);
            }
        }
        ++next;
    }
    return label;
}

// Distance in hex steps from each kept cell to the nearest cell outside its
// region (a cell of another region, not kept, or beyond the grid).
std::vector<int32_t> stepsToEdge(const Scene& s, const std::vector<int32_t>& label) {
    const size_t n = s.keptCount();
    std::vector<int32_t> d(n, -1);
    std::deque<int32_t> queue;
    for (size_t k = 0; k < n; ++k) {
        if (label[k] < 0) continue;
        for (int e = 0; e < kHexCorners; ++e) {
            const int32_t o = s.keptNeighbour(k, e);
            if (o < 0 || label[size_t(o)] != label[k]) {
                d[k] = 1;
                queue.push_back(int32_t(k));
                break;
            }
        }
    }
    while (!queue.empty()) {
        const size_t k = size_t(queue.front());
        queue.pop_front();
        for (int e = 0; e < kHexCorners; ++e) {
            const int32_t o = s.keptNeighbour(k, e);
            if (o < 0 || d[size_t(o)] >= 0 || label[size_t(o)] != label[k]) continue;
            d[size_t(o)] = d[k] + 1;
            queue.push_back(o);
        }
    }
    return d;
}

// Distance (mm) from the centre of kept cell k to the nearest point of a
// hexagon outside its region (a lower bound: centre distance - circumradius).
double clearanceMm(const Scene& s, const std::vector<int32_t>& label, size_t k, int32_t steps) {
    const int32_t reach = steps + 2;
    const Xy c = toMm(s, hexCentre(s.grid, s.col[k], s.row[k]));
    double best = INFINITY;
    for (int32_t r = s.row[k] - reach; r <= s.row[k] + reach; ++r)
        for (int32_t cc = s.col[k] - reach; cc <= s.col[k] + reach; ++cc) {
            const int32_t o = s.keptAt(cc, r);
            if (o >= 0 && label[size_t(o)] == label[k]) continue;
            best = std::min(best, dist(c, toMm(s, hexCentre(s.grid, cc, r))));
        }
    return best - hexCircumradius(s.pitch_mm, s.y_scale);
}

// The boundary loop (counter-clockwise, lattice ids) of a set of kept cells,
// or empty if it is not exactly one loop.
std::vector<int64_t> outline(const Scene& s, const std::vector<int32_t>& cells, const std::vector<uint8_t>& in) {
    std::unordered_map<int64_t, int64_t> next;
    for (int32_t k : cells)
        for (int e = 0; e < kHexCorners; ++e) {
            const int32_t o = s.keptNeighbour(size_t(k), e);
            if (o >= 0 && in[size_t(o)]) continue;
            next[hexCornerId(s.grid, s.col[size_t(k)], s.row[size_t(k)], e)] =
                hexCornerId(s.grid, s.col[size_t(k)], s.row[size_t(k)], (e + 1) % kHexCorners);
        }
    std::vector<int64_t> loop;
    if (next.empty()) return loop;
    const int64_t start = next.begin()->first;
    for (int64_t v = start;;) {
        loop.push_back(v);
        auto it = next.find(v);
        if (it == next.end() || loop.size() > next.size()) return {};
        v = it->second;
        if (v == start) break;
    }
    if (loop.size() != next.size()) return {};
    return loop;
}

// Hex cells (kept indices) the triangle fits in: the cells of its region within
// `radius_mm` of its circumcentre, provided the triangle keeps `margin_mm`
// from their outline. Empty if not.
std::vector<int32_t> triangleHost(const Scene& s, const std::vector<int32_t>& label, size_t anchor, const Xy& centre,
                                  double radius_mm, const Xy tri[3], double margin_mm) {
    std::vector<int32_t> host;
    // Rows and columns within reach, kept to the grid and its ring of outside
    // cells (any cell beyond is as absent as the ring): a recorded triangle
    // read from a file may be far larger than the grid.
    const double reach = std::ceil(radius_mm / (s.pitch_mm * 0.8)) + 2;
    const auto from = [&](int32_t at) { return int32_t(std::max(-1.0, double(at) - reach)); };
    const auto to = [&](int32_t at, int32_t n) { return int32_t(std::min(double(n), double(at) + reach)); };
    if (!(reach >= 0)) return host;
    for (int32_t r = from(s.row[anchor]); r <= to(s.row[anchor], s.grid.rows); ++r)
        for (int32_t c = from(s.col[anchor]); c <= to(s.col[anchor], s.grid.cols); ++c) {
            const int32_t o = s.keptAt(c, r);
            if (dist(centre, toMm(s, hexCentre(s.grid, c, r))) > radius_mm) continue;
            if (o < 0 || label[size_t(o)] != label[anchor]) return {};
            host.push_back(o);
        }
    if (host.empty()) return {};
    // No pillar centre on the triangle's edge: its height is read there.
    for (int32_t k : host) {
        const Xy p = toMm(s, hexCentre(s.grid, s.col[size_t(k)], s.row[size_t(k)]));
        for (int e = 0; e < 3; ++e)
            if (segmentDistance(p, tri[e], tri[(e + 1) % 3]) < kReadPointClearanceMm) return {};
    }
    std::vector<uint8_t> in(s.keptCount(), 0);
    for (int32_t k : host) in[size_t(k)] = 1;
    const std::vector<int64_t> loop = outline(s, host, in);
    if (loop.empty()) return {};
    std::vector<Xy> poly;
    for (int64_t id : loop) poly.push_back(toMm(s, latticeVertexPoint(s.grid, id)));
    for (size_t n = 0; n < poly.size(); ++n) {
        const Xy& a = poly[n];
        const Xy& b = poly[(n + 1) % poly.size()];
        for (int e = 0; e < 3; ++e) {
            if (segmentDistance(tri[e], a, b) < margin_mm) return {};
            if (segmentDistance(a, tri[e], tri[(e + 1) % 3]) < margin_mm) return {};
        }
    }
    // Inside: the triangle's corner is inside the loop (even-odd rule).
    bool inside = false;
    for (size_t n = 0, m = poly.size() - 1; n < poly.size(); m = n++) {
        const Xy& a = poly[n];
        const Xy& b = poly[m];
        if ((a.y > tri[0].y) != (b.y > tri[0].y) && tri[0].x < (b.x - a.x) * (tri[0].y - a.y) / (b.y - a.y) + a.x)
            inside = !inside;
    }
    return inside ? host : std::vector<int32_t>{};
}

void placeTriangle(Scene& s) {
    const MarkParams& mp = s.params.marks;
    const std::vector<int32_t> label = flatRegions(s);
    const std::vector<int32_t> steps = stepsToEdge(s, label);
    std::vector<int32_t> order;
    for (size_t k = 0; k < s.keptCount(); ++k)
        if (label[k] >= 0) order.push_back(int32_t(k));
    // Deepest first; among equals the lower surface (the floor before a plateau), then row-major.
    std::stable_sort(order.begin(), order.end(), [&](int32_t a, int32_t b) {
        if (steps[size_t(a)] != steps[size_t(b)]) return steps[size_t(a)] > steps[size_t(b)];
        return s.top[size_t(a)] < s.top[size_t(b)];
    });
    if (order.size() > 24) order.resize(24);
    const double margin = kTriangleMarginMm;
    double best_leg = 0;
    for (int32_t ki : order) {
        const size_t k = size_t(ki);
        const double clear = clearanceMm(s, label, k, steps[k]);
        const Xy c = toMm(s, hexCentre(s.grid, s.col[k], s.row[k]));
        for (double leg = mp.triangle_leg_mm; leg >= mp.triangle_min_leg_mm - 1e-9; leg -= 0.5) {
            if (leg <= best_leg) break;
            const double lx = leg, ly = kTriangleLegRatio * leg;
            // Centroid on the cell centre: the centre is read under the
            // triangle, far from its edges; `circum` bounds the triangle around it.
            const double circum = std::hypot(2 * lx / 3, ly / 3);
            if (circum + margin > clear) continue;
            const Xy tri[3] = {{c.x - lx / 3, c.y - ly / 3}, {c.x + 2 * lx / 3, c.y - ly / 3}, {c.x - lx / 3, c.y + 2 * ly / 3}};
            std::vector<int32_t> host;
            // The host grows ring by ring until the triangle keeps its margin
            // (triangleHost refuses a host that leaves the region).
            for (int ring = 0; ring < 3 && host.empty(); ++ring)
                host = triangleHost(s, label, k, c, circum + hexCircumradius(s.pitch_mm, s.y_scale) + ring * s.pitch_mm, tri, margin);
            if (host.empty()) continue;
            OrientationTriangle t;
            t.corner = toPlanar(s, tri[0]);
            t.east = toPlanar(s, tri[1]);
            t.north = toPlanar(s, tri[2]);
            t.leg_x_mm = lx;
            t.leg_y_mm = ly;
            t.raise_units = std::max<int64_t>(1, snapUnits(mp.triangle_height_mm, s.z_snap_mm));
            t.anchor = int32_t(k);
            s.marks.triangle = t;
            best_leg = leg;
            break;
        }
        if (best_leg >= mp.triangle_leg_mm - 1e-9) break;
    }
    if (!s.marks.triangle)
        s.notes.push_back("orientation triangle left out: no flat region is large enough for legs of " +
                          formatSignificant(mp.triangle_min_leg_mm, 3) + " x " + formatSignificant(kTriangleLegRatio * mp.triangle_min_leg_mm, 3) +
                          std::string(" mm") + (s.marks.notch ? "; the notch marks the origin" : ""));
}

// ---------------------------------------------------------------- faces ---

Cdt::Point cdtPoint(const PlanarPoint& p) { return Cdt::Point(p.i, p.j); }

struct FaceBuilder {
    Scene& s;
    int64_t lattice_ids;
    std::map<std::pair<int64_t, int64_t>, int32_t> edge_face;  // directed edge -> face

    int64_t idOf(Cdt::Vertex_handle v) {
        if (v->info().id >= 0) return v->info().id;
        const auto& p = v->point();
        s.faces.extra.push_back({CGAL::to_double(p.x()), CGAL::to_double(p.y())});
        v->info().id = lattice_ids + int64_t(s.faces.extra.size()) - 1;
        return v->info().id;
    }

    // A face from triangles (CDT faces) and the kept cells it covers.
    void addFace(int32_t anchor, int64_t raise, const std::vector<Cdt::Face_handle>& tris, std::vector<int32_t> cells) {
        if (tris.empty()) return;
        PlanarFace f;
        f.anchor = anchor;
        f.raise_units = raise;
        f.cells = std::move(cells);
        std::map<std::pair<int64_t, int64_t>, int> count;
        for (const Cdt::Face_handle& t : tris) {
            const std::array<int64_t, 3> ids = {idOf(t->vertex(0)), idOf(t->vertex(1)), idOf(t->vertex(2))};
            f.triangles.push_back(ids);
            for (int e = 0; e < 3; ++e) count[{ids[e], ids[(e + 1) % 3]}] += 1;
        }
        std::unordered_map<int64_t, int64_t> next;
        for (const auto& [edge, n] : count)
            if (!count.count({edge.second, edge.first})) {
                if (!next.emplace(edge.first, edge.second).second)
                    throw InputError("orientation mark: a face's outline touches itself (internal)");
            }
        while (!next.empty()) {
            std::vector<int64_t> ring;
            const int64_t start = next.begin()->first;
            for (int64_t v = start;;) {
                ring.push_back(v);
                auto it = next.find(v);
                if (it == next.end()) throw InputError("orientation mark: a face's outline is open (internal)");
                const int64_t w = it->second;
                next.erase(it);
                v = w;
                if (v == start) break;
            }
            f.rings.push_back(std::move(ring));
        }
        const int32_t index = int32_t(s.faces.faces.size());
        for (const auto& ring : f.rings)
            for (size_t n = 0; n < ring.size(); ++n) edge_face[{ring[n], ring[(n + 1) % ring.size()]}] = index;
        s.faces.faces.push_back(std::move(f));
    }

    // What lies across each ring edge; a face's lattice edges are hexagon
    // edges of the cells it replaces.
    void resolveAcross() {
        for (size_t fi = 0; fi < s.faces.faces.size(); ++fi) {
            PlanarFace& f = s.faces.faces[fi];
            f.across.clear();
            for (const auto& ring : f.rings) {
                std::vector<Across> a(ring.size());
                for (size_t n = 0; n < ring.size(); ++n) {
                    const int64_t u = ring[n], v = ring[(n + 1) % ring.size()];
                    auto it = edge_face.find({v, u});
                    if (it != edge_face.end()) {
                        a[n] = {Across::Kind::Face, it->second};
                        continue;
                    }
                    a[n] = {Across::Kind::Outside, -1};
                    if (u >= lattice_ids || v >= lattice_ids) continue;
                    for (int32_t k : f.cells) {
                        for (int e = 0; e < kHexCorners; ++e) {
                            if (hexCornerId(s.grid, s.col[size_t(k)], s.row[size_t(k)], e) != u ||
                                hexCornerId(s.grid, s.col[size_t(k)], s.row[size_t(k)], (e + 1) % kHexCorners) != v)
                                continue;
                            int32_t nc, nr;
                            hexNeighbour(s.col[size_t(k)], s.row[size_t(k)], e, nc, nr);
                            const int32_t o = s.keptAt(nc, nr);
                            if (o >= 0 && s.drawn_by_face[size_t(o)])
                                throw InputError("orientation mark: faces do not meet along a hex edge (internal)");
                            if (o >= 0) a[n] = {Across::Kind::Cell, o};
                        }
                    }
                }
                f.across.push_back(std::move(a));
            }
        }
    }
};

void insertHexEdges(Cdt& cdt, const Scene& s, size_t k) {
    Cdt::Vertex_handle h[kHexCorners];
    for (int e = 0; e < kHexCorners; ++e) {
        h[e] = cdt.insert(cdtPoint(toPlanar(hexCorner(s.grid, s.col[k], s.row[k], e))));
        h[e]->info().id = hexCornerId(s.grid, s.col[k], s.row[k], e);
    }
    for (int e = 0; e < kHexCorners; ++e) cdt.insert_constraint(h[e], h[(e + 1) % kHexCorners]);
}

PlanarPoint centroid(const Cdt::Face_handle& f) {
    double i = 0, j = 0;
    for (int v = 0; v < 3; ++v) {
        i += CGAL::to_double(f->vertex(v)->point().x()) / 3.0;
        j += CGAL::to_double(f->vertex(v)->point().y()) / 3.0;
    }
    return {i, j};
}

}  // namespace

void buildMarkFaces(Scene& s) {
    s.faces = {};
    s.drawn_by_face.assign(s.keptCount(), 0);
    if (!s.marks.notch && !s.marks.triangle) return;
    FaceBuilder fb{s, latticeVertexIdCount(s.grid), {}};

    if (s.marks.notch) {
        const Notch& n = *s.marks.notch;
        const Xy apex = toMm(s, n.apex), m1 = toMm(s, n.mouth_a), m2 = toMm(s, n.mouth_b);
        if (!(n.depth_mm > 0 && n.depth_mm <= 1000)) throw InputError("orientation notch: depth_mm must be in (0, 1000]");
        const std::vector<int32_t> near = cellsNear(s, apex, dist(apex, m1) + 2 * s.pitch_mm);
        const std::vector<int32_t> cut = cellsMeeting(s, near, apex, m1, m2);
        if (cut.empty() || !notchIsClean(s, apex, m1, m2, cut))
            throw InputError("orientation notch: it does not fit this model's cells");
        Cdt cdt;
        for (int32_t k : cut) insertHexEdges(cdt, s, size_t(k));
        Cdt::Vertex_handle va = cdt.insert(cdtPoint(n.apex));
        cdt.insert_constraint(va, cdt.insert(cdtPoint(n.mouth_a)));
        cdt.insert_constraint(va, cdt.insert(cdtPoint(n.mouth_b)));
        std::vector<std::vector<Cdt::Face_handle>> per_cell(cut.size());
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            const PlanarPoint c = centroid(f);
            const Xy cm = toMm(s, c);
            if (insideTriangle(cm, apex, m1, m2)) continue;
            int32_t col, row;
            if (!hexCellAt(s.grid, c.i * 0.5, c.j / (2.0 * kSqrt3), col, row)) continue;
            const int32_t kept = s.keptAt(col, row);
            const auto at = std::find(cut.begin(), cut.end(), kept);
            if (at == cut.end()) continue;
            per_cell[size_t(at - cut.begin())].push_back(f);
        }
        for (size_t n2 = 0; n2 < cut.size(); ++n2) {
            s.drawn_by_face[size_t(cut[n2])] = 1;
            fb.addFace(cut[n2], 0, per_cell[n2], {cut[n2]});
            const std::optional<Xy> at = notchReadPoint(s, size_t(cut[n2]), apex, m1, m2);
            s.faces.faces.back().read_point = toPlanar(s, *at);
        }
    }
    if (s.marks.triangle) {
        const OrientationTriangle& t = *s.marks.triangle;
        if (t.anchor < 0 || size_t(t.anchor) >= s.keptCount())
            throw InputError("orientation triangle: its anchor cell is not a kept cell");
        // The host: the anchor's flat region cells the triangle lies over, plus one ring.
        const std::vector<int32_t> label = flatRegions(s);
        if (label[size_t(t.anchor)] < 0) throw InputError("orientation triangle: its anchor cell is not on a flat region");
        const Xy tri[3] = {toMm(s, t.corner), toMm(s, t.east), toMm(s, t.north)};
        const Xy c{(tri[0].x + tri[1].x + tri[2].x) / 3, (tri[0].y + tri[1].y + tri[2].y) / 3};
        const double circum = std::max({dist(c, tri[0]), dist(c, tri[1]), dist(c, tri[2])});
        const double margin = kTriangleMarginMm;
        std::vector<int32_t> host;
        for (int ring = 0; ring < 3 && host.empty(); ++ring)
            host = triangleHost(s, label, size_t(t.anchor), c, circum + hexCircumradius(s.pitch_mm, s.y_scale) + ring * s.pitch_mm, tri, margin);
        if (host.empty()) throw InputError("orientation triangle: it does not fit its flat region");
        std::vector<uint8_t> in(s.keptCount(), 0);
        for (int32_t k : host) in[size_t(k)] = 1;
        const std::vector<int64_t> loop = outline(s, host, in);
        Cdt cdt;
        std::vector<Cdt::Vertex_handle> hv;
        for (int64_t id : loop) {
            hv.push_back(cdt.insert(cdtPoint(toPlanar(latticeVertexPoint(s.grid, id)))));
            hv.back()->info().id = id;
        }
        for (size_t n = 0; n < hv.size(); ++n) cdt.insert_constraint(hv[n], hv[(n + 1) % hv.size()]);
        Cdt::Vertex_handle tv[3] = {cdt.insert(cdtPoint(t.corner)), cdt.insert(cdtPoint(t.east)),
                                    cdt.insert(cdtPoint(t.north))};
        for (int e = 0; e < 3; ++e) cdt.insert_constraint(tv[e], tv[(e + 1) % 3]);
        // Parity of the constraints crossed from the infinite face: odd = host
        // (inside the outline, outside the triangle); the triangle is the even
        // part inside it.
        markInsideByParity(cdt);
        std::vector<Cdt::Face_handle> host_tris, tri_tris;
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            if (f->info() % 2 == 1) host_tris.push_back(f);
            else if (insideTriangle(toMm(s, centroid(f)), tri[0], tri[1], tri[2])) tri_tris.push_back(f);
        }
        for (int32_t k : host) s.drawn_by_face[size_t(k)] = 1;
        fb.addFace(t.anchor, 0, host_tris, host);
        fb.addFace(t.anchor, t.raise_units, tri_tris, {});
    }
    fb.resolveAcross();
}

PlanarPoint readPoint(const Scene& s, size_t kept) {
    if (!s.drawn_by_face.empty() && s.drawn_by_face[kept])
        for (const PlanarFace& f : s.faces.faces)
            if (f.read_point && size_t(f.anchor) == kept) return *f.read_point;
    const LatticePoint c = hexCentre(s.grid, s.col[kept], s.row[kept]);
    return {double(c.i), double(c.j)};
}

int64_t markRaiseAtCentre(const Scene& s, size_t kept) {
    if (!s.marks.triangle) return 0;
    const OrientationTriangle& t = *s.marks.triangle;
    const Xy p = toMm(s, hexCentre(s.grid, s.col[kept], s.row[kept]));
    return insideTriangle(p, toMm(s, t.corner), toMm(s, t.east), toMm(s, t.north))
               ? t.raise_units
               : 0;
}

bool marksOnTab(const SceneParams& p) {
    return p.marks.place == MarkPlace::Tab && (p.marks.notch || p.marks.triangle);
}

void placeMarks(Scene& s) {
    s.marks = {};
    buildMarkFaces(s);
    // On a tab the marks are placed after the top shapes (the tab's
    // feature, gen/model/features/tab/), not in the data.
    if (s.keptCount() == 0 || marksOnTab(s.params)) return;
    if (s.params.marks.notch) {
        placeNotch(s);
        buildMarkFaces(s);
    }
    if (s.params.marks.triangle) {
        placeTriangle(s);
        buildMarkFaces(s);
    }
}

namespace {

PlanarPoint lerp(const PlanarPoint& a, const PlanarPoint& b, double t) {
    return {a.i + t * (b.i - a.i), a.j + t * (b.j - a.j)};
}

}  // namespace

ProbeSet markProbes(const Scene& s) {
    ProbeSet set{"marks", kMarkProbesTitle, {}};
    std::vector<SurfaceProbe>& out = set.probes;
    if (const auto& t = s.marks.triangle; t && t->anchor >= 0 && size_t(t->anchor) < s.keptCount()) {
        const double z = s.zMm(s.top[size_t(t->anchor)] + t->raise_units);
        const PlanarPoint centroid{(t->corner.i + t->east.i + t->north.i) / 3, (t->corner.j + t->east.j + t->north.j) / 3};
        // A fifth of the way from each corner to the centroid: inside the
        // triangle, so a triangle moved or shrunk by more than that is missed.
        const std::pair<const char*, PlanarPoint> places[] = {
            {"the orientation triangle's middle", centroid},
            {"the orientation triangle's right-angle corner", lerp(t->corner, centroid, 0.2)},
            {"the orientation triangle's east corner", lerp(t->east, centroid, 0.2)},
            {"the orientation triangle's north corner", lerp(t->north, centroid, 0.2)},
        };
        for (const auto& [what, p] : places) {
            const Vec3 q = s.point(p, 0);
            out.push_back({what, q.x, q.y, false, z});
        }
    }
    if (const auto& n = s.marks.notch) {
        // A quarter of the way from the V's apex to the middle of its mouth:
        // inside the model's outline, inside the cut.
        const PlanarPoint mouth{0.5 * (n->mouth_a.i + n->mouth_b.i), 0.5 * (n->mouth_a.j + n->mouth_b.j)};
        const Vec3 q = s.point(lerp(n->apex, mouth, 0.25), 0);
        out.push_back({"inside the orientation notch", q.x, q.y, true, 0});
    }
    return set;
}

}  // namespace tsf
