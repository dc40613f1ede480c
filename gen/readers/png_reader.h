// PNG reader (libpng) for greyscale heightmaps.
//
// Values are the raw grey levels as stored: 0..255 for 8-bit, 0..65535 for
// 16-bit, 0..2^d-1 for 1/2/4-bit images (NOT scaled). Layout: row 0 is the
// top (north) row, column 0 the left (west) column.
//
// No data: a pixel with alpha 0 (an alpha channel, or a tRNS chunk naming a
// transparent grey level or palette entry) becomes NaN. Partially transparent
// pixels keep their grey value.
//
// Colour: RGB, RGBA and palette images are accepted only when every
// (non-transparent) pixel is grey, R == G == B (common for heightmaps saved by
// image editors); the value is then that grey level (for palette images the
// palette colour's level, not the index). A real colour image is an error
// naming the first colour pixel: a colour has no single obvious value, so
// the user must convert it (e.g. GIMP: Image > Mode > Grayscale).
//
// Errors (tsf::InputError): not a PNG, a corrupt or truncated PNG (libpng's
// message), a size over the limits of raster_limits.h, a colour pixel.
// libpng errors are caught with setjmp in frames that own no C++ objects, so
// a bad file cannot leak or skip destructors.
#pragma once

#include <string>
#include <string_view>

#include "gen/field/raster.h"

namespace tsf {

/// Parses PNG bytes. `path` names the source in errors and Raster::source.
Raster parsePng(std::string_view bytes, const std::string& path);

/// Reads and parses a PNG file.
Raster readPng(const std::string& path);

}  // namespace tsf
