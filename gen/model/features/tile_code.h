// A tile's own piece of a tiled model (gen/model/features/tiles.h): its
// share of the cells the whole keeps, and its code: each tile's place
// pitted into its flat bottom as an L of cone-topped pits under cell
// centres, read from the underside (a corner pit, then one pit per column
// number going east and one per row number going south: chiral, so it also
// says which way the tile is turned). The pits print face down without a
// bridge (a one-layer wall and a cone steeper than 45 degrees) and keep
// kTileCodeRoofMm of material under the cell's top. Placed for a Scene
// asked for as a tile (TileRequest) by the tile feature
// (tile_feature.h) before the tops are shaped: the tops over the pits stay
// level.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"
#include "gen/model/scene_tiles.h"

namespace tsf {

/// Pits a tile Scene's code into its bottom (SceneTile, in
/// Scene::features). Adds a note when the tile has no room for it.
void placeTileCode(Scene& scene);

/// The tile a Scene draws and its code; null for a whole model.
const SceneTile* sceneTile(const Scene& scene);

/// One tile of a tiled model: its share (TileRequest::cells) of the cells
/// the whole keeps. Throws InputError when the share does not match the
/// grid or is not one piece.
void keepTileShare(const HexGrid& grid, const SceneParams& params, std::vector<uint8_t>& keep);

/// True when kept cell k's top stays level: a tile's code pit is under it,
/// or, in the whole a tiling's tiles are checked against
/// (TiledWholeRequest), the cell is one a tile keeps level.
bool tileKeepsLevel(const Scene& scene, size_t k);

/// The code pits of a tile Scene as cuts into its bottom; none otherwise.
std::vector<BottomHole> tileBottomHoles(const Scene& scene);

/// "row 2, column 3" for people (rows and columns from 1).
std::string tileName(const TilePlace& place);

}  // namespace tsf
