// The tiles of a model cut into tiles (gen/model/features/tiles.h) checked
// as an assembly.
//
// Each tile is checked alone by verifyModel (closed, manifold, outward, one
// piece, its heights and code pits read back against its own Scene). This
// file checks what only the set shows:
//   [tiles_cells]   every cell of the whole model is in exactly one tile,
//                   with the same span (top and bottom, z units), the same
//                   kind (a value or no data) and the same mark drawn on it;
//                   no tile has a cell the whole model has not;
//   [tiles_volume]  the tiles' volumes sum to the whole model's less the
//                   code pits' (prism + cone from the Scenes' rings, not from
//                   the meshes): put together they are the whole model's
//                   material, with no cell twice;
//   [tiles_fit]     every tile's footprint fits the bed;
//   [tiles_teeth]   every seam between two tiles carries a dovetail tooth (a
//                   warning where a seam was too short for one).
// Units: millimetres.
#pragma once

#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"
#include "verify/report.h"

namespace tsf {

struct TilesCheckFigures {
    double whole_volume_mm3 = 0, tiles_volume_mm3 = 0, pits_volume_mm3 = 0;
    double volume_error_mm3 = 0;  ///< tiles - (whole - pits)
    double largest_width_mm = 0, largest_depth_mm = 0;
};

struct TilesCheckResult {
    TilesCheckFigures figures;
    std::vector<Check> checks;  ///< "tiles_cells", "tiles_volume", "tiles_fit", "tiles_teeth"
    bool passed() const;
};

/// What the assembly is checked against besides the Scenes.
struct TilesCheckInput {
    double bed_width_mm = 0, bed_depth_mm = 0;  ///< what each tile must fit (the bed less its margins)
    int32_t seams = 0, bare_seams = 0, teeth = 0;  ///< from the tiling
};

/// Checks the tiles (their Scenes and their meshes, in the model frame) of
/// `whole` (mesh: meshScene(whole)).
TilesCheckResult checkTiles(const Scene& whole, const Mesh& whole_mesh, const std::vector<const Scene*>& tiles,
                            const std::vector<const Mesh*>& meshes, const TilesCheckInput& input);

}  // namespace tsf
