// loadField: any field file tsf reads -> the HexField a Scene is built from.
// The first step of every command that makes a model (tsf gen, tsf info,
// tsf verify --against), usable without the command line:
//
//   FieldLoadOptions in;
//   in.input = "examples/volcano.csv";
//   const HexField field = loadField(in);              // gen/readers/load_field.h
//   const Scene scene = buildScene(field, params);     // gen/model/build_scene.h
//
// Rasters (grid CSV, PGM, PNG, ESRI ASCII grid; raster_reader.h) become one
// hexagon per value when they fit the box at tactile cell sizes, and are
// resampled otherwise (placeRaster, gen/field/resample.h); a CSV of x,y points
// (points set) is projected when it holds longitude/latitude
// (point_projection.h) and binned into hexagons (point_binning.h). The option strings are the
// ones `tsf gen` takes on its command line (`tsf gen --help`).
#pragma once

#include <optional>
#include <string>

#include "gen/field/hex_field.h"

namespace tsf {

struct FieldLoadOptions {
    std::string input;          ///< field file
    /// "x=COL,y=COL[,w=COL]": read the CSV as points and bin them
    /// (COL = header name or 0-based index); "" = the file is a raster.
    std::string points;
    std::string aggregate = "count";  ///< count | sum | mean (points)
    double bin_size = 0.0;      ///< hex pitch in data units (points); 0 = from bins
    int bins = 0;               ///< target number of hex columns (points and rasters); 0 = default
    int band = 1;               ///< rasters GDAL reads: which band (1-based)
    std::string variable;       ///< rasters GDAL reads: which variable of a file with several ("" = the only one)
    /// Rasters: ignore the file's georeference (geotransform, CRS, ground
    /// size) and read the plain grid, square pixels (--ignore-georef).
    bool ignore_georef = false;
    /// raster -> hexes: auto (mode for class codes, Raster::categorical, else
    /// mean) | mean | mode | nearest | bilinear
    std::string sample = "auto";
    /// The raster's values are class codes even without a colour table or
    /// class names in the file (a CSV or PNG of codes): resampled by the
    /// most common class, never averaged.
    bool categorical = false;
    /// "95,90,41" or names the file gives ("Open Water,Deciduous Forest"):
    /// the classes are ordered, lowest first; each stands one even step of
    /// height above the one before (the values become the ranks 1..N).
    /// Every class the model holds must be listed. Class maps only.
    std::string class_order;
    /// A CSV of code,name naming a class map's classes (over the file's own
    /// names; gen/readers/class_labels.h). "" = none.
    std::string class_names;
    /// "21-24=Developed;41-43=Forest": codes joined into one class each,
    /// named (gen/readers/class_labels.h). "" = none. Class maps only.
    std::string class_groups;
    std::string delimiter;      ///< CSV delimiter: "," ";" "tab" "space" (or the character); "" = detect
    bool decimal_comma = false; ///< grid CSV: "1,5" is 1.5 (default: detected, gen/readers/decimal_mark.h)
    std::optional<double> nodata;  ///< rasters: this value means "no data" (e.g. -9999)
    std::string project = "auto";  ///< points: auto | none | equirect | equal-area | a PROJ/EPSG definition (point_projection.h)
    std::string crs;               ///< points: the CRS the x, y columns are in ("" = longitude / latitude, or none)
    // Where the model goes: decides one pillar per value or resampling (RasterPlacement).
    double cell_mm = 0;         ///< the cell size asked for (mm); 0 = fit the box
    double fit_width_mm = 150;  ///< the box the model must fit (mm)
    double fit_depth_mm = 150;
    double min_cell_mm = 3.0;   ///< smallest default cell for rasters (kMinTactileCellMm; a wide nozzle raises it)
    bool true_aspect = true;    ///< one pillar per value keeps the ground's aspect (SceneParams::true_aspect)
};

/// Reads the input named in opts and builds its hex field (rasters are
/// resampled, points are binned); HexField::source is opts.input and
/// HexField::input says what was read (the reader's detections, the raw
/// values' range and no-data count; for points the weights' range). When a
/// raster's smallest value is a common no-data placeholder (-9999, -32768,
/// ...) and no --nodata was given, a fact and HexField::how say so. Throws
/// tsf::InputError for a missing or malformed file and for a bad option.
HexField loadField(const FieldLoadOptions& opts);

/// The class codes `text` lists (codes, or names from `classes`, matched
/// without regard to case), in its order. Throws InputError for an empty
/// entry, a name the file does not give, or a class listed twice.
std::vector<double> parseClassOrder(const std::string& text, const std::vector<RasterClass>& classes);

}  // namespace tsf
