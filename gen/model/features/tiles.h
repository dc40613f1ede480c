// Tiles: a model larger than the printer's bed, cut into pieces that each
// fit it and go together one way only.
//
// The cut runs along the hexagons' edges, never through a pillar: every kept
// cell goes to exactly one tile, at its own height, so the tiles put
// together are the untiled model's cells (verify/tiles_check.h proves it).
// A tile is a Scene of its own, built from the same field with the whole
// model's parameters and mapping, of its cells only (TileRequest, gen/model/scene_tiles.h).
//
// The tiling (planTiles): the fewest rows x columns of tiles whose
// footprints each fit the bed, split at equal distances in x and y by cell
// centres (rows from the north, columns from the west), then:
//   - registration: along every seam, dovetail teeth made of whole cells.
//     A tooth of the west (or north) tile reaches into its east (or south)
//     neighbour by a neck k cells long and a head as long and twice as wide
//     (k = kToothMm / pitch, at least 1): the neighbour's cells beside the
//     neck hold the head, so the two tiles come apart only upwards, and each
//     tile has teeth on its east and south sides and sockets on its west
//     and north sides: a tile turned about cannot be put in. Two teeth on a
//     seam with room for both, one otherwise; tiles meeting at a corner
//     (fewer than six edges in common) have no seam, and a seam with no
//     room for a tooth is counted bare (a warning of the assembly check);
//   - the orientation marks (the tab, or the notch and the triangle in the
//     data) each stay whole in one tile, drawn where the whole model has
//     them; a tile that would fall apart gives its loose cells to a
//     neighbour.
//
// Each tile's share of the cells and its code (an L of pits in its bottom
// that says its place) are the tile's own piece: tile_code.h.
#pragma once

#include <cstdint>
#include <vector>

#include "gen/model/scene.h"
#include "gen/model/features/bottom_hole_ring.h"
#include "gen/model/scene_attachments.h"
#include "gen/model/features/tile_code.h"
#include "gen/model/scene_tiles.h"

namespace tsf {

/// The smallest neck of a dovetail tooth, mm (k cells, k = round(kToothMm / pitch), at least 1).
inline constexpr double kToothMm = 4.0;

struct TileLayout {
    int32_t rows = 0, cols = 0;         ///< tile rows (north to south) and columns (west to east)
    std::vector<int32_t> tile_of_cell;  ///< per grid cell: row * cols + col, -1 for a cell not kept
    std::vector<BoxMm> boxes;           ///< per tile: its footprint (cells and what it carries), mm; x0 > x1 when empty
    std::vector<int64_t> cells;         ///< per tile: how many cells
    int32_t teeth = 0;                  ///< dovetail teeth placed
    int32_t seams = 0;                  ///< pairs of neighbouring tiles
    int32_t bare_seams = 0;             ///< seams too short or too ragged for a tooth
    int32_t marks_tile = -1;            ///< the tile carrying the orientation tab or the notch (-1: none)
    int32_t triangle_tile = -1;         ///< marks in the data: the tile the triangle stands on (-1: none)
    int32_t tooth_cells = 1;            ///< k: a tooth's neck length in cells
};

/// Cuts `whole` (a flat model with level tops, no legend or scale) into the fewest
/// tiles that each fit width_mm x depth_mm; `attached`: the boxes of what
/// stands beside the pillars (attachmentBoxes: the orientation tab), which
/// go with the tile of the marks. Throws InputError when no tiling into at
/// most kMaxTileCount tiles fits.
inline constexpr int32_t kMaxTileCount = 400;
TileLayout planTiles(const Scene& whole, const std::vector<BoxMm>& attached, double width_mm, double depth_mm);

/// The parameters buildScene draws tile `tile` of `layout` with: the whole
/// model's (its mapping, snap and marks), its cells only, its place; the
/// orientation marks only on layout.marks_tile (and, marks in the data, the
/// triangle on layout.triangle_tile), where the whole model has them.
SceneParams tileParams(const Scene& whole, const TileLayout& layout, int32_t tile);

}  // namespace tsf
