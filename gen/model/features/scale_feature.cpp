// The tactile scale's entry in the feature registry. See scale_feature.h.
#include "gen/model/features/scale_feature.h"

#include "gen/model/features/scale.h"
#include "gen/model/features/scale_record.h"

namespace tsf {

namespace {

std::optional<FootprintClaim> scaleClaim(const Scene& s) {
    const std::optional<BoxMm> box = scaleBoxMm(s);
    if (!box) return std::nullopt;
    return FootprintClaim{*box, "the tactile scale", "--scale"};
}

std::optional<SideWidth> scaleSideWidth(const SceneParams& p) {
    if (!p.requests.get<ScaleRequest>()) return std::nullopt;
    return SideWidth{"the tactile scale", kScaleGapMm + kScaleStepWidthMm};
}

bool scaleMeasures(const Scene& s) { return sceneScale(s) != nullptr; }

bool scaleAsked(const SceneParams& p) { return p.requests.get<ScaleRequest>() != nullptr; }

// Not yet cut into tiles: a tile would hold a piece of a staircase.
bool scaleSurvivesTiles(const Scene& s) { return sceneScale(s) == nullptr; }

}  // namespace

const Feature& scaleFeature() {
    static const Feature feature{
        .name = "scale",
        .option = "--scale",
        .phase = FeaturePhase::Beside,
        .place = placeScale,
        .claim = scaleClaim,
        .attachment = scaleAttachment,
        .box = scaleBoxMm,
        .top_at = scaleTopAt,
        .highest_z_mm = nullptr,  // its treads stand at values: no higher than the highest pillar
        .probes = scaleProbes,
        .check = checkScale,
        .side_width = scaleSideWidth,
        .record = scaleRecord,
        .read_record = readScaleRecord,
        .facts_listed_when_absent = true,
        .facts_json = scaleFactsJson,
        .facts_lines = scaleFactsLines,
        .key_paragraph = scaleKeyParagraph,
        .scad_piece = scaleScadPiece,
        .measures = scaleMeasures,
        .survives_tiles = scaleSurvivesTiles,
        .carried_marks = nullptr,
        .room_across_cut_units = nullptr,
        .cut_into_half = nullptr,
        .tile_cells = nullptr,
        .carry_into_tile = nullptr,
        .tactile_claims = scaleTactileClaims,
        .asked = scaleAsked,
        .needs_heights = true,  // a class map's classes at one height have none to measure
    };
    return feature;
}

}  // namespace tsf
