// Number formatting shared by the verifier's messages (internal to verify/).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "gen/geometry/mesh.h"

namespace tsf::detail {

/// Millimetres with 3 decimals (1 um), the precision of the model's xy grid.
inline std::string fmtMm(double v) {
    if (std::isnan(v)) return "n/a";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.3f", v);
    return buf;
}

/// A general number with up to 6 significant digits.
inline std::string fmtNum(double v) {
    if (std::isnan(v)) return "n/a";
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

/// "(x, y, z) mm".
inline std::string fmtPoint(const Vec3& p) {
    return "(" + fmtMm(p.x) + ", " + fmtMm(p.y) + ", " + fmtMm(p.z) + ") mm";
}

inline Vec3 boundsCentre(const Bounds& b) {
    return {0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y), 0.5 * (b.min.z + b.max.z)};
}

}  // namespace tsf::detail
