// The registry of features (gen/model/feature.h): the one list of the
// features that follow the contract, and what the rest of tsf asks of all
// of them at once. buildScene places them, the lists of attachments,
// records and facts, the key and the tiles read them from here, so none of
// those names a feature of the registry.
#pragma once

#include <initializer_list>
#include <optional>
#include <vector>

#include "gen/model/feature.h"
#include "gen/model/scene.h"

namespace tsf {

/// Every feature in the registry, in the order they are placed (the
/// braille legend, the orientation tab, the tactile scale, the edge ruler).
const std::vector<const Feature*>& features();

/// The features of the registry placed in `phases`, phase by phase in the
/// order given, each phase's in the registry's order: the lists that came
/// before the registry read each phase where its features stood (the
/// feature carrying the marks first among the bodies, its read-back last).
std::vector<const Feature*> featuresOf(std::initializer_list<FeaturePhase> phases);

/// Places each feature of `phase`, in the registry's order, and adds the
/// footprint each claims to Scene::claims.
void placeFeatures(Scene& scene, FeaturePhase phase);

/// True when some feature of the Scene lets a reader measure values by it.
bool sceneMeasures(const Scene& scene);

/// The first feature of the Scene that refuses a cut into tiles; null
/// when none does.
const Feature* featureRefusingTiles(const Scene& scene);

/// The orientation marks a feature of the Scene carries (the first that
/// carries any), as placed; none when no feature carries them (they are in
/// the data, or there are none).
std::optional<PlacedMarks> carriedMarks(const Scene& scene);

}  // namespace tsf
