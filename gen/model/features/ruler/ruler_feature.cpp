// The edge ruler's entry in the feature registry. See ruler_feature.h.
#include "gen/model/features/ruler/ruler_feature.h"

#include "gen/model/features/ruler/ruler.h"

namespace tsf {

namespace {

// Not cut into tiles: a tile would carry teeth counted from another corner.
// The west teeth reach out beside the westernmost pillars.
std::optional<SideWidth> rulerSideWidth(const SceneParams& p) {
    if (!p.requests.get<RulerRequest>()) return std::nullopt;
    return SideWidth{"the edge ruler's teeth", kRulerToothDepthMm};
}

bool rulerSurvivesTiles(const Scene& s) { return sceneRuler(s) == nullptr; }

}  // namespace

const Feature& rulerFeature() {
    static const Feature feature{
        .name = "ruler",
        .option = "--ruler",
        .phase = FeaturePhase::Beside,
        .place = placeRuler,
        .claim = nullptr,  // placed last: nothing after it keeps clear of it
        .attachment = rulerAttachment,
        .box = rulerBoxMm,
        .top_at = rulerTopAt,
        .highest_z_mm = nullptr,  // a ridge 1 mm over the floor, a few mm up: the float32 grid is resolved from 1 mm
        .probes = rulerProbes,
        .check = checkRuler,
        .side_width = rulerSideWidth,
        .record = rulerRecord,
        .read_record = readRulerRecord,
        .facts_listed_when_absent = false,
        .facts_json = rulerFactsJson,
        .facts_lines = rulerFactsLines,
        .key_paragraph = rulerKeyParagraph,
        .scad_piece = rulerScadPiece,
        .measures = nullptr,
        .survives_tiles = rulerSurvivesTiles,
        .carried_marks = nullptr,
        .room_across_cut_units = nullptr,
        .cut_into_half = nullptr,
        .tile_cells = nullptr,
        .carry_into_tile = nullptr,
        .tactile_claims = rulerTactileClaims,
    };
    return feature;
}

}  // namespace tsf
