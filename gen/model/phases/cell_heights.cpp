#include "gen/model/phases/cell_heights.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace tsf {

CellHeights snapCellHeights(const HexField& field, const ValueMapping& mapping, double z_snap_mm) {
    const size_t n = field.values.size();
    CellHeights h;
    h.units.assign(n, 0);
    h.nonempty.assign(n, 0);
    for (size_t idx = 0; idx < n; ++idx) {
        const double v = field.values[idx];
        if (std::isnan(v)) continue;
        ++h.with_data;
        h.units[idx] = snapUnits(mapping.heightMm(v), z_snap_mm);
        h.nonempty[idx] = h.units[idx] > 0;
        h.nonempty_count += h.nonempty[idx];
    }
    return h;
}

int64_t lowerToMirroredFloor(const HexField& field, const std::vector<uint8_t>& keep, const SceneParams& params,
                             int64_t relief_below_units, CellHeights& heights) {
    if (params.bottom != Bottom::Mirrored) return 0;
    const size_t n = field.values.size();
    int64_t shift = std::numeric_limits<int64_t>::max();
    for (size_t idx = 0; idx < n; ++idx)
        if (keep[idx] && !std::isnan(field.values[idx])) shift = std::min(shift, heights.units[idx]);
    if (shift == std::numeric_limits<int64_t>::max() || params.tilt != TiltSource::None) shift = 0;
    shift = std::max<int64_t>(0, shift - relief_below_units);
    for (size_t idx = 0; idx < n; ++idx)
        if (!std::isnan(field.values[idx])) heights.units[idx] = std::max<int64_t>(0, heights.units[idx] - shift);
    return shift;
}

}  // namespace tsf
