// HexField: scalar values on the hexagonal lattice described by HexGrid.
//
// Layout is the same as HexGrid: row-major over (col, row), row 0 = north,
// odd rows shifted east by half a cell ("odd-r"). NaN = no data.
// Produced by resampling a Raster (gen/field/resample.h) or by binning points
// (gen/readers/point_binning.h); consumed by buildScene (gen/model/scene.h).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gen/field/bin_regression.h"
#include "gen/field/data_place.h"
#include "gen/field/field_input.h"
#include "gen/field/hex_grid.h"

namespace tsf {

struct HexField {
    HexGrid grid;
    std::vector<double> values;  ///< grid.cols * grid.rows, row-major, NaN = no data
    std::string source;          ///< input file, for reports and headers
    std::string how;             ///< one line: how the values were made ("mean of 2x2 px", "count of points")
    /// What one hexagon's value is, in words for the model's key ("the mean
    /// of the values that fall in it"); "" when one value of the data.
    std::string per_hexagon;
    /// Centre spacing of the lattice in data units (1 = one raster pixel), so a
    /// reader of the model can relate millimetres back to data coordinates.
    double pitch_data = 1.0;
    /// True when every cell holds one input value as read (no averaging,
    /// no interpolation, no cell repeated): one pillar per value.
    bool one_to_one = false;
    /// The rows are a raster's rows, as far apart on the ground as its
    /// columns (square pixels, one hexagon per pixel: rasterOneToOne), not
    /// sqrt(3)/2 of that as a lattice laid over the ground has them; a
    /// Scene with true aspect stretches the hexagons to match (hex_grid.h).
    bool rows_a_pitch_apart = false;
    /// With rows_a_pitch_apart: the rows' distance on the ground over the
    /// columns' (Raster::row_aspect): 1 for square pixels.
    double row_aspect = 1.0;
    /// What was read from the file (filled by loadField, gen/readers/load_field.h).
    FieldInput input;
    /// Point input (gen/readers/point_binning.h): per cell, the sums of its points'
    /// offsets from the centre (and weights), for the tilt of its top
    /// (gen/model/features/tilt.h). Empty for rasters.
    std::vector<BinMoments> moments;
    /// Where each hexagon lies in the data's own coordinates; unknown when
    /// the input does not say (gen/field/data_place.h).
    CellPlace place;
    BinStatistic statistic = BinStatistic::Density;  ///< what a cell's value is, with moments

    double at(int32_t col, int32_t row) const { return values[size_t(row) * size_t(grid.cols) + size_t(col)]; }
    double& at(int32_t col, int32_t row) { return values[size_t(row) * size_t(grid.cols) + size_t(col)]; }
};

}  // namespace tsf
