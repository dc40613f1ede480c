#include "gen/model/phases/scene_limits.h"

#include <cmath>
#include <sstream>
#include <string>

#include "gen/util/error.h"

namespace tsf {

namespace {

void requireFinitePositive(double v, const char* name, bool allow_zero = false) {
    if (!std::isfinite(v) || v < 0 || (!allow_zero && v == 0)) {
        std::ostringstream s;
        s << name << " must be a finite number " << (allow_zero ? ">= 0" : "> 0") << " (got " << v << ")";
        throw InputError(s.str());
    }
}

}  // namespace

void checkSceneParams(const HexField& field, const SceneParams& p) {
    if (field.grid.cols <= 0 || field.grid.rows <= 0)
        throw InputError(field.source, 0, 0, "the field is empty (no rows or no columns)");
    if (field.grid.cols > kMaxGridSide || field.grid.rows > kMaxGridSide)
        throw InputError(field.source, 0, 0, "the hex grid is larger than " + std::to_string(kMaxGridSide) + " cells per side");
    if (int64_t(field.values.size()) != field.grid.cellCount())
        throw InputError(field.source, 0, 0, "internal: field value count does not match its grid");
    requireFinitePositive(p.pitch_mm, "cell size (pitch, mm)", true);
    if (p.pitch_mm == 0) {
        requireFinitePositive(p.fit_width_mm, "fit width (mm)");
        requireFinitePositive(p.fit_depth_mm, "fit depth (mm)");
    }
    requireFinitePositive(p.max_height_mm, "maximum height (mm)", true);
    requireFinitePositive(p.base_mm, "base thickness (mm)");
    if (!(p.z_snap_mm >= kMinSnapMm && p.z_snap_mm <= kMaxSnapMm)) {
        std::ostringstream s;
        s << "z snap step must be between " << kMinSnapMm << " and " << kMaxSnapMm << " mm (got " << p.z_snap_mm << ")";
        throw InputError(s.str());
    }
    if (p.base_mm < p.z_snap_mm)
        throw InputError("base thickness must be at least one z snap step (" + std::to_string(p.z_snap_mm) + " mm)");
    if (p.max_height_mm + 2 * p.base_mm > kMaxModelMm) throw InputError("model height is larger than 100 m; check the units (mm)");
    if (p.baseline_mode == BaselineMode::Value && !std::isfinite(p.baseline_value))
        throw InputError("baseline value must be finite");
    if (p.value_max && !std::isfinite(*p.value_max)) throw InputError("value at maximum height must be finite");
    if (!std::isfinite(p.steepness) || p.steepness <= 0)
        throw InputError("steepness must be a finite number > 0 (got " + std::to_string(p.steepness) + ")");
    if (!(p.max_slope_deg > 0 && p.max_slope_deg <= kMaxSlopeLimitDeg))
        throw InputError("--max-slope must be more than 0 and at most " + std::to_string(int(kMaxSlopeLimitDeg)) +
                         " degrees (got " + std::to_string(p.max_slope_deg) +
                         "): a steeper top is a wall to a finger and a blade to a nozzle");
    if (p.halves && p.bottom != Bottom::Mirrored)
        throw InputError("--halves cuts a mirrored model at its slab; a flat model already prints without supports. "
                         "Add --mirror, or leave out --halves");
    if (p.halves && p.tilt != TiltSource::None)
        throw InputError("--halves does not combine with --tilt yet (a tilted underside has no flat slab to cut "
                         "at); leave out one of them");
}

}  // namespace tsf
