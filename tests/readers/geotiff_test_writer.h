// Writes small GeoTIFFs for the GDAL reader's tests through GDAL's own C API,
// so no binary test file is checked in. Test-only: the library reads GDAL
// only in gen/readers/gdal_reader.cpp.
#pragma once

#include <gdal.h>
#include <gdal_rat.h>
#include <ogr_srs_api.h>

#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tsf::test {

struct GeoTiffSpec {
    int cols = 0, rows = 0;
    std::vector<float> values;  ///< row-major, row 0 north
    int epsg = 0;               ///< 0 = no CRS
    double west = 0, north = 0; ///< top-left corner, CRS units
    double pixel_w = 1, pixel_h = 1;  ///< CRS units, positive
    std::optional<double> nodata;
    bool classes = false;       ///< an 8-bit band with a colour table (a class map); values 0..255
    int bands = 1;              ///< band b (1-based) holds values + 100 * (b - 1)
    /// Band 1's category names (index = class code; "" for a code without
    /// one), without a colour table unless `classes` asks for one.
    std::vector<std::string> category_names;
    /// Band 1's raster attribute table: (class code, name) rows in a Value
    /// and a Name column.
    std::vector<std::pair<int, std::string>> attribute_names;
    bool byte_band = false;     ///< an 8-bit band (class codes 0..255) without a colour table
    /// GDAL's six numbers (x0, dx/dcol, dx/drow, y0, dy/dcol, dy/drow): a
    /// rotated or sheared raster; empty = north-up from west, north and the pixel sizes.
    std::vector<double> geotransform;
    std::string description;    ///< band 1's description ("elevation"); "" for none
    std::string units;          ///< band 1's unit type ("m"); "" for none
};

/// Writes spec as a Float32 GeoTIFF; returns false when GDAL refuses.
inline bool writeGeoTiff(const std::string& path, const GeoTiffSpec& s) {
    GDALAllRegister();
    GDALDriverH driver = GDALGetDriverByName("GTiff");
    if (!driver) return false;
    GDALDatasetH ds = GDALCreate(driver, path.c_str(), s.cols, s.rows, s.bands, s.classes || s.byte_band ? GDT_Byte : GDT_Float32, nullptr);
    if (!ds) return false;
    double gt[6] = {s.west, s.pixel_w, 0, s.north, 0, -s.pixel_h};
    if (s.geotransform.size() == 6) std::copy(s.geotransform.begin(), s.geotransform.end(), gt);
    GDALSetGeoTransform(ds, gt);
    if (s.epsg != 0) {
        OGRSpatialReferenceH srs = OSRNewSpatialReference(nullptr);
        OSRImportFromEPSG(srs, s.epsg);
        GDALSetSpatialRef(ds, srs);
        OSRDestroySpatialReference(srs);
    }
    GDALRasterBandH band = GDALGetRasterBand(ds, 1);
    if (s.nodata) GDALSetRasterNoDataValue(band, *s.nodata);
    if (!s.description.empty()) GDALSetDescription(band, s.description.c_str());
    if (!s.units.empty()) GDALSetRasterUnitType(band, s.units.c_str());
    if (s.classes) {
        GDALColorTableH table = GDALCreateColorTable(GPI_RGB);
        for (int k = 0; k < 256; ++k) {
            const GDALColorEntry e{short(k), short(255 - k), short((k * 7) % 256), 255};
            GDALSetColorEntry(table, k, &e);
        }
        GDALSetRasterColorTable(band, table);
        GDALDestroyColorTable(table);
    }
    if (!s.category_names.empty()) {
        std::vector<char*> names;
        for (const std::string& n : s.category_names) names.push_back(const_cast<char*>(n.c_str()));
        names.push_back(nullptr);
        GDALSetRasterCategoryNames(band, names.data());
    }
    if (!s.attribute_names.empty()) {
        GDALRasterAttributeTableH rat = GDALCreateRasterAttributeTable();
        GDALRATCreateColumn(rat, "Value", GFT_Integer, GFU_MinMax);
        GDALRATCreateColumn(rat, "Name", GFT_String, GFU_Name);
        GDALRATSetRowCount(rat, int(s.attribute_names.size()));
        for (size_t k = 0; k < s.attribute_names.size(); ++k) {
            GDALRATSetValueAsInt(rat, int(k), 0, s.attribute_names[k].first);
            GDALRATSetValueAsString(rat, int(k), 1, s.attribute_names[k].second.c_str());
        }
        GDALSetDefaultRAT(band, rat);
        GDALDestroyRasterAttributeTable(rat);
    }
    bool ok = true;
    for (int b = 1; b <= s.bands; ++b) {
        std::vector<float> v = s.values;
        for (float& x : v) x += float(100 * (b - 1));
        GDALRasterBandH each = GDALGetRasterBand(ds, b);
        if (s.nodata && b > 1) GDALSetRasterNoDataValue(each, *s.nodata);
        ok = ok && GDALRasterIO(each, GF_Write, 0, 0, s.cols, s.rows, v.data(), s.cols, s.rows, GDT_Float32, 0, 0) ==
                       CE_None;
    }
    GDALClose(ds);
    return ok;
}

}  // namespace tsf::test
