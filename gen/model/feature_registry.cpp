#include "gen/model/feature_registry.h"

#include "gen/model/features/legend/legend_feature.h"
#include "gen/model/features/ruler/ruler_feature.h"
#include "gen/model/features/scale_feature.h"
#include "gen/model/features/tab/tab_feature.h"

namespace tsf {

const std::vector<const Feature*>& features() {
    static const std::vector<const Feature*> registry = {&legendFeature(), &tabFeature(), &scaleFeature(),
                                                         &rulerFeature()};
    return registry;
}

std::vector<const Feature*> featuresOf(std::initializer_list<FeaturePhase> phases) {
    std::vector<const Feature*> out;
    for (const FeaturePhase phase : phases)
        for (const Feature* f : features())
            if (f->phase == phase) out.push_back(f);
    return out;
}

void placeFeatures(Scene& scene, FeaturePhase phase) {
    for (const Feature* f : featuresOf({phase})) {
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

std::optional<PlacedMarks> carriedMarks(const Scene& scene) {
    for (const Feature* f : features())
        if (f->carried_marks)
            if (std::optional<PlacedMarks> m = f->carried_marks(scene)) return m;
    return std::nullopt;
}

}  // namespace tsf
