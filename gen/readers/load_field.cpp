#include "gen/readers/load_field.h"

#include "gen/util/error.h"
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <sstream>

#include "gen/readers/class_labels.h"
#include "gen/readers/point_binning.h"
#include "gen/readers/point_projection.h"
#include "gen/readers/point_reader.h"
#include "gen/readers/raster_reader.h"
#include "gen/field/resample.h"
#include "gen/util/file_bytes.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

// A class-names CSV is a few lines per class: far below this.
constexpr int64_t kMaxClassNamesBytes = int64_t(16) << 20;

// Values GIS tools and loggers write for "no data"; a raster whose smallest
// value is one of them almost certainly means it as no data.
bool looksLikeNoDataPlaceholder(double v) {
    return v == -9999.0 || v == -99999.0 || v == -32768.0 || v == -32767.0 || v == -3.4028234663852886e38 ||
           v == -1e30;
}

std::string lower(std::string s) {
    for (char& c : s) c = char(std::tolower(static_cast<unsigned char>(c)));
    return s;
}

std::string trimmed(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

// --class-order: the field's class codes become their ranks, 1 for the
// first listed. A class in the model the list leaves out has no height.
void orderClasses(HexField& f, const std::vector<double>& order) {
    std::vector<double> missing;
    for (double& v : f.values) {
        if (std::isnan(v)) continue;
        const auto at = std::find(order.begin(), order.end(), v);
        if (at == order.end()) {
            if (std::find(missing.begin(), missing.end(), v) == missing.end()) missing.push_back(v);
            continue;
        }
        v = double(at - order.begin() + 1);
    }
    if (!missing.empty()) {
        std::sort(missing.begin(), missing.end());
        std::string list;
        for (const double m : missing) list += (list.empty() ? "" : ", ") + formatSignificant(m);
        throw InputError("--class-order leaves out class" + std::string(missing.size() == 1 ? " " : "es ") + list +
                         ", which the model holds: list every class, lowest first");
    }
    std::string chain;
    for (const double c : order) chain += (chain.empty() ? "" : " < ") + formatSignificant(c);
    f.how += "; classes in the order given (--class-order), each one step of height: " + chain;
    f.input.class_order = order;
}

}  // namespace

std::vector<double> parseClassOrder(const std::string& text, const std::vector<RasterClass>& classes) {
    std::vector<double> order;
    std::stringstream in(text);
    std::string item;
    while (std::getline(in, item, ',')) {
        item = trimmed(item);
        if (item.empty()) throw InputError("--class-order \"" + text + "\": an empty entry (codes or names, separated by commas)");
        double code = 0;
        char* end = nullptr;
        const double v = std::strtod(item.c_str(), &end);
        if (end && *end == '\0' && std::isfinite(v)) {
            code = v;
        } else {
            const auto named = std::find_if(classes.begin(), classes.end(),
                                            [&](const RasterClass& c) { return lower(c.name) == lower(item); });
            if (named == classes.end())
                throw InputError("--class-order: \"" + item + "\" is neither a class code nor a name the file gives its classes" +
                                 (classes.empty() ? " (it names none)" : ""));
            code = named->code;
        }
        if (std::find(order.begin(), order.end(), code) != order.end())
            throw InputError("--class-order lists class " + formatSignificant(code) + " twice");
        order.push_back(code);
    }
    if (order.empty()) throw InputError("--class-order: no class given");
    return order;
}

HexField loadField(const FieldLoadOptions& o) {
    if (!o.delimiter.empty() && o.delimiter != "," && o.delimiter != ";" && o.delimiter != "tab" &&
        o.delimiter != "\t" && o.delimiter != "space" && o.delimiter != " ")
        throw InputError("--delimiter: expected , ; tab or space, got '" + o.delimiter + "'");
    const char delimiter = o.delimiter.empty()                              ? 0
                           : (o.delimiter == "tab" || o.delimiter == "\t") ? '\t'
                           : (o.delimiter == "space" || o.delimiter == " ") ? ' '
                                                                            : o.delimiter[0];
    if (o.band < 1) throw InputError("--band " + std::to_string(o.band) + ": bands are counted from 1");
    if (!o.points.empty() && o.band != 1)
        throw InputError("--band is for rasters with several bands; a table of points has none");
    if (!o.points.empty() && !o.variable.empty())
        throw InputError("--variable is for files with several variables (NetCDF, HDF5); a table of points has columns: "
                         "--points x=COL,y=COL");
    if (!o.points.empty() && !o.class_order.empty())
        throw InputError("--class-order is for class maps; points are counted, summed or averaged into hexagons");
    if (!o.points.empty() && (!o.class_names.empty() || !o.class_groups.empty()))
        throw InputError(std::string(o.class_names.empty() ? "--class-groups" : "--class-names") +
                         " is for class maps; points are counted, summed or averaged into hexagons");
    if (!o.points.empty() && o.categorical)
        throw InputError("--categorical is for rasters of class codes; points are counted, summed or averaged into "
                         "hexagons (--aggregate)");
    if (!o.points.empty() && o.ignore_georef)
        throw InputError("--ignore-georef is for rasters; for points give --project none to use x and y as they are");
    if (!o.points.empty()) {
        PointColumns cols = parsePointColumns(o.points);
        cols.delimiter = delimiter;
        const PointTable table = readPointsCsv(o.input, cols);
        BinOptions b;
        b.aggregate = parseAggregate(o.aggregate);
        b.bin_size = o.bin_size;
        b.hex_cols = o.bins;
        PointTable points = table;
        double metres_per_unit = 0;
        const std::string projected = projectPoints(points, parseProjection(o.project), o.crs, &metres_per_unit);
        HexField f = binPoints(points, b);
        f.source = o.input;
        // Projected, a tooth along an edge marks no one longitude or latitude.
        if (!projected.empty()) f.place = {};
        f.input.kind = "points";
        // (All points at one place give one hexagon of an arbitrary size: no ground to state.)
        if (metres_per_unit > 0 && (f.grid.cellCount() > 1 || o.bin_size > 0)) {
            // The ground the lattice covers (its bounding box) and each hexagon's
            // area: a count per hexagon is then a density a reader can use.
            const double pitch_m = f.pitch_data * metres_per_unit;
            f.input.metres_per_unit = metres_per_unit;
            f.input.ground_width_m = pitch_m * (double(f.grid.cols) + (f.grid.rows > 1 ? 0.5 : 0.0));
            f.input.ground_depth_m = pitch_m * (3.0 * double(f.grid.rows) + 1.0) / (2.0 * kSqrt3);
            f.input.hexagon_area_km2 = pitch_m * pitch_m * kSqrt3 / 2.0 / 1e6;
        }
        describeValues(table.weight, f.input);
        f.input.values = int64_t(table.size());
        if (!projected.empty()) f.how += "; " + projected;
        return f;
    }
    RasterReadOptions ro;
    ro.delimiter = delimiter;
    ro.decimal = o.decimal_comma ? DecimalMark::Comma : DecimalMark::Detect;
    ro.band = o.band;
    ro.variable = o.variable;
    ro.ignore_georef = o.ignore_georef;
    Raster raster = readRaster(o.input, ro);
    if (o.ignore_georef) {  // the plain grid, also of formats that carry a cell size (ESRI ASCII)
        raster.metres_per_unit = 0;
        raster.longitude_scale = 0;
        raster.place = {};
    }
    if (o.categorical && !raster.categorical) {
        raster.categorical = true;
        raster.facts.push_back({"values", "classes (--categorical)"});
    }
    int64_t nodata_cells = 0;
    if (o.nodata)
        for (double& v : raster.values)
            if (v == *o.nodata) {
                v = NAN;
                ++nodata_cells;
            }
    if ((!o.class_names.empty() || !o.class_groups.empty()) && !raster.categorical)
        throw InputError(std::string(o.class_names.empty() ? "--class-groups" : "--class-names") + " is for class maps: the values of " +
                         o.input + " are measurements (give --categorical if they are class codes)");
    if (!o.class_names.empty()) {
        const std::vector<RasterClass> names = parseClassNames(readFileBytes(o.class_names, kMaxClassNamesBytes), o.class_names);
        raster.classes = mergeClassNames(raster.classes, names);
        raster.facts.push_back({"class names", std::to_string(names.size()) + " from " + o.class_names + " (--class-names)"});
    }
    if (!o.class_groups.empty()) {
        const std::vector<ClassGroup> groups = parseClassGroups(o.class_groups);
        const int64_t joined = applyClassGroups(raster.values, raster.classes, groups);
        std::string list;
        for (const ClassGroup& g : groups)
            list += (list.empty() ? "" : "; ") + formatSignificant(g.lo) + (g.hi > g.lo ? " to " + formatSignificant(g.hi) : "") +
                    " as " + g.name;
        raster.facts.push_back({"class groups", list + " (--class-groups; " + std::to_string(joined) + " values joined)"});
    }
    FieldInput input;
    input.kind = raster.kind;
    input.cols = raster.cols;
    input.rows = raster.rows;
    input.facts = raster.facts;
    input.units = raster.units;
    input.description = raster.description;
    input.variable = raster.variable;
    input.step = raster.step;
    input.categorical = raster.categorical;
    input.classes = raster.classes;
    input.metres_per_unit = raster.metres_per_unit;
    input.longitude_scale = raster.longitude_scale;
    if (raster.metres_per_unit > 0) {
        input.ground_width_m = double(raster.cols) * raster.cell_size * raster.metres_per_unit;
        input.ground_depth_m = double(raster.rows) * raster.cell_size * raster.row_aspect * raster.metres_per_unit;
    }
    describeValues(raster.values, input);
    std::string placeholder_note;
    if (o.nodata) {
        input.facts.push_back({"no-data value", formatSignificant(*o.nodata) + " (--nodata), " +
                                                    std::to_string(nodata_cells) + " cells"});
    } else if (looksLikeNoDataPlaceholder(input.min)) {
        placeholder_note = "; the smallest value " + formatSignificant(input.min) +
                           " looks like a no-data placeholder: give --nodata " + formatSignificant(input.min) +
                           " if it is one";
        input.facts.push_back({"note", placeholder_note.substr(2)});
    }
    RasterPlacement pl;
    pl.hex_cols = o.bins;
    pl.method = o.sample == "auto" ? (raster.categorical ? ResampleOptions::Method::Mode : ResampleOptions::Method::Mean)
                                   : parseResampleMethod(o.sample);
    if (raster.categorical && pl.method == ResampleOptions::Method::Mean)
        input.facts.push_back({"note", "--sample mean averages class codes into values no class has; --sample mode "
                                       "(the default for classes) keeps every hexagon a class of the map"});
    pl.pitch_mm = o.cell_mm;
    pl.fit_width_mm = o.fit_width_mm;
    pl.fit_depth_mm = o.fit_depth_mm;
    pl.min_cell_mm = o.min_cell_mm;
    pl.true_aspect = o.true_aspect;
    if (!o.class_order.empty() && !raster.categorical)
        throw InputError("--class-order is for class maps: the values of " + o.input +
                         " are measurements (give --categorical if they are class codes)");
    const std::vector<double> order =
        o.class_order.empty() ? std::vector<double>() : parseClassOrder(o.class_order, raster.classes);
    HexField f = placeRaster(raster, pl);
    f.source = o.input;
    f.input = std::move(input);
    if (!order.empty()) orderClasses(f, order);
    f.how += placeholder_note;
    if (o.nodata) {
        std::ostringstream s;
        s << "; " << nodata_cells << " values equal to --nodata " << *o.nodata << " are no data";
        f.how += s.str();
    }
    return f;
}

}  // namespace tsf
