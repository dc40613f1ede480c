// The tactile scale (gen/model/features/scale.h) as a feature of the
// registry (gen/model/feature.h, gen/model/feature_registry.h): placed
// beside the pillars after the tab, claiming its box, with its body,
// read-back, record, facts and key paragraph; it lets a reader measure
// values, and a model carrying it is not cut into tiles.
#pragma once

#include "gen/model/feature.h"

namespace tsf {

/// The scale's entry in the feature registry.
const Feature& scaleFeature();

}  // namespace tsf
