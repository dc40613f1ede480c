#include "gen/model/phases/value_mapping.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "gen/util/error.h"

namespace tsf {

ValueMapping resolveValueMapping(const HexField& field, const SceneParams& p, std::vector<std::string>& notes) {
    double vmin = INFINITY, vmax = -INFINITY;
    for (double v : field.values) {
        if (std::isnan(v)) continue;
        if (!std::isfinite(v))
            throw InputError(field.source, 0, 0, "the field holds an infinite value; values must be finite numbers");
        vmin = std::min(vmin, v);
        vmax = std::max(vmax, v);
    }
    if (!(vmin <= vmax)) throw InputError(field.source, 0, 0, "the field has no data: every cell is empty (NaN / no data)");
    ValueMapping m;
    m.transfer = p.transfer;
    m.max_height_mm = p.max_height_mm;
    switch (p.baseline_mode) {
        case BaselineMode::Zero: m.baseline = 0.0; break;
        case BaselineMode::Min: m.baseline = vmin; break;
        case BaselineMode::Value: m.baseline = p.baseline_value; break;
        default: m.baseline = vmin >= 0 ? 0.0 : vmin; break;
    }
    m.value_max = p.value_max ? *p.value_max : vmax;
    // Options that contradict each other or the data are errors, not a flat
    // block reported as a constant field.
    if (p.value_max && !(*p.value_max > m.baseline)) {
        std::ostringstream s;
        s.precision(17);
        s << "the value at full height (--value-max " << *p.value_max << ") must be above the baseline ("
          << m.baseline << ", from --baseline " << toString(p.baseline_mode) << ")";
        throw InputError(s.str());
    }
    if ((p.baseline_mode == BaselineMode::Value || p.baseline_mode == BaselineMode::Zero) && vmax < m.baseline) {
        std::ostringstream s;
        s.precision(17);
        s << "every value is below the baseline (--baseline " << m.baseline << "; the largest value is " << vmax
          << "): nothing would rise above the floor";
        throw InputError(field.source, 0, 0, s.str());
    }
    if (!(m.value_max > m.baseline)) {
        std::ostringstream s;
        s << "constant field (every value is " << vmin << (vmin == vmax ? "" : " or below the baseline")
          << "): all pillars have the same height";
        notes.push_back(s.str());
    }
    int64_t below = 0, above = 0;
    for (double v : field.values) {
        if (std::isnan(v)) continue;
        below += v < m.baseline;
        above += v > m.value_max;
    }
    if (below) notes.push_back(std::to_string(below) + " cells are below the baseline and sit at the floor");
    if (above) notes.push_back(std::to_string(above) + " cells are above the value at maximum height and are capped");
    return m;
}

}  // namespace tsf
