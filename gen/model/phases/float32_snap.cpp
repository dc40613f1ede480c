#include "gen/model/phases/float32_snap.h"

#include <algorithm>
#include <cmath>

#include "gen/model/feature_registry.h"
#include "gen/model/phases/scene_limits.h"
#include "gen/model/features/top_shapes.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {

double highestZMm(const Scene& s) {
    int64_t top = highestPillarTop(s);
    if (s.marks.triangle) top = std::max(top, s.top[size_t(s.marks.triangle->anchor)] + s.marks.triangle->raise_units);
    double z = s.zMm(top);
    for (const Feature* f : features())
        if (f->highest_z_mm)
            if (const std::optional<double> highest = f->highest_z_mm(s)) z = std::max(z, *highest);
    return z;
}

namespace {

// The finest "nice" z grid (1, 2 or 5 x 10^k mm) whose steps float32 keeps
// apart at the Scene's highest z: four times the largest spacing of float32
// numbers there (2^-23 of the value, relative), so two heights a step apart
// never round to one and a thin triangle keeps its area.
double float32SafeSnapMm(const Scene& s) {
    const double need = 4.0 * std::ldexp(std::max(1.0, highestZMm(s)), -23);
    double decade = std::pow(10.0, std::floor(std::log10(need)));
    for (;; decade *= 10.0)
        for (const double m : {1.0, 2.0, 5.0})
            if (m * decade >= need * (1 - 1e-12)) return std::max(s.z_snap_mm, m * decade);
}

}  // namespace

std::optional<double> float32SnapMm(const SceneParams& params, const Scene& s) {
    if (!params.stored_as_float32) return std::nullopt;
    const double snap = float32SafeSnapMm(s);
    if (!(snap > s.z_snap_mm)) return std::nullopt;
    if (snap > kMaxSnapMm)
        throw InputError("the model is " + formatSignificant(highestZMm(s), 4) +
                         " mm tall: a float32 STL or 3MF cannot hold its heights to " + formatSignificant(kMaxSnapMm) +
                         " mm; make it lower (--height) or write OFF or OBJ");
    return snap;
}

SceneParams coarserSnap(const SceneParams& params, double snap_mm) {
    SceneParams coarser = params;
    coarser.z_snap_mm = snap_mm;
    coarser.stored_as_float32 = false;
    return coarser;
}

void noteCoarserSnap(const SceneParams& params, double snap_mm, Scene& again) {
    again.params.stored_as_float32 = true;
    again.notes.push_back("heights snapped to " + formatSignificant(snap_mm) + " mm instead of " +
                          formatSignificant(params.z_snap_mm) + " mm: at " + formatSignificant(highestZMm(again), 4) +
                          " mm the float32 coordinates of STL and 3MF resolve no finer (OFF and OBJ keep the "
                          "finer grid)");
}

}  // namespace tsf
