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

}  // namespace tsf
