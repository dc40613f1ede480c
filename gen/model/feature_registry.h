// The registry of features (gen/model/feature.h): the one list of the
// features that follow the contract, and what the rest of tsf asks of all
// of them at once. buildScene places them, the lists of attachments,
// records and facts, the key and the tiles read them from here, so none of
// those names a feature of the registry.
#pragma once

#include <cstdint>
#include <initializer_list>
#include <optional>
#include <vector>

#include "gen/model/feature.h"
#include "gen/model/scene.h"

namespace tsf {

/// Every feature in the registry, in the registry's order (a class map's
/// textures, decided in the frame, the braille legend, the orientation
/// tab, the tactile scale, the edge ruler, a tile of a tiled model); each
/// is placed in its phase (FeaturePhase).
const std::vector<const Feature*>& features();

/// The features of the registry placed in `phases`, phase by phase in the
/// order given, each phase's in the registry's order: the lists that came
/// before the registry read each phase where its features stood (the
/// feature carrying the marks first among the bodies, its read-back last).
std::vector<const Feature*> featuresOf(std::initializer_list<FeaturePhase> phases);

/// The features beside the pillars (the phases BeforeMarks, Marks, Beside)
/// in the two orders the lists read them, each list made once: the one
/// carrying the marks first (bodies, boxes, tops, records: where the
/// marks' own entries stood), or last (checks, bed widths, OpenSCAD
/// pieces: after the features beside the pillars).
const std::vector<const Feature*>& featuresMarksFirst();
const std::vector<const Feature*>& featuresMarksLast();

/// Places each feature of `phase`, in the registry's order, and adds the
/// footprint each claims to Scene::claims. A feature that needs heights
/// (Feature::needs_heights), asked for on a model whose values a feature
/// stands at one height, is refused (InputError) before it is placed.
void placeFeatures(Scene& scene, FeaturePhase phase);

/// True when some feature of the Scene lets a reader measure values by it.
bool sceneMeasures(const Scene& scene);

/// The first feature of the Scene that refuses a cut into tiles; null
/// when none does.
const Feature* featureRefusingTiles(const Scene& scene);

/// Decides each feature of FeaturePhase::Frame from the field (Feature::frame),
/// in the registry's order.
void frameFeatures(Scene& scene, const HexField& field);

/// The most any feature shapes the tops below their level, z units; 0 when
/// none does.
int64_t featureReliefBelowUnits(const Scene& scene);

/// The shapes a feature gives the cells' tops (the first that shapes any);
/// none when no feature shapes them.
std::optional<TopShaping> featureTopShaping(const Scene& scene);

/// What a feature that stands every value at one height says instead of
/// the heights (the first that does); none when the heights are the value
/// mapping's.
std::optional<OneHeight> featureOneHeight(const Scene& scene);

/// The classes a feature tells apart, in its order, with what tells each
/// apart (Feature::class_marks); empty when none does.
std::vector<ClassMark> featureClassMarks(const Scene& scene);

/// What the key says of the classes a feature tells apart; none when none
/// does.
std::optional<KeyClasses> featureKeyClasses(const Scene& scene, const KeyNumbers& numbers);

/// The thresholds the features' tactile checks are held to, in the
/// registry's order.
std::vector<FeatureThreshold> featureThresholds();

/// Of the cells the cull keeps (grid layout, 1 = keep), only the share of
/// each feature that is a piece of the model (a tile's cells).
void keepFeatureShares(const HexGrid& grid, const SceneParams& params, std::vector<uint8_t>& keep);

/// The features' cuts into the model's bottom (a tile's code pits), in the
/// registry's order.
std::vector<BottomHole> featureBottomHoles(const Scene& scene);

/// True when some feature keeps kept cell k's top level (no structural
/// dimple: a tile's code pit is under it).
bool featureKeepsLevel(const Scene& scene, size_t kept);

/// The orientation marks a feature of the Scene carries (the first that
/// carries any), as placed; none when no feature carries them (they are in
/// the data, or there are none).
std::optional<PlacedMarks> carriedMarks(const Scene& scene);

/// The braille the features print (Feature::braille), in the registry's
/// order.
std::vector<BrailleClaim> featureBraille(const Scene& scene);

/// The marks in the data a piece of the model is given where the whole
/// has them (Feature::given_marks, the first that gives any); none when
/// they are placed as usual.
std::optional<Marks> featureGivenMarks(const Scene& scene);

}  // namespace tsf
