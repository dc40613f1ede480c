// Overhang of a mesh as it lies on the bed. See overhang.h.
#include "verify/overhang.h"

#include <algorithm>
#include <cmath>

namespace tsf {

OverhangFigures measureOverhang(const Mesh& mesh) {
    OverhangFigures f;
    if (mesh.triangles.empty()) return f;
    const double bed = meshBounds(mesh).min.z;
    const double sign = signedVolume(mesh) < 0 ? -1.0 : 1.0;
    const double limit_nz = -std::sin(kMaxOverhangDeg * 3.14159265358979323846 / 180.0);
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        const double lowest = std::min({a.z, b.z, c.z});
        if (std::max({a.z, b.z, c.z}) - bed <= kBedToleranceMm) continue;  // on the bed
        const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
        const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = sign * (ux * vy - uy * vx);
        const double len = std::sqrt(nx * nx + ny * ny + nz * nz);
        if (!(len > 0) || nz >= 0) continue;
        const double area = len / 2;
        f.downward_area_mm2 += area;
        if (nz / len >= limit_nz) continue;
        f.area_mm2 += area;
        ++f.triangles;
        if (lowest - bed > f.max_height_mm || f.triangles == 1) {
            f.max_height_mm = lowest - bed;
            f.worst_mm = {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3};
        }
    }
    return f;
}

}  // namespace tsf
