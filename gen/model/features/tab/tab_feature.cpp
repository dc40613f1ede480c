// The orientation tab's entry in the feature registry. See tab_feature.h.
#include "gen/model/features/tab/tab_feature.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "gen/model/features/marks.h"
#include "gen/model/features/tab/orientation_tab.h"
#include "gen/model/features/tab/orientation_tab_record.h"
#include "gen/util/error.h"

namespace tsf {

namespace {

// What the tile that carries the tab is asked: the whole model's tab, the
// cells it touches given as grid cell indices (carryTabIntoTile).
struct TileTabRequest {
    OrientationTab tab;
};

// A tile carries the model's own tab, not one placed again against fewer
// pillars.
void placeTabAsAsked(Scene& s) {
    const TileTabRequest* carried = s.params.requests.get<TileTabRequest>();
    if (!carried) {
        placeTab(s);
        return;
    }
    OrientationTab tab = carried->tab;
    for (auto& [k, e] : tab.touched) {
        if (k < 0 || size_t(k) >= s.kept_index.size() || s.kept_index[size_t(k)] < 0)
            throw InputError("a tile does not hold the pillars its orientation tab stands against");
        k = s.kept_index[size_t(k)];
    }
    s.features.set(std::move(tab));
}

void carryTabIntoTile(const Scene& whole, SceneParams& tile) {
    const OrientationTab* tab = sceneTab(whole);
    if (!tab) return;
    TileTabRequest request{*tab};
    for (auto& [k, e] : request.tab.touched) k = int32_t(whole.grid.index(whole.col[size_t(k)], whole.row[size_t(k)]));
    tile.requests.set(std::move(request));
}

// The cells it stands against stay with it in one tile.
std::vector<int32_t> tabTileCells(const Scene& s) {
    std::vector<int32_t> out;
    if (const OrientationTab* tab = sceneTab(s))
        for (const auto& [k, e] : tab->touched) out.push_back(k);
    return out;
}

// Both marks, at full size whatever the cells.
std::optional<PlacedMarks> tabMarks(const Scene& s) {
    const OrientationTab* tab = sceneTab(s);
    if (!tab) return std::nullopt;
    const OrientationTab& t = *tab;
    PlacedMarks m;
    m.has_notch = t.has_notch;
    m.notch_depth_mm = t.notch_depth_mm;
    m.has_triangle = t.has_triangle;
    if (t.has_triangle) {
        const double ex = std::hypot(t.triangle[1].x_mm - t.triangle[0].x_mm, t.triangle[1].y_mm - t.triangle[0].y_mm);
        const double ny = std::hypot(t.triangle[2].x_mm - t.triangle[0].x_mm, t.triangle[2].y_mm - t.triangle[0].y_mm);
        m.long_leg_mm = std::max(ex, ny);
        m.short_leg_mm = std::min(ex, ny);
    }
    m.underside = t.has_triangle && t.under_triangle;
    m.triangle_place = "on a flat tab west of the pillars";
    m.where = "on the orientation tab";
    m.note = "The tab holds no data.";
    m.corner_x_mm = t.x_west_mm;
    m.corner_y_mm = t.y_south_mm;
    return m;
}

// The tab lies across the cut, as thick as the base (at least
// kTabMinThicknessMm) on each side, in every pillar it may stand against
// (orientation_tab.h). Whatever the marks: the tab's fallback to marks in
// the data cuts the same slab.
int64_t tabRoomAcrossCut(const Scene& s) {
    return 2 * std::max(snapUnits(s.params.base_mm, s.z_snap_mm), snapUnits(kTabMinThicknessMm, s.z_snap_mm));
}

// Each half keeps its side of the tab, standing on the cut, with the
// triangle on its face away from the cut (the lower half's is the
// underside's).
void cutTabIntoHalf(const Scene& whole, Scene& half, HalfKind kind) {
    OrientationTab* tab = sceneTab(half);
    const OrientationTab* whole_tab = sceneTab(whole);
    if (!tab || !whole_tab) return;
    OrientationTab& t = *tab;
    const int64_t cut = whole.halves->split_units;
    const int64_t bottom = whole_tab->bottom_units, top = whole_tab->top_units;
    t.bottom_units = 0;
    t.top_units = kind == HalfKind::Upper ? top - cut : cut - bottom;
    t.under_triangle = false;
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
        .carried_marks = tabMarks,
        .room_across_cut_units = tabRoomAcrossCut,
        .cut_into_half = cutTabIntoHalf,
        .tile_cells = tabTileCells,
        .carry_into_tile = carryTabIntoTile,
        .tactile_claims = nullptr,
    };
    return feature;
}

}  // namespace tsf
