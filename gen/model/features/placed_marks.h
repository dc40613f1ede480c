// The orientation marks as placed, wherever they stand: carried by a
// feature beside the pillars (Feature::carried_marks, gen/model/feature.h:
// the orientation tab) or in the data (gen/model/features/marks.h). The
// model's key tells a reader of them, the tactile check measures them.
#pragma once

#include "gen/model/scene.h"

namespace tsf {

/// The marks a feature carries (carriedMarks, gen/model/feature_registry.h),
/// else the notch and the triangle in the data.
PlacedMarks placedMarks(const Scene& scene);

}  // namespace tsf
