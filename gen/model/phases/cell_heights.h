// Each grid cell's height above the floor, in z snap steps, and the
// mirrored model's floor: where its lowest kept value stands on the bed.
#pragma once

#include <cstdint>
#include <vector>

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"

namespace tsf {

/// Heights above the floor, snapped once so that everything after compares
/// integers (units of the z snap step), by grid cell index.
struct CellHeights {
    std::vector<int64_t> units;     ///< 0 for a cell without data
    std::vector<uint8_t> nonempty;  ///< a value above the floor
    int64_t with_data = 0;          ///< cells with a finite value
    int64_t nonempty_count = 0;
};

/// The heights of the field's values under the mapping, snapped to z_snap_mm.
CellHeights snapCellHeights(const HexField& field, const ValueMapping& mapping, double z_snap_mm);

/// A mirrored model stands on z = 0: its lowest kept data cell's underside
/// is the bed, not the height of its value above a floor it does not have
/// (a mirrored band of values 7000 to 25000 would float 2 mm up). Lowers
/// every data cell's height by that shift (never below 0) and returns it,
/// units; 0 for a flat model. The shift is taken over every cell the
/// culling keeps, before a tile takes its share, so the tiles of one model
/// share it. Tops a feature shapes below their level (a class map's
/// dimples and ridges: Feature::relief_below_units, gen/model/feature.h)
/// mirror into the underside: that relief is kept below the lowest cell. Tilted tops keep the whole height below them
/// (no shift) until their corners are resolved (shaped_tops.h).
int64_t lowerToMirroredFloor(const HexField& field, const std::vector<uint8_t>& keep, const SceneParams& params,
                             int64_t relief_below_units, CellHeights& heights);

}  // namespace tsf
