// buildScene: from a HexField and parameters to the model description, in
// phases, each a free function over plain data in gen/model/phases/ (the
// height rules: pillar_spans.h). Three phases find that the Scene must be
// built again with other parameters, and say so here, where the build
// starts again: the halves' slab search, the tab's marks placed in the
// data, and the coarser z grid a float32 file needs.
#include "gen/model/build_scene.h"

#include <cassert>
#include <optional>
#include <utility>

#include "gen/model/phases/cell_heights.h"
#include "gen/model/phases/float32_snap.h"
#include "gen/model/phases/halves_slab.h"
#include "gen/model/phases/kept_cells.h"
#include "gen/model/phases/model_marks.h"
#include "gen/model/phases/pillar_spans.h"
#include "gen/model/phases/scene_frame.h"
#include "gen/model/phases/scene_limits.h"
#include "gen/model/phases/shaped_tops.h"
#include "gen/model/feature_registry.h"
#include "gen/model/features/halves.h"

namespace tsf {

Scene buildScene(const HexField& field, const SceneParams& params) {
    checkSceneParams(field, params);
    Scene s = sceneFrame(field, params);

    // The cells: heights snapped once, the cull's decision, the mirrored
    // floor taken over the whole model, then a piece's share of it (a
    // tile's: Feature::keep_share).
    CellHeights heights = snapCellHeights(field, s.mapping, s.z_snap_mm);
    s.cells_with_data = heights.with_data;
    s.cells_nonempty = heights.nonempty_count;
    KeptCells culled = cullCells(field, heights, params);
    s.hull = std::move(culled.hull);
    s.cells_convex = culled.cells_convex;
    s.notes.insert(s.notes.end(), culled.notes.begin(), culled.notes.end());
    const int64_t mirror_shift =
        lowerToMirroredFloor(field, culled.keep, params, featureReliefBelowUnits(s), heights);
    keepFeatureShares(s.grid, params, culled.keep);
    assert(componentCount(s.grid, culled.keep) == 1);
    listKeptCells(field, culled.keep, s);

    // The pillars' spans: flat, or a mirrored slab (grown for halves).
    stackPillars(heights.units, mirror_shift, s);
    if (s.cells_nodata_kept > 0 && s.nodata_pit_units == 0)
        s.notes.push_back("the base is one z step thick: cells without data sit at the floor, like the lowest value");
    noteConcaveSavings(field, culled.dropped_by_concave, s);

    placeModelMarks(s);
    if (s.halves && !placeHalves(s, /*or_throw=*/lastHalvesSlabTry(params, s.z_snap_mm))) {
        // A try of the slab search below: the caller sees no halves.
        if (params.halves_slab_units) {
            s.halves.reset();
            return s;
        }
        // No three pillars have room for the pins in the model's own slab:
        // built again on the thinnest slab that gives them room, each slab
        // tried a whole build.
        SceneParams grown = params;
        grown.halves_slab_units = thinnestHalvesSlabUnits(*s.halves, s.z_snap_mm, [&](int64_t slab_units) {
            SceneParams trial = params;
            trial.halves_slab_units = slab_units;
            return buildScene(field, trial).halves.has_value();
        });
        return buildScene(field, grown);
    }
    // What goes under level tops (a tile's code pits), so before the dimples.
    placeFeatures(s, FeaturePhase::UnderTops);
    shapeTops(field, heights.units, params, s);

    // The features last: they stand against cells whose tops (tilted or
    // not) rise to the floor, or on a mirrored model hold their band; the
    // tab keeps clear of what the features placed before it claim (the
    // legend's plate), the features after it of every footprint claimed.
    placeFeatures(s, FeaturePhase::BeforeMarks);
    placeFeatures(s, FeaturePhase::Marks);
    if (tabFallsBackToData(params, s)) {
        // No pillar on the west side to stand a tab against: built again
        // with the marks in the data, where they fit.
        Scene again = buildScene(field, marksInData(params));
        noteMarksInData(s.notes.back(), again);
        return again;
    }
    placeFeatures(s, FeaturePhase::Beside);

    if (const std::optional<double> snap_mm = float32SnapMm(params, s)) {
        // Built again on the z grid a float32 STL or 3MF resolves.
        Scene again = buildScene(field, coarserSnap(params, *snap_mm));
        noteCoarserSnap(params, *snap_mm, again);
        return again;
    }
    return s;
}

}  // namespace tsf
