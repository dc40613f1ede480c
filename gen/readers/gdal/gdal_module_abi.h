// What tsf and its GDAL module (tsf-gdal.so, gdal_module.cpp) pass each
// other. Both are built together from one tree with one compiler, so plain
// C++ types cross; the version below keeps a module of another build from
// being used. No exception crosses: errors come back as GdalModuleError.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gen/field/raster.h"

namespace tsf {

/// The module's file name (CMakeLists.txt builds it under this name).
inline constexpr const char* kGdalModuleName = "tsf-gdal.so";

/// Bumped whenever GdalCall, GdalModuleError or Raster change.
inline constexpr int kGdalModuleAbi = 9;  // 9: Raster::description, variable, step; 8: GdalCall::ignore_georef; 7: Raster::classes; 6: Raster::decimation, units; 5: GdalCall::variable; 4: tsf_gdal_transform; 3: GdalCall::band; 2: Raster::categorical

inline constexpr int kGdalOk = 0;
inline constexpr int kGdalInputError = 1;  ///< error holds an InputError's parts
inline constexpr int kGdalFailed = 2;      ///< error.detail holds what failed

struct GdalModuleError {
    std::string path;
    int line = 0, column = 0;
    std::string detail;
};

struct GdalCall {
    const std::string* path = nullptr;        ///< the file, or the name of the bytes in messages
    const std::string_view* bytes = nullptr;  ///< the file's bytes in memory; nullptr: read `path`
    Raster* raster = nullptr;                 ///< out
    GdalModuleError* error = nullptr;         ///< out, when the result is not kGdalOk
    int band = 1;                             ///< which band, 1-based (bands, time steps, levels)
    const std::string* variable = nullptr;    ///< which variable (subdataset) of a file with several; nullptr or "": the only one
    bool ignore_georef = false;               ///< read the plain grid: no geotransform, no CRS (--ignore-georef)
};

/// Points from one coordinate reference system to another (PROJ, through
/// GDAL's OSR): x is the easting or longitude, y the northing or latitude.
struct GdalTransformCall {
    const std::string* from = nullptr;  ///< any CRS GDAL reads from user input: "EPSG:4326", "+proj=...", WKT
    const std::string* to = nullptr;
    std::vector<double>* x = nullptr;   ///< in and out
    std::vector<double>* y = nullptr;   ///< in and out
    std::string* to_name = nullptr;     ///< out: the target CRS's name
    GdalModuleError* error = nullptr;   ///< out, when the result is not kGdalOk
};

// The module's entry points (extern "C", looked up with dlsym):
//   int tsf_gdal_module_abi();                 returns kGdalModuleAbi
//   int tsf_gdal_read(const GdalCall* call);   returns kGdalOk, kGdalInputError or kGdalFailed
//   int tsf_gdal_transform(const GdalTransformCall* call);   the same

}  // namespace tsf
