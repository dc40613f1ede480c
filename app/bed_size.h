// The printer's bed as the command line gives it: "220x220" (width x depth,
// mm) or "220x220x250" (with the printable height). Shared by every command
// with a --bed option (gen, verify, print-check).
#pragma once

#include <string>

namespace tsf::cli {

struct BedSize {
    double width_mm = 0;   ///< x
    double depth_mm = 0;   ///< y
    double height_mm = 0;  ///< z; 0 when the text gave only two numbers
};

/// Parses WIDTHxDEPTH[xHEIGHT] (mm, each finite and > 0; 'x' or 'X').
/// need_height: the height is required. Throws InputError naming `option`.
BedSize parseBedSize(const std::string& text, const std::string& option, bool need_height);

}  // namespace tsf::cli
