// makeVerifiedTiles: a verified model too large for the printer's bed ->
// its tiles (gen/model/features/tiles.h), each built from the field as a
// Scene of its own, meshed and verified like any model, and the set checked
// as an assembly (verify/tiles_check.h). A failure throws
// ModelVerificationFailed, and nothing may be written.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "gen/field/hex_field.h"
#include "gen/model/features/tiles.h"
#include "pipeline/verified_model.h"
#include "verify/tiles_check.h"

namespace tsf {

struct VerifiedTile {
    Scene scene;          ///< the tile's own Scene (model frame: where it lies in the assembly)
    VerifiedModel model;  ///< its mesh and self-check
};

struct VerifiedTiles {
    TileLayout layout;
    std::vector<VerifiedTile> tiles;          ///< tiles with cells, north-west first, row by row
    std::optional<TilesCheckResult> assembly; ///< when verified
};

/// Tiles of `whole` (built from `field`) that each fit width_mm x depth_mm (the bed less its margins). `rq` as
/// for the whole model; on_mesh is called with each tile's mesh.
VerifiedTiles makeVerifiedTiles(const HexField& field, const Scene& whole, double width_mm,
                                double depth_mm, const ModelRequest& rq,
                                const std::function<void(const std::string&)>& progress = {});

/// The check lines of an assembly, for a person.
std::string tilesCheckText(const TilesCheckResult& result);

}  // namespace tsf
