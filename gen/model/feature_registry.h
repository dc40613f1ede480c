// The registry of features (gen/model/feature.h): the one list of the
// features that follow the contract, and what the rest of tsf asks of all
// of them at once. buildScene places them, the lists of attachments,
// records and facts, the key and the tiles read them from here, so none of
// those names a feature of the registry.
#pragma once

#include <vector>

#include "gen/model/feature.h"
#include "gen/model/scene.h"

namespace tsf {

/// Every feature in the registry, in the order they are placed (the
/// braille legend, the tactile scale, the edge ruler).
const std::vector<const Feature*>& features();

/// Places each feature of `phase`, in the registry's order, and adds the
/// footprint each claims to Scene::claims.
void placeFeatures(Scene& scene, FeaturePhase phase);

/// True when some feature of the Scene lets a reader measure values by it.
bool sceneMeasures(const Scene& scene);

/// The first feature of the Scene that refuses a cut into tiles; null
/// when none does.
const Feature* featureRefusingTiles(const Scene& scene);

}  // namespace tsf
