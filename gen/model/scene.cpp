// The Scene's own arithmetic: value -> height, snapping, positions of
// lattice and planar points, the names of its enums. buildScene, which makes
// a Scene, is gen/model/build_scene.cpp.
#include "gen/model/scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <deque>
#include <limits>
#include <sstream>

namespace tsf {

int64_t snapUnits(double mm, double snap_mm) { return int64_t(std::llround(mm / snap_mm)); }

double maxSlopeDegFor(double nozzle_mm, double layer_mm) { return std::atan(layer_mm / nozzle_mm) * 180.0 / M_PI; }

double spanFraction(double v, double lo, double hi) {
    const double span = hi - lo;
    if (std::isfinite(span)) return (v - lo) / span;
    // Two finite values can lie further apart than the largest double
    // (1e308 and -1e308): halve them first, which cannot overflow and is
    // exact for every normal number.
    return (v / 2 - lo / 2) / (hi / 2 - lo / 2);
}

double ValueMapping::heightMm(double v) const {
    if (std::isnan(v)) return 0.0;
    if (!(value_max > baseline)) return v > baseline ? max_height_mm : 0.0;  // constant field
    const double t = std::clamp(spanFraction(v, baseline, value_max), 0.0, 1.0);
    switch (transfer) {
        case Transfer::Sqrt: return max_height_mm * std::sqrt(t);
        case Transfer::Log: return max_height_mm * std::log10(1.0 + 99.0 * t) / 2.0;
        default: return max_height_mm * t;
    }
}

double ValueMapping::valueAt(double h) const {
    if (!(value_max > baseline) || !(max_height_mm > 0)) return baseline;
    const double s = std::clamp(h / max_height_mm, 0.0, 1.0);
    double t = s;
    if (transfer == Transfer::Sqrt) t = s * s;
    if (transfer == Transfer::Log) t = (std::pow(10.0, 2.0 * s) - 1.0) / 99.0;
    const double span = value_max - baseline;
    if (std::isfinite(span)) return baseline + t * span;
    // A span beyond the largest double (see spanFraction): interpolate the
    // halves, and keep rounding from stepping past the ends.
    return std::clamp(2.0 * (baseline / 2 + t * (value_max / 2 - baseline / 2)), baseline, value_max);
}

double snapXy(double v) { return std::round(v / kXYSnapMm) * kXYSnapMm; }

Vec3 Scene::point(const LatticePoint& p, int64_t z_units) const {
    return {snapXy(latticeX(p, pitch_mm)), snapXy(latticeY(p, pitch_mm, y_scale)), zMm(z_units)};
}

Vec3 Scene::planarPoint(int64_t id, int64_t z_units) const {
    const int64_t lattice = latticeVertexIdCount(grid);
    if (id < lattice) return point(latticeVertexPoint(grid, id), z_units);
    if (!shapes.empty() && id >= shapes.first_id) return point(shapes.extra[size_t(id - shapes.first_id)], z_units);
    return point(faces.extra[size_t(id - lattice)], z_units);
}

Vec3 Scene::point(const PlanarPoint& p, int64_t z_units) const {
    return {snapXy(planarX(p, pitch_mm)), snapXy(planarY(p, pitch_mm, y_scale)), zMm(z_units)};
}

const char* toString(Transfer t) {
    switch (t) {
        case Transfer::Sqrt: return "sqrt";
        case Transfer::Log: return "log";
        default: return "linear";
    }
}
const char* toString(Cull c) {
    switch (c) {
        case Cull::None: return "none";
        case Cull::Concave: return "concave";
        default: return "hull";
    }
}
const char* toString(Bottom b) { return b == Bottom::Mirrored ? "mirrored" : "flat"; }
const char* toString(BaselineMode b) {
    switch (b) {
        case BaselineMode::Zero: return "zero";
        case BaselineMode::Min: return "min";
        case BaselineMode::Value: return "value";
        default: return "auto";
    }
}

const char* toString(TiltSource t) {
    switch (t) {
        case TiltSource::Points: return "points";
        case TiltSource::Gradient: return "gradient";
        default: return "none";
    }
}

}  // namespace tsf
