// The tile's entry in the feature registry. See tile_feature.h.
#include "gen/model/features/tile_feature.h"

#include "gen/model/features/tile_code.h"
#include "gen/util/error.h"

namespace tsf {

namespace {

void placeTile(Scene& s) {
    if (s.params.requests.get<TileRequest>()) placeTileCode(s);
}

// The tile that carries the marks in the data draws the whole model's,
// where the model has them, rather than placing them again on its cells.
std::optional<Marks> tileGivenMarks(const Scene& s) {
    const TileRequest* tile = s.params.requests.get<TileRequest>();
    if (!tile || !tile->marks) return std::nullopt;
    Marks m;
    m.notch = tile->marks->notch;
    m.triangle = tile->marks->triangle;
    if (m.triangle) {
        const int32_t anchor = m.triangle->anchor;
        if (anchor < 0 || size_t(anchor) >= s.kept_index.size() || s.kept_index[size_t(anchor)] < 0)
            throw InputError("a tile does not hold the cell its orientation triangle stands on");
        m.triangle->anchor = s.kept_index[size_t(anchor)];
    }
    return m;
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
        .given_marks = tileGivenMarks,
    };
    return feature;
}

}  // namespace tsf
