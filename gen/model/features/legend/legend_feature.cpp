// The braille legend's entry in the feature registry. See legend_feature.h.
#include "gen/model/features/legend/legend_feature.h"

#include "gen/model/features/braille.h"
#include "gen/model/features/legend/legend.h"
#include "gen/model/features/legend/legend_join.h"
#include "gen/model/features/legend/legend_record.h"
#include "gen/model/features/legend/legend_scene.h"

namespace tsf {

namespace {

// The dots' apexes stand a dot's height over the plate, which stands at
// the floor: over a low model they are its highest points.
std::optional<double> legendHighestZMm(const Scene& s) {
    const SceneLegend* l = sceneLegend(s);
    if (!l) return std::nullopt;
    return s.zMm(l->plate_top_units) + l->layout.standard.dot_height_mm;
}

std::string legendKeyParagraph(const Scene& s, const KeyNumbers&) {
    const SceneLegend* l = sceneLegend(s);
    if (!l) return "";
    std::string p = "Braille on the plate north of the pillars, in " + brailleCodeName(s.params.words.braille_table) + ", reads:";
    for (const std::string& line : l->layout.text) p += " \"" + line + "\".";
    return p;
}

// Its dots, on the plate's top.
std::optional<BrailleClaim> legendBraille(const Scene& s) {
    const SceneLegend* l = sceneLegend(s);
    if (!l) return std::nullopt;
    BrailleClaim b{.standard = l->layout.standard, .dots = l->layout.dots.size(), .first_dot_mm = {0, 0, 0}};
    if (!l->layout.dots.empty())
        b.first_dot_mm = {l->layout.dots[0].x_mm + l->x0_mm, l->layout.dots[0].y_mm + l->y0_mm, s.zMm(l->plate_top_units)};
    return b;
}

// Not cut into tiles: a tile would hold a piece of the plate.
bool legendSurvivesTiles(const Scene& s) { return sceneLegend(s) == nullptr; }

}  // namespace

const Feature& legendFeature() {
    static const Feature feature{
        .name = "legend",
        .option = "--title/--units",
        // Before the orientation tab, which keeps clear of its plate.
        .phase = FeaturePhase::BeforeMarks,
        .place = placeLegend,
        .claim = legendClaim,
        .attachment = legendAttachment,
        .box = legendBoxMm,
        .top_at = legendTopAt,
        .highest_z_mm = legendHighestZMm,
        .probes = legendProbes,
        .check = nullptr,
        .side_width = nullptr,  // north of the pillars: it takes depth, not width beside them
        .record = legendRecord,
        .read_record = readLegendRecord,
        .facts_listed_when_absent = true,  // always in the sidecar and the facts, null without one
        .facts_json = legendFactsJson,
        .facts_lines = legendFactsLines,
        .key_paragraph = legendKeyParagraph,
        .scad_piece = legendScadPiece,
        .measures = nullptr,
        .survives_tiles = legendSurvivesTiles,
        .carried_marks = nullptr,
        .room_across_cut_units = nullptr,
        .cut_into_half = nullptr,
        .tile_cells = nullptr,
        .carry_into_tile = nullptr,
        // The braille dots' own check (verify/tactile.h, tactile_braille)
        // proves them against the standards' range, not a least rise alone.
        .tactile_claims = nullptr,
        .braille = legendBraille,
    };
    return feature;
}

}  // namespace tsf
