// The GDAL module (tsf-gdal.so): the only code that includes or links GDAL.
// tsf loads it with dlopen the first time a raster needs GDAL (gdal_reader.cpp),
// so the hundred-odd libraries GDAL pulls in cost nothing to the commands
// that never read a GeoTIFF (about 70 ms at every start when linked).
#include "gen/readers/gdal/gdal_module_abi.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cpl_conv.h>
#include <cpl_string.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <gdal_rat.h>
#include <mutex>
#include <ogr_srs_api.h>
#include <sstream>
#include <vector>

#include "gen/util/error.h"
#include "gen/readers/cf_time.h"
#include "gen/readers/raster_limits.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;

void registerDrivers() {
    static std::once_flag once;
    std::call_once(once, [] {
        GDALAllRegister();
        // GDAL's block cache (by default a share of the machine's memory)
        // need hold no more than a row of tiles of the widest raster read.
        GDALSetCacheMax64(int64_t(64) << 20);
    });
}

// Keeps GDAL from printing on stderr while it works; its last message goes
// into our InputError instead.
struct QuietGdal {
    QuietGdal() {
        CPLPushErrorHandler(CPLQuietErrorHandler);
        CPLErrorReset();
    }
    ~QuietGdal() { CPLPopErrorHandler(); }
    static std::string lastMessage() {
        const char* m = CPLGetLastErrorMsg();
        return m && *m ? std::string(m) : std::string("unknown GDAL error");
    }
};

// Reads a window of the band as doubles. False when GDAL says it failed,
// by its return value or by an error it only reported (a driver may log a
// failure and still return CE_None with the buffer partly unread).
bool readPixels(GDALRasterBandH band, int64_t x0, int64_t y0, int64_t cols, int64_t rows, double* out) {
    CPLErrorReset();
    const CPLErr status = GDALRasterIO(band, GF_Read, int(x0), int(y0), int(cols), int(rows), out, int(cols), int(rows),
                                       GDT_Float64, 0, 0);
    return status == CE_None && CPLGetLastErrorType() != CE_Failure && CPLGetLastErrorType() != CE_Fatal;
}

struct Dataset {
    GDALDatasetH h = nullptr;
    ~Dataset() {
        if (h) GDALClose(h);
    }
};

std::string crsName(OGRSpatialReferenceH srs) {
    const char* name = OSRGetName(srs);
    std::string out = name ? name : "unnamed CRS";
    const char* auth = OSRGetAuthorityName(srs, nullptr);
    const char* code = OSRGetAuthorityCode(srs, nullptr);
    if (auth && code) out += std::string(" (") + auth + ":" + code + ")";
    return out;
}

/// The classes a band names: its category names (index = code, empty names
/// skipped), else a raster attribute table's name column against its value
/// column (or, without one, its row number). Names are trimmed and capped
/// at 80 characters; at most kMaxClasses are kept.
std::vector<RasterClass> classNames(GDALRasterBandH band) {
    constexpr size_t kMaxClasses = 1024;
    constexpr size_t kMaxNameBytes = 80;
    std::vector<RasterClass> out;
    auto add = [&](double code, const char* raw) {
        if (!raw || out.size() >= kMaxClasses) return;
        std::string name(raw);
        for (char& c : name)
            if (static_cast<unsigned char>(c) < 0x20) c = ' ';
        const size_t a = name.find_first_not_of(' '), b = name.find_last_not_of(' ');
        if (a == std::string::npos) return;
        name = name.substr(a, b - a + 1);
        if (name.size() > kMaxNameBytes) name = name.substr(0, kMaxNameBytes);
        out.push_back({code, name});
    };
    if (char** names = GDALGetRasterCategoryNames(band)) {
        for (int k = 0; names[k] && out.size() < kMaxClasses; ++k) add(double(k), names[k]);
        if (!out.empty()) return out;
    }
    GDALRasterAttributeTableH rat = GDALGetDefaultRAT(band);
    if (!rat) return out;
    const int name_col = GDALRATGetColOfUsage(rat, GFU_Name);
    if (name_col < 0) return out;
    int value_col = GDALRATGetColOfUsage(rat, GFU_MinMax);
    if (value_col < 0) value_col = GDALRATGetColOfUsage(rat, GFU_Min);
    const int rows = GDALRATGetRowCount(rat);
    for (int row = 0; row < rows && out.size() < kMaxClasses; ++row)
        add(value_col >= 0 ? GDALRATGetValueAsDouble(rat, row, value_col) : double(row),
            GDALRATGetValueAsString(rat, row, name_col));
    std::sort(out.begin(), out.end(), [](const RasterClass& x, const RasterClass& y) { return x.code < y.code; });
    return out;
}

/// A dataset inside a file (GDAL's subdataset): a NetCDF or HDF5 variable,
/// a GeoPackage raster table.
struct Variable {
    std::string gdal_name;  ///< what GDAL opens: NETCDF:"file.nc":pr
    std::string name;       ///< the variable's own name: pr
    std::string description;///< GDAL's: "[12x33x81] precipitation_flux (32-bit floating-point)"
};

std::vector<Variable> variablesOf(GDALDatasetH ds) {
    std::vector<Variable> out;
    char** md = GDALGetMetadata(ds, "SUBDATASETS");
    for (int n = 1;; ++n) {
        const char* name = CSLFetchNameValue(md, ("SUBDATASET_" + std::to_string(n) + "_NAME").c_str());
        if (!name) break;
        const char* desc = CSLFetchNameValue(md, ("SUBDATASET_" + std::to_string(n) + "_DESC").c_str());
        Variable v{name, name, desc ? desc : ""};
        // The variable is what follows the last ':' outside quotes (NETCDF:"a:b.nc":pr, HDF5:"f.h5"://grp/x).
        const size_t close = v.gdal_name.rfind('"');
        const size_t colon = v.gdal_name.find(':', close == std::string::npos ? 0 : close);
        if (colon != std::string::npos) v.name = v.gdal_name.substr(colon + 1);
        while (!v.name.empty() && v.name.front() == '/') v.name.erase(0, 1);
        out.push_back(std::move(v));
    }
    return out;
}

std::string listVariables(const std::vector<Variable>& vars) {
    std::string out;
    for (size_t k = 0; k < vars.size(); ++k)
        out += (k ? "; " : "") + vars[k].name + (vars[k].description.empty() ? "" : " " + vars[k].description);
    return out;
}

/// What a NetCDF band stands for: "time = 59 days since 1850-01-01
/// (1850-03-01)" from the band's NETCDF_DIM_* metadata and the dataset's
/// units and calendar of those dimensions; "" when there is none.
std::string bandCoordinates(GDALDatasetH ds, GDALRasterBandH band) {
    std::string out;
    char** md = GDALGetMetadata(band, nullptr);
    for (int k = 0; md && md[k]; ++k) {
        const std::string entry = md[k];
        if (entry.rfind("NETCDF_DIM_", 0) != 0) continue;
        const size_t eq = entry.find('=');
        if (eq == std::string::npos) continue;
        const std::string dim = entry.substr(11, eq - 11), value = entry.substr(eq + 1);
        const char* units = GDALGetMetadataItem(ds, (dim + "#units").c_str(), nullptr);
        const char* calendar = GDALGetMetadataItem(ds, (dim + "#calendar").c_str(), nullptr);
        std::string what = dim + " = " + value + (units ? std::string(" ") + units : "");
        if (units) {
            const std::string date = cfDate(units, calendar ? calendar : "", std::atof(value.c_str()));
            if (!date.empty()) what += " (" + date + ")";
        }
        out += (out.empty() ? "" : ", ") + what;
    }
    return out;
}

/// The largest raster side GDAL is asked for (decimated reading works on
/// strips of it, so memory is not the bound; a side beyond this is not a
/// raster a model can be made of).
constexpr int64_t kMaxGdalSide = 1'000'000;
/// A raster read whole holds at most this many values (32 MB of doubles):
/// ten times the hexagons of the largest default model; larger rasters are
/// read decimated to it.
constexpr int64_t kWholeReadCells = 4'000'000;

/// The whole-number factor both sides are divided by so the raster holds at
/// most kWholeReadCells values and kMaxRasterSide a side (1: read whole).
int64_t decimationFor(int64_t cols, int64_t rows) {
    int64_t f = 1;
    while ((cols / f) * (rows / f) > kWholeReadCells || cols / f > kMaxRasterSide || rows / f > kMaxRasterSide) ++f;
    return f;
}

/// Above this many source pixels a decimated read says how far it has got
/// on stderr (tenths of the rows): a tiled 40 000 x 40 000 file is small on
/// disk but takes many seconds to read.
constexpr int64_t kProgressPixels = 100'000'000;

/// Reads the band into dec_cols x dec_rows values, each the mean (categorical:
/// the most common value, the smaller on a tie) of the source pixels with
/// data in its block; NaN when the block has none. Works a strip of source
/// rows at a time: memory is the result and one strip.
void readDecimated(GDALRasterBandH band, const std::string& path, int64_t cols, int64_t rows, int64_t dec_cols,
                   int64_t dec_rows, bool categorical, bool has_nodata, double nodata, std::vector<double>& out) {
    out.assign(size_t(dec_cols) * size_t(dec_rows), NAN);
    const size_t n_blocks = static_cast<size_t>(dec_cols);
    std::vector<double> strip, sum(n_blocks), count(n_blocks);
    std::vector<std::vector<std::pair<double, int64_t>>> classes(categorical ? n_blocks : 0);
    std::vector<int64_t> col_block(static_cast<size_t>(cols));
    for (int64_t x = 0; x < cols; ++x) col_block[size_t(x)] = std::min(dec_cols - 1, x * dec_cols / cols);
    const bool tell = cols * rows > kProgressPixels;
    int said = 0;  // tenths of the rows said so far
    if (tell)
        std::fprintf(stderr, "tsf: reading %lld x %lld pixels of %s into %lld x %lld values\n", (long long)cols,
                     (long long)rows, path.c_str(), (long long)dec_cols, (long long)dec_rows);
    for (int64_t r = 0; r < dec_rows; ++r) {
        if (tell && r * 10 / dec_rows > said) {
            said = int(r * 10 / dec_rows);
            std::fprintf(stderr, "tsf: read %d %% of the rows\n", said * 10);
        }
        const int64_t y0 = r * rows / dec_rows, y1 = std::max(y0 + 1, (r + 1) * rows / dec_rows);
        strip.resize(size_t(cols) * size_t(y1 - y0));
        if (!readPixels(band, 0, y0, cols, y1 - y0, strip.data()))
            throw InputError(path, 0, 0, "GDAL could not read the pixels: " + QuietGdal::lastMessage());
        std::fill(sum.begin(), sum.end(), 0.0);
        std::fill(count.begin(), count.end(), 0.0);
        for (auto& c : classes) c.clear();
        for (int64_t y = 0; y < y1 - y0; ++y)
            for (int64_t x = 0; x < cols; ++x) {
                const double v = strip[size_t(y * cols + x)];
                if (!std::isfinite(v) || (has_nodata && v == nodata)) continue;
                const size_t c = size_t(col_block[size_t(x)]);
                if (categorical) {
                    auto& list = classes[c];
                    auto it = std::find_if(list.begin(), list.end(), [v](const auto& e) { return e.first == v; });
                    if (it == list.end()) list.emplace_back(v, 1);
                    else ++it->second;
                } else {
                    sum[c] += v;
                    count[c] += 1;
                }
            }
        for (size_t c = 0; c < size_t(dec_cols); ++c) {
            double& o = out[size_t(r) * size_t(dec_cols) + c];
            if (categorical) {
                std::pair<double, int64_t> best{NAN, 0};
                for (const auto& e : classes[c])
                    if (e.second > best.second || (e.second == best.second && e.first < best.first)) best = e;
                if (best.second > 0) o = best.first;
            } else if (count[c] > 0) {
                o = sum[c] / count[c];
            }
        }
    }
}

/// True when the dataset's metadata gives a coordinate variable in
/// degrees_east and one in degrees_north (CF units of longitude, latitude).
bool cfLonLat(GDALDatasetH ds) {
    bool east = false, north = false;
    char** md = GDALGetMetadata(ds, nullptr);
    for (int k = 0; md && md[k]; ++k) {
        const std::string entry = md[k];
        const size_t at = entry.find("#units=");
        if (at == std::string::npos) continue;
        const std::string unit = entry.substr(at + 7);
        east = east || unit == "degrees_east" || unit == "degree_east" || unit == "degrees_E";
        north = north || unit == "degrees_north" || unit == "degree_north" || unit == "degrees_N";
    }
    return east && north;
}

/// No data to NaN and packed values unpacked, with their facts.
Raster finishValues(GDALRasterBandH band, bool has_nodata, double nodata, Raster& r) {
    // Packed values (CF scale_factor, add_offset; GDAL's scale and offset):
    // the stored number times the scale plus the offset is the value.
    int has_scale = 0, has_offset = 0;
    const double scale = GDALGetRasterScale(band, &has_scale), offset = GDALGetRasterOffset(band, &has_offset);
    const bool unpack = (has_scale && scale != 1.0) || (has_offset && offset != 0.0);
    for (double& v : r.values) {
        if ((has_nodata && v == nodata) || !std::isfinite(v)) v = NAN;
        else if (unpack) v = v * (has_scale ? scale : 1.0) + (has_offset ? offset : 0.0);
    }
    if (has_nodata) r.facts.push_back({"no-data value", formatSignificant(nodata) + " (from the file)"});
    if (unpack)
        r.facts.push_back({"packed", "stored values x " + formatSignificant(has_scale ? scale : 1.0) + " + " +
                                         formatSignificant(has_offset ? offset : 0.0) + " (the file's scale and offset)"});
    return r;
}

/// A raster whose geotransform is rotated or sheared, resampled north-up in
/// its CRS's coordinates (see rotatedNorthUp).
struct NorthUp {
    std::vector<double> values;  ///< row 0 north, NaN outside the source raster and for its no data
    int64_t cols = 0, rows = 0;
    double x0 = 0, y0 = 0;       ///< the west and north edges (CRS units)
    double px_w = 0, px_h = 0;   ///< pixel width and height (CRS units)
};

/// The source grid `src` (src_cols x src_rows, NaN for no data, laid out as
/// the file's rows) placed by the geotransform gt (pixel, line -> x, y),
/// resampled onto a north-up grid of its bounding box by nearest neighbour:
/// each new pixel takes the source pixel its centre falls in, NaN outside.
/// Pixels are x_scale times as wide in x units as high in y units (square on
/// the ground for degrees of longitude), of the source pixel's ground area,
/// grown when the box would hold more than kWholeReadCells.
NorthUp rotatedNorthUp(const std::vector<double>& src, int64_t src_cols, int64_t src_rows, const double gt[6],
                       double x_scale, int64_t max_cells) {
    const double det = gt[1] * gt[5] - gt[2] * gt[4];
    double xs[4], ys[4];
    const double corner_px[4][2] = {{0, 0}, {double(src_cols), 0}, {0, double(src_rows)}, {double(src_cols), double(src_rows)}};
    for (int k = 0; k < 4; ++k) {
        xs[k] = gt[0] + gt[1] * corner_px[k][0] + gt[2] * corner_px[k][1];
        ys[k] = gt[3] + gt[4] * corner_px[k][0] + gt[5] * corner_px[k][1];
    }
    const double west = *std::min_element(xs, xs + 4), east = *std::max_element(xs, xs + 4);
    const double south = *std::min_element(ys, ys + 4), north = *std::max_element(ys, ys + 4);
    // Ground area of a source pixel in y units squared, as a square of side h.
    double h = std::sqrt(std::fabs(det) * x_scale);
    // A box a whole number of pixels wide, up to the rounding of the corners'
    // coordinates (relative, far below a pixel), gets no extra column.
    constexpr double kWholePixelsSlack = 1e-9;
    NorthUp out;
    for (;;) {
        out.px_h = h;
        out.px_w = h / x_scale;
        out.cols = std::max<int64_t>(1, std::llround(std::ceil((east - west) / out.px_w - kWholePixelsSlack)));
        out.rows = std::max<int64_t>(1, std::llround(std::ceil((north - south) / out.px_h - kWholePixelsSlack)));
        if (out.cols * out.rows <= max_cells && out.cols <= kMaxRasterSide && out.rows <= kMaxRasterSide) break;
        h *= 1.01 * std::sqrt(double(out.cols) * double(out.rows) / double(max_cells));
        h = std::max(h, out.px_h * 1.01);
    }
    out.x0 = west;
    out.y0 = north;
    out.values.assign(size_t(out.cols) * size_t(out.rows), NAN);
    // Inverse of the geotransform's linear part: (x - gt0, y - gt3) -> (pixel, line).
    const double inv00 = gt[5] / det, inv01 = -gt[2] / det, inv10 = -gt[4] / det, inv11 = gt[1] / det;
    for (int64_t r = 0; r < out.rows; ++r) {
        const double y = north - (double(r) + 0.5) * out.px_h - gt[3];
        for (int64_t c = 0; c < out.cols; ++c) {
            const double x = west + (double(c) + 0.5) * out.px_w - gt[0];
            const double u = inv00 * x + inv01 * y, v = inv10 * x + inv11 * y;
            if (!(u >= 0 && v >= 0 && u < double(src_cols) && v < double(src_rows))) continue;
            out.values[size_t(r * out.cols + c)] = src[size_t(int64_t(v) * src_cols + int64_t(u))];
        }
    }
    return out;
}

/// Reads a band whose geotransform is rotated or sheared into `r`,
/// north-up (rotatedNorthUp): the source whole, or decimated to the block
/// means (most common classes) when larger than tsf reads whole. Sets the
/// values, size, cell size, origin and the facts that say what was done.
void readRotated(GDALRasterBandH band, const std::string& path, int64_t cols, int64_t rows, const double gt[6],
                 double x_scale, bool categorical, bool has_nodata, double nodata, Raster& r) {
    std::vector<double> src;
    const int64_t f = decimationFor(cols, rows);
    int64_t src_cols = cols, src_rows = rows;
    double sgt[6];
    std::copy(gt, gt + 6, sgt);
    if (f > 1) {
        src_cols = (cols + f - 1) / f;
        src_rows = (rows + f - 1) / f;
        readDecimated(band, path, cols, rows, src_cols, src_rows, categorical, has_nodata, nodata, src);
        const double sx = double(cols) / double(src_cols), sy = double(rows) / double(src_rows);
        sgt[1] *= sx, sgt[4] *= sx, sgt[2] *= sy, sgt[5] *= sy;
        r.decimation = int(f);
    } else {
        src.assign(size_t(cols) * size_t(rows), 0.0);
        if (GDALRasterIO(band, GF_Read, 0, 0, int(cols), int(rows), src.data(), int(cols), int(rows), GDT_Float64, 0, 0) !=
            CE_None)
            throw InputError(path, 0, 0, "GDAL could not read the pixels: " + QuietGdal::lastMessage());
        for (double& v : src)
            if (has_nodata && v == nodata) v = NAN;
    }
    NorthUp n = rotatedNorthUp(src, src_cols, src_rows, sgt, x_scale, kWholeReadCells);
    checkRasterSize(path, 0, n.cols, n.rows);
    r.values = std::move(n.values);
    r.cols = int32_t(n.cols);
    r.rows = int32_t(n.rows);
    r.cell_size = n.px_h;  // square on the ground: px_w * x_scale == px_h
    r.row_aspect = 1.0;
    r.x_origin = n.x0;
    r.y_origin = n.y0 - n.px_h * double(n.rows);
    r.place = {.known = true, .x_west = n.x0, .dx = n.px_w, .y_north = n.y0, .dy = n.px_h, .axes = {}};
    // The raster's own sides on the ground and where its top edge faced.
    const double side_x = std::hypot(gt[1] * x_scale, gt[4]) * double(cols);
    const double side_y = std::hypot(gt[2] * x_scale, gt[5]) * double(rows);
    double bearing = std::atan2(-gt[2] * x_scale, -gt[5]) * 180.0 / kPi;  // "up" in the raster, clockwise from north
    if (bearing < 0) bearing += 360.0;
    const double cos_angle = (gt[1] * x_scale * gt[2] * x_scale + gt[4] * gt[5]) /
                             (std::hypot(gt[1] * x_scale, gt[4]) * std::hypot(gt[2] * x_scale, gt[5]));
    const bool sheared = std::fabs(cos_angle) > 1e-6;
    r.facts.push_back({"rotated", std::string("the geotransform is ") + (sheared ? "sheared and rotated" : "rotated") +
                                      ": the raster's top edge faced " + formatFixed(bearing, 1) +
                                      " degrees clockwise from north, its sides " + formatSignificant(side_x, 4) + " by " +
                                      formatSignificant(side_y, 4) + " (CRS units); resampled north-up (nearest "
                                      "neighbour, values unchanged) onto " + std::to_string(n.cols) + " x " +
                                      std::to_string(n.rows) + " pixels of " + formatSignificant(n.px_h, 4) +
                                      ", no data outside the raster's outline; --ignore-georef keeps the raster's own grid"});
}

Raster readDataset(const std::string& gdal_name, const std::string& path, int band_number,
                   const std::string& variable = "", bool ignore_georef = false) {
    registerDrivers();
    QuietGdal quiet;
    Dataset ds;
    ds.h = GDALOpenEx(gdal_name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
    if (!ds.h) throw InputError(path, 0, 0, "GDAL cannot read it as a raster: " + QuietGdal::lastMessage());
    // A file of several variables (NetCDF, HDF5, GeoPackage): the one asked
    // for, or the only one.
    const std::vector<Variable> vars = variablesOf(ds.h);
    if (!vars.empty()) {
        const Variable* chosen = nullptr;
        if (!variable.empty()) {
            for (const Variable& v : vars)
                if (v.name == variable || v.gdal_name == variable) chosen = &v;
            if (!chosen)
                throw InputError(path, 0, 0, "has no variable '" + variable + "'; it has " + std::to_string(vars.size()) +
                                                 ": " + listVariables(vars));
        } else if (vars.size() == 1) {
            chosen = &vars[0];
        } else {
            throw InputError(path, 0, 0, "holds " + std::to_string(vars.size()) + " variables: " + listVariables(vars) +
                                             "; choose one with --variable NAME");
        }
        Raster r = readDataset(chosen->gdal_name, path, band_number, "", ignore_georef);
        r.variable = chosen->name;
        std::string names;
        for (const Variable& v : vars) names += (names.empty() ? "" : ", ") + v.name;
        r.facts.insert(r.facts.begin(), {"variable", chosen->name + (chosen->description.empty() ? "" : " " + chosen->description) +
                                                        (vars.size() > 1 ? " (of " + names + "; --variable NAME)" : "")});
        return r;
    }
    if (!variable.empty() && variable != gdal_name)
        throw InputError(path, 0, 0, "--variable " + variable + ": it holds one dataset, not variables to choose from");
    const int cols = GDALGetRasterXSize(ds.h), rows = GDALGetRasterYSize(ds.h), bands = GDALGetRasterCount(ds.h);
    if (bands < 1) throw InputError(path, 0, 0, "has no raster band");
    if (int64_t(cols) > kMaxGdalSide || int64_t(rows) > kMaxGdalSide)
        throw InputError(path, 0, 0, "is " + std::to_string(cols) + " x " + std::to_string(rows) +
                                         " pixels; tsf reads rasters up to " + std::to_string(kMaxGdalSide) +
                                         " pixels a side (decimated when larger than it holds whole)");
    if (band_number < 1 || band_number > bands)
        throw InputError(path, 0, 0,
                         "--band " + std::to_string(band_number) + ": it has " + std::to_string(bands) +
                             (bands == 1 ? " band" : " bands") + " (give --band 1 to " + std::to_string(bands) + ")");
    GDALRasterBandH band = GDALGetRasterBand(ds.h, band_number);

    Raster r;
    r.source = path;
    const char* driver = GDALGetDriverShortName(GDALGetDatasetDriver(ds.h));
    r.kind = std::string("gdal/") + (driver ? driver : "?");
    r.facts.push_back({"format", std::string(driver ? GDALGetDriverLongName(GDALGetDatasetDriver(ds.h)) : "?") +
                                     " through GDAL " + GDALVersionInfo("RELEASE_NAME")});
    if (bands > 1) {
        std::string what = std::to_string(band_number) + " of " + std::to_string(bands);
        const std::string coordinates = bandCoordinates(ds.h, band);
        if (!coordinates.empty()) what += ": " + coordinates;
        else if (const char* d = GDALGetDescription(band); d && *d) what += std::string(" (") + d + ")";
        if (band_number == 1) what += "; --band N for another";
        r.facts.push_back({"band", what});
        // Every band's step (the first kListedBands), so a reader can choose.
        constexpr int kListedBands = 24;
        std::string all;
        for (int b = 1; b <= std::min(bands, kListedBands); ++b) {
            const std::string label = stepLabel(bandCoordinates(ds.h, GDALGetRasterBand(ds.h, b)));
            if (label.empty()) break;
            all += (all.empty() ? "" : "; ") + std::to_string(b) + ": " + label;
        }
        if (!all.empty()) r.facts.push_back({"bands", all + (bands > kListedBands ? "; ... (" + std::to_string(bands) + " in all)" : "")});
    }
    // The file's own words for what the values are: a CF long_name (or
    // standard_name), else the band's description.
    if (const char* d = GDALGetMetadataItem(band, "long_name", nullptr); d && *d) r.description = d;
    else if (const char* sn = GDALGetMetadataItem(band, "standard_name", nullptr); sn && *sn) {
        r.description = sn;
        std::replace(r.description.begin(), r.description.end(), '_', ' ');
    } else if (const char* bd = GDALGetDescription(band); bd && *bd) r.description = bd;
    if (const char* v = GDALGetMetadataItem(band, "NETCDF_VARNAME", nullptr); v && *v) r.variable = v;
    r.step = stepLabel(bandCoordinates(ds.h, band));
    if (const char* units = GDALGetRasterUnitType(band); units && *units) {
        r.units = units;
        r.facts.push_back({"units", units});
    }
    // A colour table (a palette), category names or a raster attribute
    // table with a name column mean the values are class codes: land cover,
    // soil types. Averaging two of them invents a class.
    r.classes = classNames(band);
    const bool palette = GDALGetRasterColorTable(band) || GDALGetRasterColorInterpretation(band) == GCI_PaletteIndex;
    if (palette || !r.classes.empty()) {
        r.categorical = true;
        r.facts.push_back({"values", std::string("classes (the band has ") +
                                         (palette ? "a colour table" : "class names") + ")"});
        if (!r.classes.empty()) {
            std::string names;
            for (const RasterClass& c : r.classes) {
                if (names.size() > 400) {
                    names += "; ...";
                    break;
                }
                names += (names.empty() ? "" : "; ") + formatSignificant(c.code) + " " + c.name;
            }
            r.facts.push_back({"class names", std::to_string(r.classes.size()) + ": " + names});
        }
    }

    // Pixel size on the ground (CRS units) and whether x is degrees of longitude.
    double gt[6] = {0, 1, 0, 0, -1, 0};
    const bool has_gt = !ignore_georef && GDALGetGeoTransform(ds.h, gt) == CE_None;
    if (!has_gt) {
        const double plain[6] = {0, 1, 0, double(rows), 0, -1};
        std::copy(plain, plain + 6, gt);
    }
    // Rotated or sheared: the pixel grid is not north-up (resampled below).
    const double det = gt[1] * gt[5] - gt[2] * gt[4];
    const bool rotated = has_gt && (gt[2] != 0 || gt[4] != 0) && std::isfinite(det) && det != 0;
    double px_w = std::abs(gt[1]), px_h = std::abs(gt[5]);
    if (rotated) px_w = px_h = std::sqrt(std::fabs(det));
    if (px_w == 0 || px_h == 0 || !std::isfinite(px_w) || !std::isfinite(px_h)) px_w = px_h = 1;
    // The latitude of the raster's centre (a geographic CRS's longitude scale).
    const double centre_y = gt[3] + gt[4] * cols / 2.0 + gt[5] * rows / 2.0;
    OGRSpatialReferenceH srs = ignore_georef ? nullptr : GDALGetSpatialRef(ds.h);
    if (ignore_georef) r.facts.push_back({"georeference", "ignored (--ignore-georef): the plain grid, square pixels"});
    double x_scale = 1.0;  // ground width of one unit of x, in units of y
    const bool lon_lat = has_gt && ((!srs && cfLonLat(ds.h)) || (srs && OSRIsGeographic(srs)));
    if (lon_lat) {
        // Degrees must be on the globe: a latitude of 435 is a file whose
        // coordinates are not what it says (or a grid of indices). Pixel
        // edges may pass a pole or +-180 by half a pixel.
        double worst_lat = 0, worst_lon = 0;
        for (const double c : {0.0, double(cols)})
            for (const double rr : {0.0, double(rows)}) {
                const double x = gt[0] + gt[1] * c + gt[2] * rr, y = gt[3] + gt[4] * c + gt[5] * rr;
                if (!(std::fabs(y) <= std::fabs(worst_lat))) worst_lat = y;
                if (!(std::fabs(x) <= std::fabs(worst_lon))) worst_lon = x;
            }
        const double slack = std::fabs(gt[1]) + std::fabs(gt[2]) + std::fabs(gt[4]) + std::fabs(gt[5]);
        if (!(std::fabs(worst_lat) <= 90.0 + slack) || !(std::fabs(worst_lon) <= 360.0 + slack)) {
            const bool lat = !(std::fabs(worst_lat) <= 90.0 + slack);
            throw InputError(path, 0, 0, std::string("its coordinates are ") +
                                             (srs ? "in a geographic CRS (degrees)" : "degrees east and north (CF units)") +
                                             ", but its " + (lat ? "y values reach latitude " : "x values reach longitude ") +
                                             formatSignificant(lat ? worst_lat : worst_lon) + " degrees, outside " +
                                             (lat ? "-90 to 90" : "-360 to 360") +
                                             ": the file's coordinates are wrong; --ignore-georef reads the plain grid");
        }
    }
    if (!srs && has_gt && cfLonLat(ds.h)) {
        // No CRS in the file, but CF coordinates in degrees east and north
        // (most climate files): longitude and latitude on the sphere.
        const double lat = centre_y;
        x_scale = std::cos(lat * kPi / 180.0);
        r.metres_per_unit = kMetresPerDegreeOfLatitude;
        r.longitude_scale = x_scale;
        r.facts.push_back({"crs", "none in the file; its coordinates are degrees east and north (CF), so longitude is "
                                  "scaled by cos(" + formatSignificant(lat) + " deg) = " + formatSignificant(x_scale)});
        r.facts.push_back({"pixel", formatSignificant(px_w) + " x " + formatSignificant(px_h) + " degrees"});
    } else if (srs && OSRIsGeographic(srs)) {
        const double lat = centre_y;  // mean latitude, degrees
        x_scale = std::cos(lat * kPi / 180.0);
        r.metres_per_unit = kMetresPerDegreeOfLatitude;
        r.longitude_scale = x_scale;
        r.facts.push_back({"crs", crsName(srs) + ", geographic: longitude scaled by cos(" + formatSignificant(lat) +
                                      " deg) = " + formatSignificant(x_scale)});
        r.facts.push_back({"pixel", formatSignificant(px_w) + " x " + formatSignificant(px_h) + " degrees"});
    } else if (srs) {
        char* unit = nullptr;
        const double metres = OSRGetLinearUnits(srs, &unit);
        if (OSRIsProjected(srs) && metres > 0 && std::isfinite(metres)) r.metres_per_unit = metres;
        const std::string u = unit ? unit : "units";
        r.facts.push_back({"crs", crsName(srs) + (OSRIsProjected(srs) ? ", projected: true aspect" : "")});
        r.facts.push_back({"pixel", formatSignificant(px_w) + " x " + formatSignificant(px_h) + " " + u});
    } else {
        r.facts.push_back({"crs", has_gt ? "none; pixel sizes taken as they are" : "none (no georeference)"});
        if (has_gt) r.facts.push_back({"pixel", formatSignificant(px_w) + " x " + formatSignificant(px_h)});
    }
    // The axes a reader is told the model's places in (the pixels' place
    // itself is set below, once the grid read is known).
    DataAxes axes;
    if (lon_lat) {
        axes = {"longitude", "latitude", "degrees"};
    } else if (srs && OSRIsProjected(srs)) {
        axes = {"easting", "northing", OSRGetLinearUnits(srs, nullptr) == 1.0 ? "metres" : ""};
    }

    int has_nodata = 0;
    const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
    if (rotated) {
        readRotated(band, path, cols, rows, gt, x_scale, r.categorical, has_nodata != 0, nodata, r);
        r.place.axes = axes;
        return finishValues(band, has_nodata != 0, nodata, r);
    }

    // Square pixels on the ground: stretch the shorter side of the pixel.
    const double ground_w = px_w * x_scale;
    int64_t out_cols = cols, out_rows = rows;
    if (ground_w > px_h) out_cols = std::llround(double(cols) * ground_w / px_h);
    else out_rows = std::llround(double(rows) * px_h / ground_w);
    r.x_origin = gt[0];
    r.y_origin = gt[3] + gt[5] * rows;

    // Larger than tsf holds whole: read decimated, each value the mean (the
    // most common class) of a block of pixels, strip by strip.
    const int64_t f = decimationFor(out_cols, out_rows);
    if (f > 1) {
        const int64_t dec_cols = (out_cols + f - 1) / f, dec_rows = (out_rows + f - 1) / f;
        checkRasterSize(path, 0, dec_cols, dec_rows);
        readDecimated(band, path, cols, rows, dec_cols, dec_rows, r.categorical, has_nodata != 0, nodata, r.values);
        r.cols = int32_t(dec_cols);
        r.rows = int32_t(dec_rows);
        r.cell_size = std::min(ground_w, px_h) * double(out_cols) / double(dec_cols);
        r.decimation = int(f);
        r.facts.push_back({"decimated", std::to_string(cols) + " x " + std::to_string(rows) + " px -> " +
                                            std::to_string(dec_cols) + " x " + std::to_string(dec_rows) + " values, each the " +
                                            (r.categorical ? "most common class" : "mean") + " of the pixels with data in a block of about " +
                                            formatSignificant(double(cols) / double(dec_cols), 3) + " x " +
                                            formatSignificant(double(rows) / double(dec_rows), 3) +
                                            " (the file is larger than tsf reads whole)"});
    } else {
        // Every pixel as it is: pixels that are not square on the ground keep
        // their shape as the raster's row aspect (one pillar per value
        // stretches its hexagons to it; resampling squares them first:
        // gen/field/resample.h).
        checkRasterSize(path, 0, cols, rows);
        r.cell_size = ground_w;
        r.row_aspect = px_h / ground_w;
        if (std::abs(r.row_aspect - 1.0) > 1e-9)
            r.facts.push_back({"pixel shape", "on the ground the rows are " + formatSignificant(r.row_aspect, 4) +
                                                  " times as far apart as the columns"});
        r.cols = int32_t(cols);
        r.rows = int32_t(rows);
        r.values.assign(size_t(cols) * size_t(rows), 0.0);
        if (!readPixels(band, 0, 0, cols, rows, r.values.data()))
            throw InputError(path, 0, 0, "GDAL could not read the pixels: " + QuietGdal::lastMessage());
    }
    // North-up (a south-up file's rows are not turned here: no place said).
    if (has_gt && gt[1] > 0 && gt[5] < 0)
        r.place = {.known = true,
                   .x_west = gt[0],
                   .dx = gt[1] * double(cols) / double(r.cols),
                   .y_north = gt[3],
                   .dy = -gt[5] * double(rows) / double(r.rows),
                   .axes = axes};

    return finishValues(band, has_nodata != 0, nodata, r);
}


Raster readGdalFile(const std::string& path, int band, const std::string& variable, bool ignore_georef) {
    return readDataset(path, path, band, variable, ignore_georef);
}

Raster parseGdalBytes(std::string_view bytes, const std::string& path, int band, const std::string& variable,
                      bool ignore_georef) {
    registerDrivers();
    static std::atomic<unsigned> counter{0};
    std::string ext;
    const size_t dot = path.find_last_of('.');
    if (dot != std::string::npos && path.find('/', dot) == std::string::npos) ext = path.substr(dot);
    const std::string name = "/vsimem/tsf-" + std::to_string(counter++) + ext;
    VSILFILE* f = VSIFileFromMemBuffer(name.c_str(), reinterpret_cast<GByte*>(const_cast<char*>(bytes.data())),
                                       vsi_l_offset(bytes.size()), /*bTakeOwnership=*/FALSE);
    if (!f) throw InputError(path, 0, 0, "GDAL cannot take the file's bytes");
    VSIFCloseL(f);
    struct Unlink {
        std::string n;
        ~Unlink() { VSIUnlink(n.c_str()); }
    } unlink{name};
    return readDataset(name, path, band, variable, ignore_georef);
}

}  // namespace
}  // namespace tsf

extern "C" __attribute__((visibility("default"))) int tsf_gdal_module_abi() { return tsf::kGdalModuleAbi; }

namespace tsf {
namespace {

// Runs `work`; no exception crosses the module's edge: an InputError comes
// back as its parts, anything else as its message.
template <class Work>
int guarded(GdalModuleError* error, Work work) {
    try {
        work();
        return kGdalOk;
    } catch (const InputError& e) {
        error->path = e.path();
        error->line = e.line();
        error->column = e.column();
        error->detail = e.detail();
        return kGdalInputError;
    } catch (const std::exception& e) {
        error->detail = e.what();
        return kGdalFailed;
    }
}

}  // namespace
}  // namespace tsf

extern "C" __attribute__((visibility("default"))) int tsf_gdal_read(const tsf::GdalCall* call) {
    return tsf::guarded(call->error, [call] {
        const std::string variable = call->variable ? *call->variable : std::string();
        *call->raster = call->bytes
                            ? tsf::parseGdalBytes(*call->bytes, *call->path, call->band, variable, call->ignore_georef)
                            : tsf::readGdalFile(*call->path, call->band, variable, call->ignore_georef);
    });
}

namespace tsf {
namespace {

struct Srs {
    OGRSpatialReferenceH h = OSRNewSpatialReference(nullptr);
    ~Srs() { OSRDestroySpatialReference(h); }
};

void transformPoints(const GdalTransformCall& c) {
    QuietGdal quiet;
    Srs from, to;
    // GDAL often says nothing more than that it failed: then what is accepted.
    const auto why = [] {
        const char* m = CPLGetLastErrorMsg();
        return m && *m ? std::string(" (") + m + ")" : std::string();
    };
    if (OSRSetFromUserInput(from.h, c.from->c_str()) != OGRERR_NONE)
        throw InputError("--crs '" + *c.from + "' is not a coordinate reference system GDAL and PROJ know" + why() +
                         ": give an EPSG code (EPSG:3857), a PROJ string (+proj=utm +zone=32 +datum=WGS84) or WKT");
    if (OSRSetFromUserInput(to.h, c.to->c_str()) != OGRERR_NONE)
        throw InputError("--project '" + *c.to + "' is not a projection GDAL and PROJ know" + why() +
                         ": give auto, none, equal-area, equirect, an EPSG code (EPSG:3035) or a PROJ string "
                         "(+proj=laea +lat_0=52 +lon_0=10)");
    // x east (longitude), y north (latitude), whatever order the authority gives.
    OSRSetAxisMappingStrategy(from.h, OAMS_TRADITIONAL_GIS_ORDER);
    OSRSetAxisMappingStrategy(to.h, OAMS_TRADITIONAL_GIS_ORDER);
    OGRCoordinateTransformationH t = OCTNewCoordinateTransformation(from.h, to.h);
    if (!t) throw InputError("no transformation from '" + *c.from + "' to '" + *c.to + "': " + QuietGdal::lastMessage());
    std::vector<double>& x = *c.x;
    std::vector<double>& y = *c.y;
    std::vector<int> ok(x.size(), 0);
    const int done = x.empty() ? 1 : OCTTransformEx(t, int(x.size()), x.data(), y.data(), nullptr, ok.data());
    OCTDestroyCoordinateTransformation(t);
    for (size_t k = 0; k < ok.size(); ++k)
        if (!done || !ok[k] || !std::isfinite(x[k]) || !std::isfinite(y[k]))
            throw InputError("point " + std::to_string(k + 1) + " cannot be projected from '" + *c.from + "' to '" + *c.to + "'");
    *c.to_name = crsName(to.h);
}

}  // namespace
}  // namespace tsf

extern "C" __attribute__((visibility("default"))) int tsf_gdal_transform(const tsf::GdalTransformCall* call) {
    return tsf::guarded(call->error, [call] { tsf::transformPoints(*call); });
}
