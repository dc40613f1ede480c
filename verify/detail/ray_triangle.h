// The watertight ray/triangle test of Woop, Benthin and Wald ("Watertight
// Ray/Triangle Intersection", JCGT 2013), shared by the verifier's two ray
// casters (verify/triangle_bvh.h, verify/column_grid.h) so that both answer
// every ray the same way: the edge functions of a shared edge are computed
// the same way for both of its triangles, so their signs are exact negations
// and a ray through a shared edge or vertex meets at least one of them. A
// ray lying in a triangle's plane does not hit it; a zero-area triangle is
// never hit. Units: millimetres; t is the ray parameter (origin + t * d).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace tsf::detail {

using V3 = std::array<double, 3>;

// kx, ky, kz and the shear (sx, sy, sz) are per ray.
struct RaySetup {
    V3 o, d;
    int kx, ky, kz;
    double sx, sy, sz;
};

inline RaySetup raySetup(const V3& o, const V3& d) {
    RaySetup r{o, d, 0, 0, 0, 0, 0, 0};
    int kz = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(d[k]) > std::fabs(d[kz])) kz = k;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);  // keep the winding of the triangles
    r.kx = kx;
    r.ky = ky;
    r.kz = kz;
    r.sx = d[kx] / d[kz];
    r.sy = d[ky] / d[kz];
    r.sz = 1.0 / d[kz];
    return r;
}

// Ray parameter of the hit, or a negative number for no hit; on a hit, the
// hit point from the triangle's own corners (barycentric), kept inside the
// triangle's bounding box so that a hit on a face parallel to an axis plane
// has exactly that face's coordinate (a top at z = 12.4 reads 12.4, not
// 12.4 plus the rounding of origin + t * direction).
inline double hitTriangle(const RaySetup& r, const V3& a, const V3& b, const V3& c, double t_max, V3& point) {
    const V3 A{a[0] - r.o[0], a[1] - r.o[1], a[2] - r.o[2]};
    const V3 B{b[0] - r.o[0], b[1] - r.o[1], b[2] - r.o[2]};
    const V3 C{c[0] - r.o[0], c[1] - r.o[1], c[2] - r.o[2]};
    const double Ax = A[r.kx] - r.sx * A[r.kz], Ay = A[r.ky] - r.sy * A[r.kz];
    const double Bx = B[r.kx] - r.sx * B[r.kz], By = B[r.ky] - r.sy * B[r.kz];
    const double Cx = C[r.kx] - r.sx * C[r.kz], Cy = C[r.ky] - r.sy * C[r.kz];
    const double U = Cx * By - Cy * Bx;
    const double V = Ax * Cy - Ay * Cx;
    const double W = Bx * Ay - By * Ax;
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return -1.0;
    const double det = U + V + W;
    if (det == 0.0) return -1.0;  // the ray lies in the triangle's plane, or the triangle has no area
    const double T = U * (r.sz * A[r.kz]) + V * (r.sz * B[r.kz]) + W * (r.sz * C[r.kz]);
    const double tt = T / det;
    if (!(tt >= 0.0) || tt > t_max) return -1.0;
    for (int k = 0; k < 3; ++k) {
        const double p = (U * a[k] + V * b[k] + W * c[k]) / det;
        const double lo = std::min({a[k], b[k], c[k]}), hi = std::max({a[k], b[k], c[k]});
        point[k] = std::clamp(p, lo, hi);
    }
    return tt;
}

}  // namespace tsf::detail
