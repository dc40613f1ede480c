// Rows of points parallel to a triangle's longest edge. See triangle_samples.h.
#include "verify/triangle_samples.h"

#include <cassert>
#include <cmath>

namespace tsf {
namespace {

// Row spacing as a fraction of the covering radius: sqrt(3) / 2, so that the
// step to the row below (<= sqrt(3)/2 r) and half the spacing along a row
// (<= r / 2) add up, in quadrature, to r.
constexpr double kRowSpacingFraction = 0.86602540378443864676;

Vec3 lerp(const Vec3& p, const Vec3& q, double t) {
    return {p.x + t * (q.x - p.x), p.y + t * (q.y - p.y), p.z + t * (q.z - p.z)};
}
double dist(const Vec3& p, const Vec3& q) { return std::hypot(q.x - p.x, q.y - p.y, q.z - p.z); }

// Calls row(left, right, k, first_row, last_row) for each row, base first;
// the row holds k + 1 points from left to right (one point when k = 0).
template <class Row>
void forEachRow(const Vec3& a0, const Vec3& b0, const Vec3& c0, double r, Row&& row) {
    assert(r > 0 && std::isfinite(r));
    // Relabel so that (a, b) is the longest edge and c the apex.
    const double ab = dist(a0, b0), bc = dist(b0, c0), ca = dist(c0, a0);
    const Vec3 *a = &a0, *b = &b0, *c = &c0;
    if (bc >= ab && bc >= ca) {
        a = &b0;
        b = &c0;
        c = &a0;
    } else if (ca >= ab && ca >= bc) {
        a = &c0;
        b = &a0;
        c = &b0;
    }
    const double base = dist(*a, *b);
    // Height of the apex over the base line.
    double height = 0;
    if (base > 0) {
        const Vec3 u{(b->x - a->x) / base, (b->y - a->y) / base, (b->z - a->z) / base};
        const Vec3 ac{c->x - a->x, c->y - a->y, c->z - a->z};
        const double along = ac.x * u.x + ac.y * u.y + ac.z * u.z;
        height = std::hypot(ac.x - along * u.x, ac.y - along * u.y, ac.z - along * u.z);
    }
    const double rows = std::ceil(height / (r * kRowSpacingFraction));
    const size_t m = size_t(rows);
    for (size_t j = 0; j <= m; ++j) {
        const double f = m ? double(j) / double(m) : 0.0;
        const double length = base * (1.0 - f);
        const size_t k = size_t(std::ceil(length / r));
        row(lerp(*a, *c, f), lerp(*b, *c, f), k, j == 0, j == m);
    }
}

// The points of a row that are corners of the triangle: the base row's two
// ends (one when they coincide) and the apex, which is the last row when
// there is more than one.
bool isCorner(size_t i, size_t k, bool first_row, bool last_row) {
    if (first_row) return i == 0 || i == k;
    return last_row;
}

}  // namespace

size_t triangleSampleCount(const Vec3& a, const Vec3& b, const Vec3& c, double radius_mm, Corners corners) {
    size_t n = 0;
    forEachRow(a, b, c, radius_mm, [&](const Vec3&, const Vec3&, size_t k, bool first, bool last) {
        n += k + 1;
        if (corners == Corners::Omit) n -= first ? (k ? 2 : 1) : (last ? 1 : 0);
    });
    return n;
}

void sampleTriangle(const Vec3& a, const Vec3& b, const Vec3& c, double radius_mm, std::vector<Vec3>& out,
                    Corners corners) {
    forEachRow(a, b, c, radius_mm, [&](const Vec3& left, const Vec3& right, size_t k, bool first, bool last) {
        for (size_t i = 0; i <= k; ++i) {
            if (corners == Corners::Omit && isCorner(i, k, first, last)) continue;
            out.push_back(k ? lerp(left, right, double(i) / double(k)) : left);
        }
    });
}

}  // namespace tsf
