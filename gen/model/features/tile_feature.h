// A tile of a model cut into tiles (gen/model/features/tiles.h) as a
// feature of the registry (gen/model/feature.h, gen/model/feature_registry.h):
// of the cells the cull keeps it keeps its share, pits its code into its
// bottom under level tops before the tops are shaped (FeaturePhase::UnderTops),
// and hands the pits in as cuts into the bottom; in the whole a tiling is
// checked against, it keeps level the cells its tiles keep level.
#pragma once

#include "gen/model/feature.h"

namespace tsf {

/// The tile's entry in the feature registry.
const Feature& tileFeature();

}  // namespace tsf
