#include "gen/model/feature_registry.h"

#include <algorithm>
#include <string>

#include "gen/model/features/class_textures_feature.h"
#include "gen/model/features/legend/legend_feature.h"
#include "gen/model/features/ruler/ruler_feature.h"
#include "gen/model/features/scale_feature.h"
#include "gen/model/features/tab/tab_feature.h"
#include "gen/model/features/tile_feature.h"
#include "gen/util/error.h"

namespace tsf {

const std::vector<const Feature*>& features() {
    static const std::vector<const Feature*> registry = {&classTexturesFeature(), &legendFeature(), &tabFeature(),
                                                         &scaleFeature(), &rulerFeature(), &tileFeature()};
    return registry;
}

namespace {

// What the first feature that gives one gives (hook returns an optional),
// in the registry's order; none when no feature gives one.
template <class R, class... Params, class... Args>
std::optional<R> firstGiven(std::optional<R> (*Feature::*hook)(Params...), const Args&... args) {
    for (const Feature* f : features())
        if (f->*hook)
            if (std::optional<R> r = (f->*hook)(args...)) return r;
    return std::nullopt;
}

}  // namespace

std::vector<const Feature*> featuresOf(std::initializer_list<FeaturePhase> phases) {
    std::vector<const Feature*> out;
    for (const FeaturePhase phase : phases)
        for (const Feature* f : features())
            if (f->phase == phase) out.push_back(f);
    return out;
}

const std::vector<const Feature*>& featuresMarksFirst() {
    static const std::vector<const Feature*> list =
        featuresOf({FeaturePhase::Marks, FeaturePhase::BeforeMarks, FeaturePhase::Beside});
    return list;
}

const std::vector<const Feature*>& featuresMarksLast() {
    static const std::vector<const Feature*> list =
        featuresOf({FeaturePhase::BeforeMarks, FeaturePhase::Beside, FeaturePhase::Marks});
    return list;
}

void placeFeatures(Scene& scene, FeaturePhase phase) {
    for (const Feature* f : featuresOf({phase})) {
        if (f->needs_heights && f->asked && f->asked(scene.params) && scene.keptCount() > 0)
            if (const std::optional<OneHeight> one = featureOneHeight(scene))
                throw InputError(std::string(f->option) + " measures heights, and " + one->unmeasurable);
        if (f->place) f->place(scene);
        if (f->claim)
            if (std::optional<FootprintClaim> c = f->claim(scene)) scene.claims.push_back(std::move(*c));
    }
}

bool sceneMeasures(const Scene& scene) {
    for (const Feature* f : features())
        if (f->measures && f->measures(scene)) return true;
    return false;
}

const Feature* featureRefusingTiles(const Scene& scene) {
    for (const Feature* f : features())
        if (f->survives_tiles && !f->survives_tiles(scene)) return f;
    return nullptr;
}

void frameFeatures(Scene& scene, const HexField& field) {
    for (const Feature* f : featuresOf({FeaturePhase::Frame}))
        if (f->frame) f->frame(scene, field);
}

int64_t featureReliefBelowUnits(const Scene& scene) {
    int64_t most = 0;
    for (const Feature* f : features())
        if (f->relief_below_units) most = std::max(most, f->relief_below_units(scene));
    return most;
}

std::optional<TopShaping> featureTopShaping(const Scene& scene) {
    return firstGiven(&Feature::top_shaping, scene);
}

std::optional<OneHeight> featureOneHeight(const Scene& scene) {
    return firstGiven(&Feature::one_height, scene);
}

std::vector<ClassMark> featureClassMarks(const Scene& scene) {
    for (const Feature* f : features())
        if (f->class_marks)
            if (std::vector<ClassMark> marks = f->class_marks(scene); !marks.empty()) return marks;
    return {};
}

std::optional<KeyClasses> featureKeyClasses(const Scene& scene, const KeyNumbers& numbers) {
    return firstGiven(&Feature::key_classes, scene, numbers);
}

std::vector<FeatureThreshold> featureThresholds() {
    std::vector<FeatureThreshold> out;
    for (const Feature* f : features())
        if (f->thresholds)
            for (const FeatureThreshold& t : f->thresholds()) out.push_back(t);
    return out;
}

void keepFeatureShares(const HexGrid& grid, const SceneParams& params, std::vector<uint8_t>& keep) {
    for (const Feature* f : features())
        if (f->keep_share) f->keep_share(grid, params, keep);
}

std::vector<BottomHole> featureBottomHoles(const Scene& scene) {
    std::vector<BottomHole> holes;
    for (const Feature* f : features())
        if (f->bottom_holes)
            for (BottomHole& h : f->bottom_holes(scene)) holes.push_back(std::move(h));
    return holes;
}

bool featureKeepsLevel(const Scene& scene, size_t kept) {
    for (const Feature* f : features())
        if (f->keeps_level && f->keeps_level(scene, kept)) return true;
    return false;
}

std::optional<PlacedMarks> carriedMarks(const Scene& scene) {
    return firstGiven(&Feature::carried_marks, scene);
}

std::vector<BrailleClaim> featureBraille(const Scene& scene) {
    std::vector<BrailleClaim> out;
    for (const Feature* f : features())
        if (f->braille)
            if (std::optional<BrailleClaim> b = f->braille(scene)) out.push_back(std::move(*b));
    return out;
}

std::optional<Marks> featureGivenMarks(const Scene& scene) {
    return firstGiven(&Feature::given_marks, scene);
}

}  // namespace tsf
