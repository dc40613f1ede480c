#include "gen/geometry/joint_stress.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace tsf {
namespace {

using Mat3 = std::array<std::array<double, 3>, 3>;

// K^-1 m for a symmetric positive definite K (the adjugate over the
// determinant); none when K is singular (a joint of no extent).
bool solve(const Mat3& k, const Vec3& m, Vec3& out) {
    const double a = k[0][0], b = k[0][1], c = k[0][2], d = k[1][1], e = k[1][2], f = k[2][2];
    const double A = d * f - e * e, B = c * e - b * f, C = b * e - c * d;
    const double det = a * A + b * B + c * C;
    if (!(std::fabs(det) > 0) || !std::isfinite(det)) return false;
    const double D = a * f - c * c, E = b * c - a * e, F = a * d - b * b;
    out = {(A * m.x + B * m.y + C * m.z) / det, (B * m.x + D * m.y + E * m.z) / det, (C * m.x + E * m.y + F * m.z) / det};
    return true;
}

}  // namespace

double jointStressMpa(const std::vector<JointWall>& walls, const Vec3& push_at, double push_N) {
    // Each wall is a rectangle: centre c, unit direction e in plan, length
    // L, height h. Its second moments about O are exact: the integral of
    // d d^T over it is A ((c - O)(c - O)^T + L^2/12 e e^T + h^2/12 z z^T).
    struct Rect {
        Vec3 c, e;
        double len = 0, h = 0, area = 0;
    };
    std::vector<Rect> rects;
    double area = 0;
    Vec3 o{0, 0, 0};
    for (const JointWall& w : walls) {
        const double len = std::hypot(w.b.x - w.a.x, w.b.y - w.a.y), h = w.z_hi_mm - w.z_lo_mm;
        if (!(h > 0) || !(len > 0)) continue;
        Rect r{{0.5 * (w.a.x + w.b.x), 0.5 * (w.a.y + w.b.y), 0.5 * (w.z_lo_mm + w.z_hi_mm)},
               {(w.b.x - w.a.x) / len, (w.b.y - w.a.y) / len, 0}, len, h, len * h};
        area += r.area;
        o = {o.x + r.c.x * r.area, o.y + r.c.y * r.area, o.z + r.c.z * r.area};
        rects.push_back(r);
    }
    if (!(area > 0)) return std::numeric_limits<double>::infinity();
    o = {o.x / area, o.y / area, o.z / area};
    Mat3 second{};  // the integral of d d^T
    for (const Rect& r : rects) {
        const Vec3 d = sub(r.c, o);
        const double dv[3] = {d.x, d.y, d.z}, ev[3] = {r.e.x, r.e.y, r.e.z}, zv[3] = {0, 0, 1};
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j)
                second[i][j] += r.area * (dv[i] * dv[j] + r.len * r.len / 12 * ev[i] * ev[j] + r.h * r.h / 12 * zv[i] * zv[j]);
    }
    const double trace = second[0][0] + second[1][1] + second[2][2];
    Mat3 k{};
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) k[i][j] = (i == j ? trace : 0.0) - second[i][j];
    const Vec3 moment = cross(sub(push_at, o), Vec3{0, 0, -push_N});
    Vec3 turn;
    if (!solve(k, moment, turn)) return std::numeric_limits<double>::infinity();
    // The traction is affine over a wall, so its largest size is at a corner.
    const double direct = push_N / area;  // the push spread evenly, downward
    double worst = 0;
    for (const Rect& r : rects)
        for (const double u : {-0.5, 0.5})
            for (const double w : {-0.5, 0.5}) {
                const Vec3 at{r.c.x + u * r.len * r.e.x, r.c.y + u * r.len * r.e.y, r.c.z + w * r.h};
                const Vec3 t = cross(turn, sub(at, o));
                worst = std::max(worst, std::sqrt(t.x * t.x + t.y * t.y + (t.z - direct) * (t.z - direct)));
            }
    return worst;
}

JointLoad jointLoad(const std::vector<JointWall>& walls, const Bounds& b, double push_N) {
    JointLoad j;
    for (const JointWall& w : walls)
        if (w.z_hi_mm > w.z_lo_mm) {
            const double len = std::hypot(w.b.x - w.a.x, w.b.y - w.a.y);
            j.length_mm += len;
            j.area_mm2 += len * (w.z_hi_mm - w.z_lo_mm);
        }
    // The joint's centre in plan (the box's without a joint).
    Vec3 o{0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y), b.min.z};
    if (j.area_mm2 > 0) {
        Vec3 sum{0, 0, 0};
        for (const JointWall& w : walls) {
            const double area = std::hypot(w.b.x - w.a.x, w.b.y - w.a.y) * std::max(0.0, w.z_hi_mm - w.z_lo_mm);
            sum = {sum.x + 0.5 * (w.a.x + w.b.x) * area, sum.y + 0.5 * (w.a.y + w.b.y) * area, 0};
        }
        o = {sum.x / j.area_mm2, sum.y / j.area_mm2, 0};
    }
    // The far corner of its box, on its top.
    double far = -1;
    for (const double x : {b.min.x, b.max.x})
        for (const double y : {b.min.y, b.max.y})
            if (const double d = std::hypot(x - o.x, y - o.y); d > far) {
                far = d;
                j.push_at_mm = {x, y, b.max.z};
            }
    j.lever_mm = far;
    j.stress_MPa = jointStressMpa(walls, j.push_at_mm, push_N);
    return j;
}

}  // namespace tsf
