#include "gen/readers/raster_reader.h"

#include <algorithm>
#include <filesystem>

#include "gen/util/error.h"
#include "gen/readers/csv_grid_reader.h"
#include "gen/readers/esri_ascii_reader.h"
#include "gen/readers/file_magic.h"
#include "gen/readers/gdal_reader.h"
#include "gen/readers/netcdf_classic_size.h"
#include "gen/readers/number_field.h"
#include "gen/readers/pgm_reader.h"
#include "gen/readers/png_reader.h"
#include "gen/readers/raster_limits.h"
#include "gen/util/file_bytes.h"

namespace tsf {
namespace {

std::string lowerCase(std::string s) {
    for (char& c : s)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return s;
}

std::string extensionOf(const std::string& path) {
    return lowerCase(std::filesystem::path(path).extension().string());
}

bool startsWithNoCase(std::string_view text, std::string_view word) {
    if (text.size() < word.size()) return false;
    return lowerCase(std::string(text.substr(0, word.size()))) == word;
}

// Bytes enough to recognise any format by its magic number.
constexpr size_t kMagicBytes = 4096;

// Runs a GDAL read; its error says first what the file's magic bytes say it
// is ("is a ZIP archive (an .xlsx or .ods spreadsheet?); GDAL cannot ...").
template <class Read>
Raster withMagicInErrors(std::string_view head, Read read) {
    try {
        return read();
    } catch (const InputError& e) {
        const std::string kind = binaryFileKind(head.substr(0, kMagicBytes));
        if (kind.empty()) throw;
        throw InputError(e.path(), e.line(), e.column(), "is " + kind + "; " + e.detail());
    }
}

// Bytes read of a classic netCDF header that is longer than the magic bytes
// (long attribute lists); a header longer still is left to the netCDF library.
constexpr int64_t kMaxNetcdfHeaderBytes = int64_t(16) << 20;

// A classic netCDF file shorter than its header says is refused here: the
// netCDF library reads what is missing as zeros without an error.
void checkNetcdfFile(const std::string& path, const std::string& head) {
    if (!isNetcdfClassic(head)) return;
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) return;
    const auto extent = netcdfClassicExtent(head);
    if ((extent && !extent->header_cut) || head.size() >= size) return checkNetcdfClassicComplete(head, int64_t(size), path);
    const std::string header = readFileHead(path, size_t(std::min<int64_t>(int64_t(size), kMaxNetcdfHeaderBytes)));
    checkNetcdfClassicComplete(header, int64_t(size), path);
}

}  // namespace

RasterFormat detectRasterFormat(std::string_view bytes, const std::string& path) {
    constexpr std::string_view kPngSignature = "\x89PNG\r\n\x1a\n";
    if (bytes.substr(0, kPngSignature.size()) == kPngSignature) return RasterFormat::Png;
    if (bytes.size() >= 3 && bytes[0] == 'P' && bytes[1] >= '1' && bytes[1] <= '7' &&
        (bytes[2] == ' ' || bytes[2] == '\t' || bytes[2] == '\n' || bytes[2] == '\r' || bytes[2] == '#'))
        return RasterFormat::Pgm;
    if (!binaryFileKind(bytes.substr(0, kMagicBytes)).empty()) return RasterFormat::Gdal;
    std::string_view text = bytes;
    if (text.substr(0, 3) == "\xEF\xBB\xBF") text.remove_prefix(3);
    while (!text.empty() && (text.front() == ' ' || text.front() == '\t' || text.front() == '\n' || text.front() == '\r'))
        text.remove_prefix(1);
    if (startsWithNoCase(text, "ncols") || startsWithNoCase(text, "nrows")) return RasterFormat::EsriAscii;
    const std::string ext = extensionOf(path);
    if (ext == ".png") return RasterFormat::Png;
    if (ext == ".pgm" || ext == ".pnm") return RasterFormat::Pgm;
    if (ext == ".asc") return RasterFormat::EsriAscii;
    for (const char* gdal_ext : {".tif", ".tiff", ".hgt", ".img", ".vrt", ".nc", ".nc4", ".cdf", ".h5", ".hdf5", ".he5",
                                 ".hdf", ".gpkg", ".grib", ".grb", ".grb2", ".jp2", ".bil", ".flt", ".dem", ".dt0",
                                 ".dt1", ".dt2"})
        if (ext == gdal_ext) return RasterFormat::Gdal;
    return RasterFormat::Csv;
}

const char* rasterFormatName(RasterFormat format) {
    switch (format) {
        case RasterFormat::Csv: return "csv";
        case RasterFormat::Pgm: return "pgm";
        case RasterFormat::Png: return "png";
        case RasterFormat::EsriAscii: return "esri-ascii";
        case RasterFormat::Gdal: return "gdal";
        default: return "auto";
    }
}

RasterFormat parseRasterFormat(const std::string& name) {
    const std::string n = lowerCase(name);
    if (n == "auto" || n.empty()) return RasterFormat::Auto;
    if (n == "csv") return RasterFormat::Csv;
    if (n == "pgm") return RasterFormat::Pgm;
    if (n == "png") return RasterFormat::Png;
    if (n == "esri-ascii" || n == "asc" || n == "esri") return RasterFormat::EsriAscii;
    if (n == "gdal" || n == "geotiff" || n == "tif" || n == "tiff") return RasterFormat::Gdal;
    throw InputError("unknown raster format " + quoteForMessage(name) +
                     "; expected auto, csv, pgm, png, esri-ascii or gdal");
}

Raster parseRaster(std::string_view bytes, const std::string& path, const RasterReadOptions& opts) {
    checkCsvDelimiter(opts.delimiter);
    refuseUtf16Text(bytes.substr(0, kMagicBytes), path);
    const RasterFormat format = opts.format == RasterFormat::Auto ? detectRasterFormat(bytes, path) : opts.format;
    switch (format) {
        case RasterFormat::Png: return parsePng(bytes, path);
        case RasterFormat::Pgm: return parsePgm(bytes, path);
        case RasterFormat::EsriAscii: return parseEsriAscii(bytes, path);
        case RasterFormat::Gdal:
            checkNetcdfClassicComplete(bytes, int64_t(bytes.size()), path);
            return withMagicInErrors(bytes, [&] { return parseGdalRaster(bytes, path, opts.band, opts.variable, opts.ignore_georef); });
        default: return parseCsvGrid(bytes, path, opts.delimiter, opts.decimal);
    }
}

Raster readRaster(const std::string& path, const RasterReadOptions& opts) {
    checkCsvDelimiter(opts.delimiter);
    // GDAL's own name of a variable in a file (NETCDF:"f.nc":pr) is GDAL's to open.
    std::error_code ec;
    if (isGdalDatasetName(path) && !std::filesystem::exists(path, ec))
        return readGdalRaster(path, opts.band, opts.variable, opts.ignore_georef);
    const std::string head = readFileHead(path, kMagicBytes);
    refuseUtf16Text(head, path);
    RasterReadOptions o = opts;
    if (o.format == RasterFormat::Auto) o.format = detectRasterFormat(head, path);
    // GDAL reads the file itself (and any sidecar: .prj, .hdr, .aux.xml).
    if (o.format == RasterFormat::Gdal) {
        checkNetcdfFile(path, head);
        return withMagicInErrors(head, [&] { return readGdalRaster(path, o.band, o.variable, o.ignore_georef); });
    }
    if (!o.variable.empty())
        throw InputError(path, 0, 0, "--variable " + o.variable + ": this file holds one set of values (--variable is for "
                                     "files GDAL reads with several: NetCDF, HDF5, GeoPackage)");
    if (o.band != 1)
        throw InputError(path, 0, 0, "--band " + std::to_string(o.band) + ": this file has one band (--band is for "
                                     "rasters GDAL reads with several: multi-band GeoTIFF, NetCDF time steps)");
    const std::string bytes = readFileBytes(path, kMaxInputFileBytes);
    return parseRaster(bytes, path, o);
}

}  // namespace tsf
