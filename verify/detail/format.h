// The verifier's messages' number conventions (internal to verify/): "n/a"
// for a figure that could not be measured, else gen/util/number_format.h.
#pragma once

#include <cmath>
#include <cstdio>
#include <string>

#include "gen/geometry/mesh.h"
#include "gen/util/number_format.h"

namespace tsf::detail {

/// Millimetres with 3 decimals (1 um), the precision of the model's xy grid.
inline std::string fmtMm(double v) { return std::isnan(v) ? "n/a" : formatFixed(v, 3); }

/// A general number with up to 6 significant digits.
inline std::string fmtNum(double v) { return std::isnan(v) ? "n/a" : formatSignificant(v, 6); }

/// "(x, y, z) mm".
inline std::string fmtPoint(const Vec3& p) {
    return "(" + fmtMm(p.x) + ", " + fmtMm(p.y) + ", " + fmtMm(p.z) + ") mm";
}

inline Vec3 boundsCentre(const Bounds& b) {
    return {0.5 * (b.min.x + b.max.x), 0.5 * (b.min.y + b.max.y), 0.5 * (b.min.z + b.max.z)};
}

}  // namespace tsf::detail
