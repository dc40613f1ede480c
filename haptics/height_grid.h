// HeightGrid: a field prepared for haptic rendering - every cell finite and
// normalised to [0, 1], rows ordered south to north.
//
// Layout: row-major, cell (i, j) at heights[j * cols + i]; i runs east
// (raster column), j runs NORTH from the south edge (j = rows - 1 - raster
// row). Continuous grid coordinates (gi, gj) put the centre of cell (i, j) at
// (i, j), so the field covers [-0.5, cols - 0.5] x [-0.5, rows - 0.5].
//
// Values: 0 = the lowest finite raster value, 1 = the highest. A flat field
// (all finite values equal) becomes all 0. No-data cells (NaN) become 0, the
// floor: a blind user must not feel invented relief where there is no data,
// and the floor is the value "nothing here" has in the printed model too.
#pragma once

#include <cstdint>
#include <vector>

#include "gen/field/raster.h"

namespace tsf::haptics {

struct HeightGrid {
    int32_t cols = 0;             ///< cells along u (east)
    int32_t rows = 0;             ///< cells along v (north)
    std::vector<float> heights;   ///< row-major, row 0 = SOUTH, values in [0, 1], all finite

    float at(int32_t i, int32_t j) const { return heights[size_t(j) * size_t(cols) + size_t(i)]; }
    float& at(int32_t i, int32_t j) { return heights[size_t(j) * size_t(cols) + size_t(i)]; }
    bool empty() const { return cols <= 0 || rows <= 0; }
};

/// What normalisation did, for reports and for labelling plots.
struct HeightGridInfo {
    double min_value = 0.0;      ///< raster value mapped to height 0
    double max_value = 0.0;      ///< raster value mapped to height 1 (== min_value when flat)
    int64_t nodata_cells = 0;    ///< NaN (or non-finite) cells, set to the floor
};

/// Builds a HeightGrid from a raster (see the file comment for the mapping).
/// Throws tsf::InputError naming raster.source when the raster is empty or has
/// no finite value at all. Non-finite values are treated as no data.
HeightGrid heightGridFromRaster(const Raster& raster, HeightGridInfo* info = nullptr);

/// A grid of the given size from values already in [0, 1] (south-first rows);
/// for tests and synthetic fields. Values outside [0, 1] or NaN are a bug.
HeightGrid makeHeightGrid(int32_t cols, int32_t rows, std::vector<float> heights_south_first);

}  // namespace tsf::haptics
