#include "gen/model/convex_hull.h"

#include <algorithm>
#include <cmath>

namespace tsf {
namespace {
// Twice the signed area of (a, b, c); > 0 for a left turn. Lattice coordinates
// stay below 2^31 in magnitude (grid sizes are capped), so products fit int64.
int64_t cross(const LatticePoint& a, const LatticePoint& b, const LatticePoint& c) {
    return (b.i - a.i) * (c.j - a.j) - (b.j - a.j) * (c.i - a.i);
}

// Lattice -> pitch units (see hex_grid.h).
double px(const LatticePoint& p) { return double(p.i) * 0.5; }
double py(const LatticePoint& p) { return double(p.j) / (2.0 * kSqrt3); }

double segmentDistance(const LatticePoint& a, const LatticePoint& b, const LatticePoint& p) {
    const double ax = px(a), ay = py(a), bx = px(b), by = py(b), qx = px(p), qy = py(p);
    const double dx = bx - ax, dy = by - ay;
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((qx - ax) * dx + (qy - ay) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(qx - (ax + t * dx), qy - (ay + t * dy));
}
}  // namespace

std::vector<LatticePoint> convexHull(std::span<const LatticePoint> input) {
    std::vector<LatticePoint> pts(input.begin(), input.end());
    std::sort(pts.begin(), pts.end(), [](const LatticePoint& a, const LatticePoint& b) {
        return a.i != b.i ? a.i < b.i : a.j < b.j;
    });
    pts.erase(std::unique(pts.begin(), pts.end()), pts.end());
    if (pts.size() <= 2) return pts;
    std::vector<LatticePoint> hull(2 * pts.size());
    size_t k = 0;
    for (size_t n = 0; n < pts.size(); ++n) {  // lower chain
        while (k >= 2 && cross(hull[k - 2], hull[k - 1], pts[n]) <= 0) --k;
        hull[k++] = pts[n];
    }
    for (size_t n = pts.size() - 1, lower = k + 1; n-- > 0;) {  // upper chain
        while (k >= lower && cross(hull[k - 2], hull[k - 1], pts[n]) <= 0) --k;
        hull[k++] = pts[n];
    }
    hull.resize(k - 1);  // last point repeats the first
    return hull;
}

bool hullContains(std::span<const LatticePoint> hull, const LatticePoint& p) {
    if (hull.empty()) return false;
    if (hull.size() == 1) return hull[0] == p;
    if (hull.size() == 2) {
        const LatticePoint& a = hull[0];
        const LatticePoint& b = hull[1];
        return cross(a, b, p) == 0 && std::min(a.i, b.i) <= p.i && p.i <= std::max(a.i, b.i) &&
               std::min(a.j, b.j) <= p.j && p.j <= std::max(a.j, b.j);
    }
    for (size_t n = 0; n < hull.size(); ++n)
        if (cross(hull[n], hull[(n + 1) % hull.size()], p) < 0) return false;
    return true;
}

double hullDistancePitch(std::span<const LatticePoint> hull, const LatticePoint& p) {
    if (hull.empty()) return INFINITY;
    if (hullContains(hull, p)) return 0.0;
    if (hull.size() == 1) return segmentDistance(hull[0], hull[0], p);
    double best = INFINITY;
    for (size_t n = 0; n < hull.size(); ++n)
        best = std::min(best, segmentDistance(hull[n], hull[(n + 1) % hull.size()], p));
    return best;
}

}  // namespace tsf
