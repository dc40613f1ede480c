// One tile of a model cut into tiles as the Scene holds it: data only.
// Where the cut comes from is gen/model/features/tiles.h.
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

#include "gen/model/scene_attachments.h"
#include "gen/model/scene_marks.h"

namespace tsf {

/// A tile's code pit: a cone-topped hole into the bottom under a cell
/// centre, mm. Straight for one layer, then a cone at least 45 degrees
/// steep (kHoleConeRatio), so it prints face down without a bridge.
inline constexpr double kTileCodePitRadiusMm = 1.0;
inline constexpr double kTileCodePitWallMm = 0.2;
/// Material kept between a code pit's tip and the cell's top, mm.
inline constexpr double kTileCodeRoofMm = 0.6;
/// The least distance between two code pits' centres, mm: braille's dots
/// stand 2.3-2.5 mm apart (US signage and the Marburg medium size), and a
/// fingertip tells them apart.
inline constexpr double kTileCodeSpacingMm = 2.4;
/// The smallest pit a fingertip finds on the underside, mm (radius).
inline constexpr double kTileCodeMinPitRadiusMm = 0.5;

/// Where a tile lies in the tiling: rows from the north, columns from the
/// west, both from 0 (people read them from 1: MODEL-tile-ROW-COL).
struct TilePlace {
    int32_t row = 0, col = 0;
    int32_t rows = 1, cols = 1;
};

/// What buildScene is asked for one tile of a tiled model, held in
/// SceneParams::requests (tileParams, gen/model/features/tiles.h, makes it).
struct TileRequest {
    /// One entry per grid cell: of the cells the culling keeps, only these;
    /// the tile must be one piece.
    std::vector<uint8_t> cells;
    /// The tile's place, pitted into its bottom as its code.
    TilePlace place;
    /// On the tile that carries them, the whole model's marks in the data,
    /// drawn where the model has them rather than placed again on the
    /// tile's cells: its notch and triangle (the triangle's anchor as a grid
    /// cell index), or none when a feature carries the marks (an empty
    /// Marks: the feature's own request carries it, Feature::carry_into_tile
    /// in gen/model/feature.h). None on the other tiles.
    std::optional<Marks> marks;
};

/// What buildScene is asked for the whole model a tiling's tiles are
/// checked against, held in SceneParams::requests: one entry per grid
/// cell, the cells whose tops stay level (no structural dimple), as the
/// tiles keep level the cells their code pits are under.
struct TiledWholeRequest {
    std::vector<uint8_t> level_cells;
};

/// The tile a Scene draws and its code: pits in its bottom, an L of cell
/// centres read from the underside (gen/model/features/tiles.h).
struct SceneTile {
    TilePlace place;
    std::vector<int32_t> code_cells;    ///< kept cells with a pit: the corner, then the east arm, then the south arm
    std::vector<BottomHole> code_pits;  ///< one per code cell
    double pit_radius_mm = 0;           ///< 0: no room for the code (a note says so)
};

}  // namespace tsf
