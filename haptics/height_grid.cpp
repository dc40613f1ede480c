#include "haptics/height_grid.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include "gen/util/error.h"

namespace tsf::haptics {

HeightGrid heightGridFromRaster(const Raster& raster, HeightGridInfo* info) {
    if (raster.empty() || raster.values.size() != size_t(raster.cols) * size_t(raster.rows))
        throw InputError(raster.source, 0, 0, "the field has no cells to feel");
    double lo = std::numeric_limits<double>::infinity();
    double hi = -std::numeric_limits<double>::infinity();
    int64_t nodata = 0;
    for (double v : raster.values) {
        if (!std::isfinite(v)) {
            ++nodata;
            continue;
        }
        lo = std::min(lo, v);
        hi = std::max(hi, v);
    }
    if (!(lo <= hi))
        throw InputError(raster.source, 0, 0,
                         "the field has no finite value (every cell is 'no data'); expected at least one number");
    const double range = hi - lo;
    HeightGrid grid;
    grid.cols = raster.cols;
    grid.rows = raster.rows;
    grid.heights.assign(size_t(grid.cols) * size_t(grid.rows), 0.0f);
    for (int32_t r = 0; r < raster.rows; ++r) {
        const int32_t j = raster.rows - 1 - r;
        for (int32_t i = 0; i < raster.cols; ++i) {
            const double v = raster.at(i, r);
            double h = 0.0;
            if (std::isfinite(v) && range > 0.0) h = (v - lo) / range;
            grid.at(i, j) = float(std::clamp(h, 0.0, 1.0));
        }
    }
    if (info) {
        info->min_value = lo;
        info->max_value = hi;
        info->nodata_cells = nodata;
    }
    return grid;
}

HeightGrid makeHeightGrid(int32_t cols, int32_t rows, std::vector<float> heights_south_first) {
    assert(cols > 0 && rows > 0);
    assert(heights_south_first.size() == size_t(cols) * size_t(rows));
    for ([[maybe_unused]] float h : heights_south_first) assert(h >= 0.0f && h <= 1.0f);
    HeightGrid grid;
    grid.cols = cols;
    grid.rows = rows;
    grid.heights = std::move(heights_south_first);
    return grid;
}

}  // namespace tsf::haptics
