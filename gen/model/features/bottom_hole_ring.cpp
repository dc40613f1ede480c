// See bottom_hole_ring.h.
#include "gen/model/features/bottom_hole_ring.h"

#include <cmath>

namespace tsf {
namespace {
constexpr double kPi = 3.14159265358979323846;
}  // namespace

std::vector<PlanarPoint> bottomHoleRing(const Scene& s, const LatticePoint& c, double vertex_radius_mm) {
    // mm -> lattice coordinates (hex_grid.h: x = i p / 2, y = j p / (2 sqrt 3) y_scale):
    // round in mm however the lattice is stretched.
    const double per_i = s.pitch_mm / 2, per_j = s.pitch_mm / (2 * kSqrt3) * s.y_scale;
    std::vector<PlanarPoint> ring;
    for (int k = 0; k < kHoleSides; ++k) {
        const double a = 2 * kPi * (k + 0.5) / kHoleSides;
        ring.push_back({double(c.i) + vertex_radius_mm * std::cos(a) / per_i, double(c.j) + vertex_radius_mm * std::sin(a) / per_j});
    }
    return ring;
}

double bottomHoleVolumeMm3(const Scene& s, const BottomHole& h) {
    double area = 0;
    for (size_t n = 0; n < h.ring.size(); ++n) {
        const Vec3 a = s.point(h.ring[n], 0), b = s.point(h.ring[(n + 1) % h.ring.size()], 0);
        area += a.x * b.y - b.x * a.y;
    }
    area = std::fabs(area) / 2;
    return area * s.zMm(h.depth_units) + area * s.zMm(h.apex_units - h.depth_units) / 3;
}

}  // namespace tsf
