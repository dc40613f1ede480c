// `tsf gen --bed WxD --tile`: the tiles of a model larger than the bed,
// verified and written instead of the one-piece model
// (gen/model/features/tiles.h, pipeline/verified_tiles.h).
#pragma once

#include <string>
#include <vector>

#include "app/gen_summary.h"
#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_writer.h"
#include "pipeline/verified_tiles.h"

namespace tsf::cli {

/// The file -o MODEL.ext becomes for a tile: MODEL-tile-ROW-COL.ext (from 1, rows from the north).
std::string tilePath(const std::string& output, const TilePlace& place);

/// Every tile's file: tilePath(output, ...) of each tile.
std::vector<std::string> tilePaths(const VerifiedTiles& tiles, const std::string& output);

/// Removes the files in output's folder named as tiles of output
/// (MODEL-tile-ROW-COL.ext, ROW and COL numbers) that are not in `keep`:
/// the tiles of an earlier run that cut the model differently. Returns
/// the paths removed. Never throws.
std::vector<std::string> removeStaleTiles(const std::string& output, const std::vector<std::string>& keep);

/// The tiles' figures and checks for the summary: summary.tiles and tiles_text.
void summarizeTiles(const VerifiedTiles& tiles, GenSummary& summary);

/// Writes each tile to tilePath(output, ...) and lists them in the summary.
void writeTiles(const VerifiedTiles& tiles, const std::string& output, const MeshWriteOptions& wo, GenSummary& summary);

/// Which tiles carry the orientation marks, one sentence for the key.
std::string tilesMarksSentence(const VerifiedTiles& tiles);

/// The tiles at their places, drawn apart by a gap (an exploded view), for the preview.
Mesh tilesApart(const VerifiedTiles& tiles);

}  // namespace tsf::cli
