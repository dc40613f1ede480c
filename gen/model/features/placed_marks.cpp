// See placed_marks.h.
#include "gen/model/features/placed_marks.h"

#include <algorithm>
#include <optional>
#include <utility>

#include "gen/model/feature_registry.h"

namespace tsf {

PlacedMarks placedMarks(const Scene& s) {
    if (std::optional<PlacedMarks> carried = carriedMarks(s)) return std::move(*carried);
    PlacedMarks m;
    if (s.marks.notch) {
        m.has_notch = true;
        m.notch_depth_mm = s.marks.notch->depth_mm;
    }
    if (s.marks.triangle) {
        m.has_triangle = true;
        m.long_leg_mm = std::max(s.marks.triangle->leg_x_mm, s.marks.triangle->leg_y_mm);
        m.short_leg_mm = std::min(s.marks.triangle->leg_x_mm, s.marks.triangle->leg_y_mm);
    }
    m.triangle_place = "on a flat region of the model";
    m.where = "in the data";
    return m;
}

}  // namespace tsf
