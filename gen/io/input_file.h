// Reading a whole input file into memory, with errors a person can act on.
#pragma once

#include <cstdint>
#include <string>

namespace tsf {

/// Largest input file tsf reads (bytes). A raster at the cell cap
/// (raster_limits.h) as text is well below this; anything larger is almost
/// certainly not a field file.
inline constexpr int64_t kMaxInputFileBytes = int64_t(4) << 30;  // 4 GiB

/// Returns the file's bytes unchanged (binary mode, no newline translation).
/// Throws InputError naming the path if it does not exist, is a directory,
/// cannot be read, or is larger than kMaxInputFileBytes.
std::string readInputFile(const std::string& path);

}  // namespace tsf
