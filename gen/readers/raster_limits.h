// Size limits for field files and rasters, checked by every reader BEFORE it
// allocates.
//
// A raster is held as doubles (8 bytes per cell), so kMaxRasterCells cells
// take 800 MB. tsf models have at most a few hundred thousand hexagons, so a
// larger input would only be averaged down. Rasters GDAL reads are read
// decimated when larger than tsf holds whole (gen/readers/gdal_reader.h);
// text formats that large are refused: downsample them first (for example
// `gdal_translate -outsize 25% 25% big.asc small.asc`), or give GDAL the file.
#pragma once

#include <cstdint>
#include <string>

namespace tsf {

/// Largest field file tsf reads (bytes; readFileBytes(path,
/// kMaxInputFileBytes), gen/util/file_bytes.h). A raster at the cell cap as
/// text is well below this; anything larger is almost certainly not a field
/// file.
inline constexpr int64_t kMaxInputFileBytes = int64_t(4) << 30;  // 4 GiB

inline constexpr int64_t kMaxRasterSide = 20'000;         ///< cells along either side
inline constexpr int64_t kMaxRasterCells = 100'000'000;   ///< cols * rows

/// Throws InputError(path, line, 0, ...) unless 1 <= cols, rows <= kMaxRasterSide
/// and cols * rows <= kMaxRasterCells. `line` is where the size was read
/// (0 if not applicable). Never overflows for any int64 input.
void checkRasterSize(const std::string& path, int line, int64_t cols, int64_t rows);

}  // namespace tsf
