// Which cells the model keeps (the cull: all, the convex hull of the
// non-empty cells, or a concave closing of them; docs/model.md) and the
// kept cells listed in the Scene. (A piece of the model keeps its share of
// them: Feature::keep_share, gen/model/feature.h.)
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gen/field/hex_field.h"
#include "gen/model/phases/cell_heights.h"
#include "gen/model/scene.h"

namespace tsf {

/// The cull's decision, by grid cell index.
struct KeptCells {
    std::vector<uint8_t> keep;
    std::vector<uint8_t> dropped_by_concave;  ///< kept by the convex hull, not by the concave one (else empty)
    std::vector<LatticePoint> hull;           ///< the convex hull culled with (empty when none)
    int64_t cells_convex = 0;                 ///< Cull::Concave: cells the convex hull keeps
    std::vector<std::string> notes;           ///< a flat slab kept whole, a thin hull widened
};

/// The cells params.cull keeps: always one piece (a thin hull is widened
/// to the cells touching it).
KeptCells cullCells(const HexField& field, const CellHeights& heights, const SceneParams& params);

/// Lists the kept cells in the Scene, row by row: kept_index, col, row,
/// value, kind and cells_nodata_kept.
void listKeptCells(const HexField& field, const std::vector<uint8_t>& keep, Scene& s);

/// Cull::Concave: what the convex hull would have printed where the
/// concave one did not (empty pillars of the full slab), as
/// s.volume_saved_mm3 and a note. Needs the pillars' spans (pillar_spans.h).
void noteConcaveSavings(const HexField& field, const std::vector<uint8_t>& dropped_by_concave, Scene& s);

}  // namespace tsf
