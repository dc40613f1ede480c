// What a file's first bytes say it is, so a binary file is never parsed as
// text (a GeoTIFF read as CSV fails with a misleading "tab-separated fields").
#pragma once

#include <string>
#include <string_view>

namespace tsf {

/// "" when `head` (the file's first bytes; 4 KiB are plenty) looks like text:
/// no magic number of a known binary format and no NUL byte. Otherwise what
/// it is, for messages: "a TIFF image", "a JPEG image", "a GIF image",
/// "a ZIP archive (an .xlsx or .ods spreadsheet?)", "an HDF5 file",
/// "a netCDF file", "a PDF document", or "a binary file". PNG and netpbm
/// images, which tsf reads itself, are not named here.
std::string binaryFileKind(std::string_view head);

/// Throws tsf::InputError naming `path` when `head` (the file's first
/// bytes) is UTF-16 text: a byte-order mark FF FE or FE FF, or a NUL in
/// every other byte of an ASCII-looking start (spreadsheets save
/// "Unicode text" so). tsf reads UTF-8; the message says how to save it.
void refuseUtf16Text(std::string_view head, const std::string& path);

}  // namespace tsf
