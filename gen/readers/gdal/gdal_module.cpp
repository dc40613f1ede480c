// The GDAL module (tsf-gdal.so): the only code that includes or links GDAL.
// tsf loads it with dlopen the first time a raster needs GDAL (gdal_reader.cpp),
// so the hundred-odd libraries GDAL pulls in cost nothing to the commands
// that never read a GeoTIFF (about 70 ms at every start when linked).
#include "gen/readers/gdal/gdal_module_abi.h"

#include <atomic>
#include <cmath>
#include <cpl_conv.h>
#include <cpl_error.h>
#include <cpl_vsi.h>
#include <gdal.h>
#include <mutex>
#include <ogr_srs_api.h>
#include <sstream>
#include <vector>

#include "gen/util/error.h"
#include "gen/readers/raster_limits.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;

void registerDrivers() {
    static std::once_flag once;
    std::call_once(once, [] { GDALAllRegister(); });
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

Raster readDataset(const std::string& gdal_name, const std::string& path, int band_number) {
    registerDrivers();
    QuietGdal quiet;
    Dataset ds;
    ds.h = GDALOpenEx(gdal_name.c_str(), GDAL_OF_RASTER | GDAL_OF_READONLY, nullptr, nullptr, nullptr);
    if (!ds.h) throw InputError(path, 0, 0, "GDAL cannot read it as a raster: " + QuietGdal::lastMessage());
    const int cols = GDALGetRasterXSize(ds.h), rows = GDALGetRasterYSize(ds.h), bands = GDALGetRasterCount(ds.h);
    if (bands < 1) throw InputError(path, 0, 0, "has no raster band");
    checkRasterSize(path, 0, cols, rows);
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
        if (const char* d = GDALGetDescription(band); d && *d) what += std::string(" (") + d + ")";
        if (band_number == 1) what += "; --band N for another";
        r.facts.push_back({"band", what});
    }
    // A colour table (a palette) means the values are class codes: land
    // cover, soil types. Averaging two of them invents a class.
    if (GDALGetRasterColorTable(band) || GDALGetRasterColorInterpretation(band) == GCI_PaletteIndex) {
        r.categorical = true;
        r.facts.push_back({"values", "classes (the band has a colour table)"});
    }

    // Pixel size on the ground (CRS units) and whether x is degrees of longitude.
    double gt[6] = {0, 1, 0, 0, -1, 0};
    const bool has_gt = GDALGetGeoTransform(ds.h, gt) == CE_None;
    double px_w = std::abs(gt[1]), px_h = std::abs(gt[5]);
    if (px_w == 0 || px_h == 0 || !std::isfinite(px_w) || !std::isfinite(px_h)) px_w = px_h = 1;
    if (has_gt && (gt[2] != 0 || gt[4] != 0)) r.facts.push_back({"note", "rotated geotransform read as north-up"});
    OGRSpatialReferenceH srs = GDALGetSpatialRef(ds.h);
    double x_scale = 1.0;  // ground width of one unit of x, in units of y
    if (srs && OSRIsGeographic(srs)) {
        const double lat = gt[3] + gt[5] * rows / 2.0;  // mean latitude, degrees
        x_scale = std::cos(lat * kPi / 180.0);
        r.facts.push_back({"crs", crsName(srs) + ", geographic: longitude scaled by cos(" + formatSignificant(lat) +
                                      " deg) = " + formatSignificant(x_scale)});
        r.facts.push_back({"pixel", formatSignificant(px_w) + " x " + formatSignificant(px_h) + " degrees"});
    } else if (srs) {
        char* unit = nullptr;
        OSRGetLinearUnits(srs, &unit);
        const std::string u = unit ? unit : "units";
        r.facts.push_back({"crs", crsName(srs) + (OSRIsProjected(srs) ? ", projected: true aspect" : "")});
        r.facts.push_back({"pixel", formatSignificant(px_w) + " x " + formatSignificant(px_h) + " " + u});
    } else {
        r.facts.push_back({"crs", has_gt ? "none; pixel sizes taken as they are" : "none (no georeference)"});
        if (has_gt) r.facts.push_back({"pixel", formatSignificant(px_w) + " x " + formatSignificant(px_h)});
    }

    // Square pixels on the ground: stretch the shorter side of the pixel.
    const double ground_w = px_w * x_scale;
    int out_cols = cols, out_rows = rows;
    if (ground_w > px_h) out_cols = int(std::lround(cols * ground_w / px_h));
    else out_rows = int(std::lround(rows * px_h / ground_w));
    checkRasterSize(path, 0, out_cols, out_rows);
    r.cell_size = std::min(ground_w, px_h);
    r.x_origin = gt[0];
    r.y_origin = gt[3] + gt[5] * rows;
    if (out_cols != cols || out_rows != rows)
        r.facts.push_back({"resampled", std::to_string(cols) + " x " + std::to_string(rows) + " -> " +
                                            std::to_string(out_cols) + " x " + std::to_string(out_rows) +
                                            " square pixels (nearest) to keep the ground's aspect"});

    r.cols = out_cols;
    r.rows = out_rows;
    r.values.assign(size_t(out_cols) * size_t(out_rows), 0.0);
    GDALRasterIOExtraArg extra;
    INIT_RASTERIO_EXTRA_ARG(extra);
    extra.eResampleAlg = GRIORA_NearestNeighbour;
    if (GDALRasterIOEx(band, GF_Read, 0, 0, cols, rows, r.values.data(), out_cols, out_rows, GDT_Float64, 0, 0,
                       &extra) != CE_None)
        throw InputError(path, 0, 0, "GDAL could not read the pixels: " + QuietGdal::lastMessage());

    int has_nodata = 0;
    const double nodata = GDALGetRasterNoDataValue(band, &has_nodata);
    for (double& v : r.values)
        if ((has_nodata && v == nodata) || !std::isfinite(v)) v = NAN;
    if (has_nodata) r.facts.push_back({"no-data value", formatSignificant(nodata) + " (from the file)"});
    return r;
}

Raster readGdalFile(const std::string& path, int band) { return readDataset(path, path, band); }

Raster parseGdalBytes(std::string_view bytes, const std::string& path, int band) {
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
    return readDataset(name, path, band);
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
        *call->raster = call->bytes ? tsf::parseGdalBytes(*call->bytes, *call->path, call->band)
                                    : tsf::readGdalFile(*call->path, call->band);
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
    if (OSRSetFromUserInput(from.h, c.from->c_str()) != OGRERR_NONE)
        throw InputError("'" + *c.from + "' is not a coordinate reference system GDAL and PROJ know: " + QuietGdal::lastMessage());
    if (OSRSetFromUserInput(to.h, c.to->c_str()) != OGRERR_NONE)
        throw InputError("'" + *c.to + "' is not a projection GDAL and PROJ know: " + QuietGdal::lastMessage());
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
