// PGM (netpbm greymap) reader: plain "P2" (ASCII) and raw "P5" (binary).
//
// Values are the raw grey levels 0..maxval as stored in the file, NOT scaled
// to 0..1: the grey level is the user's data. Layout as in the file: first
// sample = top-left (north-west) pixel, row by row. PGM has no "no data", so
// the raster never contains NaN.
//
// Format: magic "P2" or "P5", whitespace, width, height, maxval (decimal,
// separated by whitespace; '#' comments to the end of the line anywhere in
// the header, and in P2 also between samples), then
//   - P5: exactly one whitespace byte, then width*height samples of 1 byte
//     (maxval < 256) or 2 bytes big-endian (maxval 256..65535); bytes after
//     the image are ignored (netpbm allows several images per file; only
//     the first is read);
//   - P2: width*height decimal integers separated by whitespace.
// Errors (tsf::InputError): another magic (P1/P3/P4/P6 are named and a
// conversion is suggested), a missing or non-numeric header field (line,
// column), maxval outside 1..65535 (line, column), a size over the limits of
// raster_limits.h, a truncated P5 file (byte offset where the samples end and
// how many bytes were expected) or P2 file (line, count expected and found),
// a sample above maxval (P5: byte offset; P2: line, column), extra P2 samples
// (line, column of the first extra one).
#pragma once

#include <string>
#include <string_view>

#include "gen/field/raster.h"

namespace tsf {

/// Parses PGM bytes. `path` names the source in errors and Raster::source.
Raster parsePgm(std::string_view bytes, const std::string& path);

/// Reads and parses a PGM file.
Raster readPgm(const std::string& path);

}  // namespace tsf
