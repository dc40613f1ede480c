// The orientation tab (orientation_tab.h) as a feature of the registry
// (gen/model/feature.h, gen/model/feature_registry.h): placed in
// FeaturePhase::Marks, before the features beside the pillars, claiming its
// box, with its body, read-back (the marks' set), check, bed width west of
// the pillars, record, facts and OpenSCAD piece. What a reader is told of it
// is the marks' paragraph of the key, and a tile carries it.
#pragma once

#include "gen/model/feature.h"

namespace tsf {

/// The tab's entry in the feature registry.
const Feature& tabFeature();

}  // namespace tsf
