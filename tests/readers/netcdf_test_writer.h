// Writes small CF NetCDF files for the GDAL reader's tests through GDAL's
// multidimensional C API, so no binary test file is checked in. Test-only.
//
// The file: dimensions time (steps), lat (rows, ascending: south first, as
// most climate files have it; one degree apart around the equator, so a
// degree of longitude is one of latitude on the ground), lon (cols, one
// degree apart from 10 E); coordinate variables with CF
// units ("degrees_north", "degrees_east", "days since 2000-01-01" on the
// standard calendar, steps 0, 31, 60, ... days); and two variables on
// (time, lat, lon):
//   pr:  float, units "mm/day", _FillValue 1e20 at (lat 0, lon 0) in every
//        step, elsewhere 100 * (t + 1) + 10 * lat + lon;
//   tas: 16-bit integers packed with scale_factor 0.5 and add_offset 200
//        (kelvin): stored 2 * lon + lat + t, so the value is 200 + that / 2.
#pragma once

#include <gdal.h>

#include <cstdint>
#include <string>
#include <vector>

namespace tsf::test {

struct NetCdfSpec {
    int steps = 3, rows = 4, cols = 5;
    double lat_shift = 0;  ///< added to every latitude (degrees): a file whose y values are off the globe
};

inline double netcdfPr(int t, int lat, int lon) { return 100.0 * (t + 1) + 10.0 * lat + lon; }
inline double netcdfTas(int t, int lat, int lon) { return 200.0 + 0.5 * (2 * lon + lat + t); }

/// Writes the file; returns false when GDAL has no netCDF driver or refuses.
/// format: the driver's FORMAT (NC: classic, NC2: 64-bit offsets, NC4:
/// HDF5-based), or empty for the driver's default.
inline bool writeNetCdf(const std::string& path, const NetCdfSpec& s = {}, const std::string& format = "") {
    GDALAllRegister();
    GDALDriverH driver = GDALGetDriverByName("netCDF");
    if (!driver) return false;
    const std::string format_option = "FORMAT=" + format;
    const char* options[] = {format_option.c_str(), nullptr};
    GDALDatasetH ds = GDALCreateMultiDimensional(driver, path.c_str(), nullptr, format.empty() ? nullptr : options);
    if (!ds) return false;
    GDALGroupH root = GDALDatasetGetRootGroup(ds);
    GDALExtendedDataTypeH f64 = GDALExtendedDataTypeCreate(GDT_Float64);
    GDALExtendedDataTypeH f32 = GDALExtendedDataTypeCreate(GDT_Float32);
    GDALExtendedDataTypeH i16 = GDALExtendedDataTypeCreate(GDT_Int16);
    GDALExtendedDataTypeH text = GDALExtendedDataTypeCreateString(0);
    bool ok = true;
    auto attribute = [&](GDALMDArrayH array, const char* name, const char* value) {
        GDALAttributeH a = GDALMDArrayCreateAttribute(array, name, 0, nullptr, text, nullptr);
        ok = ok && a && GDALAttributeWriteString(a, value);
        if (a) GDALAttributeRelease(a);
    };
    GDALDimensionH dims[3] = {GDALGroupCreateDimension(root, "time", "TEMPORAL", nullptr, GUInt64(s.steps), nullptr),
                              GDALGroupCreateDimension(root, "lat", "HORIZONTAL_Y", nullptr, GUInt64(s.rows), nullptr),
                              GDALGroupCreateDimension(root, "lon", "HORIZONTAL_X", nullptr, GUInt64(s.cols), nullptr)};
    // Coordinate variables.
    const char* names[3] = {"time", "lat", "lon"};
    const char* units[3] = {"days since 2000-01-01", "degrees_north", "degrees_east"};
    for (int d = 0; d < 3; ++d) {
        GDALMDArrayH coord = GDALGroupCreateMDArray(root, names[d], 1, &dims[d], f64, nullptr);
        ok = ok && coord;
        if (!coord) continue;
        attribute(coord, "units", units[d]);
        if (d == 0) attribute(coord, "calendar", "standard");
        const size_t n = size_t(d == 0 ? s.steps : d == 1 ? s.rows : s.cols);
        std::vector<double> v(n);
        for (size_t k = 0; k < n; ++k)
            v[k] = d == 0   ? (k == 0 ? 0.0 : k == 1 ? 31.0 : 60.0 + 30.0 * double(k - 2))
                   : d == 1 ? double(k) - 0.5 * double(n - 1) + s.lat_shift  // centred on the equator: square pixels on the ground
                            : 10.0 + double(k);
        const GUInt64 start = 0;
        const size_t count = n;
        ok = ok && GDALMDArrayWrite(coord, &start, &count, nullptr, nullptr, f64, v.data(), nullptr, 0);
        GDALMDArrayRelease(coord);
    }
    const size_t n = size_t(s.steps) * size_t(s.rows) * size_t(s.cols);
    const GUInt64 start[3] = {0, 0, 0};
    const size_t count[3] = {size_t(s.steps), size_t(s.rows), size_t(s.cols)};
    // pr: floats with a fill value.
    if (GDALMDArrayH pr = GDALGroupCreateMDArray(root, "pr", 3, dims, f32, nullptr)) {
        attribute(pr, "units", "mm/day");
        attribute(pr, "long_name", "precipitation");
        ok = ok && GDALMDArraySetNoDataValueAsDouble(pr, 1e20);
        std::vector<float> v(n);
        for (int t = 0; t < s.steps; ++t)
            for (int r = 0; r < s.rows; ++r)
                for (int c = 0; c < s.cols; ++c)
                    v[(size_t(t) * size_t(s.rows) + size_t(r)) * size_t(s.cols) + size_t(c)] =
                        r == 0 && c == 0 ? 1e20f : float(netcdfPr(t, r, c));
        ok = ok && GDALMDArrayWrite(pr, start, count, nullptr, nullptr, f32, v.data(), nullptr, 0);
        GDALMDArrayRelease(pr);
    } else {
        ok = false;
    }
    // tas: packed 16-bit integers.
    if (GDALMDArrayH tas = GDALGroupCreateMDArray(root, "tas", 3, dims, i16, nullptr)) {
        attribute(tas, "units", "K");
        ok = ok && GDALMDArraySetScale(tas, 0.5) && GDALMDArraySetOffset(tas, 200.0);
        std::vector<int16_t> v(n);
        for (int t = 0; t < s.steps; ++t)
            for (int r = 0; r < s.rows; ++r)
                for (int c = 0; c < s.cols; ++c)
                    v[(size_t(t) * size_t(s.rows) + size_t(r)) * size_t(s.cols) + size_t(c)] = int16_t(2 * c + r + t);
        ok = ok && GDALMDArrayWrite(tas, start, count, nullptr, nullptr, i16, v.data(), nullptr, 0);
        GDALMDArrayRelease(tas);
    } else {
        ok = false;
    }
    for (GDALDimensionH d : dims)
        if (d) GDALDimensionRelease(d);
    for (GDALExtendedDataTypeH t : {f64, f32, i16, text}) GDALExtendedDataTypeRelease(t);
    GDALGroupRelease(root);
    GDALClose(ds);
    return ok;
}

}  // namespace tsf::test
