#include "gen/geometry/mesh.h"

#include <cmath>
#include <limits>

namespace tsf {

Bounds meshBounds(const Mesh& mesh) {
    const double inf = std::numeric_limits<double>::infinity();
    Bounds b{{inf, inf, inf}, {-inf, -inf, -inf}};
    for (const Vec3& p : mesh.positions) extendBounds(b, p);
    return b;
}

double signedVolume(const Mesh& mesh) {
    // Sum of signed tetrahedra against a reference point near the mesh, which
    // keeps the terms small and the sum accurate for models far from 0.
    if (mesh.positions.empty()) return 0.0;
    const Vec3 o = mesh.positions[0];
    double six_v = 0.0;
    for (const auto& t : mesh.triangles) {
        const Vec3& a = mesh.positions[t[0]];
        const Vec3& b = mesh.positions[t[1]];
        const Vec3& c = mesh.positions[t[2]];
        const double ax = a.x - o.x, ay = a.y - o.y, az = a.z - o.z;
        const double bx = b.x - o.x, by = b.y - o.y, bz = b.z - o.z;
        const double cx = c.x - o.x, cy = c.y - o.y, cz = c.z - o.z;
        six_v += ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
    }
    return six_v / 6.0;
}

double triangleArea(const Mesh& m, const std::array<uint32_t, 3>& t) {
    const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const double vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
    return 0.5 * std::hypot(uy * vz - uz * vy, uz * vx - ux * vz, ux * vy - uy * vx);
}

}  // namespace tsf
