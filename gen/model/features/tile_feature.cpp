// The tile's entry in the feature registry. See tile_feature.h.
#include "gen/model/features/tile_feature.h"

#include "gen/model/features/tile_code.h"

namespace tsf {

namespace {

void placeTile(Scene& s) {
    if (s.params.requests.get<TileRequest>()) placeTileCode(s);
}

}  // namespace

const Feature& tileFeature() {
    static const Feature feature{
        .name = "tile",
        .option = "--tile",
        .phase = FeaturePhase::UnderTops,
        .place = placeTile,
        .claim = nullptr,
        .attachment = nullptr,
        .box = nullptr,
        .top_at = nullptr,
        .highest_z_mm = nullptr,
        .probes = nullptr,
        .check = nullptr,
        .side_width = nullptr,
        .record = nullptr,  // a tile has no sidecar: it is a piece of the whole's
        .read_record = nullptr,
        .facts_listed_when_absent = false,
        .facts_json = nullptr,
        .facts_lines = nullptr,
        .key_paragraph = nullptr,  // the tiles' key is the whole model's (app/tiles_output.h)
        .scad_piece = nullptr,
        .measures = nullptr,
        .survives_tiles = nullptr,
        .tactile_claims = nullptr,
        .keep_share = keepTileShare,
        .bottom_holes = tileBottomHoles,
        .keeps_level = tileKeepsLevel,
    };
    return feature;
}

}  // namespace tsf
