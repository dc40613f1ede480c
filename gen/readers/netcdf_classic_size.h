// How many bytes a netCDF classic file must have, from its header alone, so
// that a truncated file (a download cut short) is refused instead of read:
// the netCDF library fills what lies past the end of a classic file with
// zeros and reports no error, and GDAL then hands those zeros on as values.
//
// The classic formats are CDF-1 ("CDF\x01"), CDF-2 (64-bit offsets,
// "CDF\x02") and CDF-5 (64-bit data, "CDF\x05"), all big-endian: magic,
// number of records, dimensions, global attributes, variables (each with its
// dimension ids, attributes, type, size and the byte offset of its data).
// NetCDF-4 files are HDF5 files: the HDF5 library itself refuses a
// truncated one. Format: https://docs.unidata.ucar.edu/netcdf-c/current/file_format_specifications.html
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace tsf {

/// What the header of a classic netCDF file says its data needs.
struct NetcdfClassicExtent {
    int64_t end_bytes = 0;     ///< the least file size holding every variable's data (bytes)
    std::string last_variable; ///< the variable whose data ends there
    bool header_cut = false;   ///< the header runs past the bytes given (end_bytes: more than them)
};

/// True when `head` starts with a classic netCDF magic number (CDF-1, -2, -5).
bool isNetcdfClassic(std::string_view head);

/// The extent the header in `head` (the file's first bytes) describes;
/// header_cut when `head` ends inside the header (read more, or, when
/// `head` is the whole file, it is truncated); std::nullopt when `head` is
/// not a classic netCDF header or describes something this check does not
/// follow (a streaming record count, sizes
/// that overflow 64 bits). Never throws.
std::optional<NetcdfClassicExtent> netcdfClassicExtent(std::string_view head);

/// Throws tsf::InputError naming `path` when `head` is a classic netCDF
/// header whose data ends past `file_bytes`, the file's size, or when
/// `head` is the whole file and it ends inside the header. Reads nothing.
void checkNetcdfClassicComplete(std::string_view head, int64_t file_bytes, const std::string& path);

}  // namespace tsf
