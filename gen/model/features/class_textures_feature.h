// A class map's textures (gen/model/features/class_textures.h) as a feature
// of the registry (gen/model/feature.h, gen/model/feature_registry.h): a
// feature of the pillars themselves, decided in the frame (its classes at
// one height, its textures handed out), shaping the cells' tops, with its
// record, facts, what the summary and the key say of the heights and the
// classes, and the tactile check of its relief. A model carrying it is not
// cut into tiles (its tops are not level: gen/model/features/tiles.h).
#pragma once

#include "gen/model/feature.h"

namespace tsf {

/// The class textures' entry in the feature registry.
const Feature& classTexturesFeature();

}  // namespace tsf
