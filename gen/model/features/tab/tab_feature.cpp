// The orientation tab's entry in the feature registry. See tab_feature.h.
#include "gen/model/features/tab/tab_feature.h"

#include <utility>

#include "gen/model/features/marks.h"
#include "gen/model/features/tab/orientation_tab.h"
#include "gen/model/features/tab/orientation_tab_record.h"
#include "gen/model/scene_tiles.h"
#include "gen/util/error.h"

namespace tsf {

namespace {

// A tile carries the model's own tab (its TileRequest's marks, its touched
// cells given as grid cell indices), not one placed again against fewer
// pillars.
void placeTabAsAsked(Scene& s) {
    const TileRequest* tile = s.params.requests.get<TileRequest>();
    if (!tile || !tile->marks || !tile->marks->tab) {
        placeTab(s);
        return;
    }
    OrientationTab tab = *tile->marks->tab;
    for (auto& [k, e] : tab.touched) {
        if (k < 0 || size_t(k) >= s.kept_index.size() || s.kept_index[size_t(k)] < 0)
            throw InputError("a tile does not hold the pillars its orientation tab stands against");
        k = s.kept_index[size_t(k)];
    }
    s.marks.tab = std::move(tab);
}

// Read back with the marks, in their set: on a tab the marks in the data
// are none.
ProbeSet tabMarkProbes(const Scene& s) { return {"marks", kMarkProbesTitle, tabProbes(s)}; }

std::optional<SideWidth> tabSideWidth(const SceneParams& p) {
    if (!marksOnTab(p)) return std::nullopt;
    return SideWidth{"the orientation tab", tabWidthMm(p.marks)};
}

}  // namespace

const Feature& tabFeature() {
    static const Feature feature{
        .name = "marks.tab",
        .option = "--marks-on",
        .phase = FeaturePhase::Marks,
        .place = placeTabAsAsked,
        .claim = tabClaim,
        .attachment = tabAttachment,
        .box = tabBoxMm,
        .top_at = tabTopAt,
        .probes = tabMarkProbes,
        .check = checkTabInScene,
        .side_width = tabSideWidth,
        .record = tabRecord,
        .read_record = readTabRecord,
        .facts_listed_when_absent = true,
        .facts_json = tabFactsJson,
        .facts_lines = tabFactsLines,
        .key_paragraph = nullptr,  // the marks' paragraph tells where they are
        .scad_piece = tabScadPiece,
        .measures = nullptr,
        .survives_tiles = nullptr,  // the tile holding its pillars carries it
        .tactile_claims = nullptr,
    };
    return feature;
}

}  // namespace tsf
