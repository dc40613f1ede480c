#include "gen/readers/raster_limits.h"

#include "gen/util/error.h"

namespace tsf {

void checkRasterSize(const std::string& path, int line, int64_t cols, int64_t rows) {
    const auto size = [&] { return std::to_string(cols) + " x " + std::to_string(rows); };
    if (cols <= 0 || rows <= 0)
        throw InputError(path, line, 0, "raster is " + size() + " cells; expected at least 1 x 1");
    if (cols > kMaxRasterSide || rows > kMaxRasterSide)
        throw InputError(path, line, 0,
                         "raster is " + size() + " cells; the largest side tsf reads is " +
                             std::to_string(kMaxRasterSide) + " cells (downsample the input first)");
    if (cols * rows > kMaxRasterCells)  // both <= 2e4, no overflow
        throw InputError(path, line, 0,
                         "raster is " + size() + " = " + std::to_string(cols * rows) +
                             " cells; the most tsf reads is " + std::to_string(kMaxRasterCells) +
                             " cells (downsample the input first)");
}

}  // namespace tsf
