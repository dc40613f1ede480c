#include "gen/field/field_input.h"

#include <algorithm>

namespace tsf {

void describeValues(std::span<const double> values, FieldInput& into) {
    into.values = int64_t(values.size());
    into.nodata = 0;
    double lo = INFINITY, hi = -INFINITY, sum = 0.0;
    for (double v : values) {
        if (std::isnan(v)) {
            ++into.nodata;
            continue;
        }
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        sum += v;
    }
    const int64_t n = into.values - into.nodata;
    into.min = n > 0 ? lo : NAN;
    into.max = n > 0 ? hi : NAN;
    into.mean = n > 0 ? sum / double(n) : NAN;
}

}  // namespace tsf
