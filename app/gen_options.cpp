#include "app/gen_options.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "gen/model/features/class_textures.h"
#include "gen/model/features/ruler/ruler.h"
#include "gen/model/scene_scale.h"
#include "gen/util/error.h"

namespace tsf::cli {
namespace {

// Accepts "auto", "zero", "min" or a number.
void parseBaseline(const std::string& text, SceneParams& p) {
    if (text == "auto") p.baseline_mode = BaselineMode::Auto;
    else if (text == "zero") p.baseline_mode = BaselineMode::Zero;
    else if (text == "min") p.baseline_mode = BaselineMode::Min;
    else {
        size_t used = 0;
        double v = NAN;
        try { v = std::stod(text, &used); } catch (const std::exception&) { used = 0; }
        if (used != text.size() || !std::isfinite(v))
            throw InputError("--baseline: expected auto, zero, min or a number, got '" + text + "'");
        p.baseline_mode = BaselineMode::Value;
        p.baseline_value = v;
    }
}

}  // namespace

std::vector<int> parseBandSpec(const std::string& spec) {
    constexpr size_t kMaxSeries = 10000;
    auto bad = [&](const std::string& why) {
        return InputError("--band " + spec + ": " + why + " (give a band, 3; a range, 1-12; or a list, 1,4,7-9)");
    };
    auto number = [&](const std::string& t) {
        if (t.empty() || t.size() > 9 || t.find_first_not_of("0123456789") != std::string::npos) throw bad("'" + t + "' is not a band number");
        const int n = std::stoi(t);
        if (n < 1) throw bad("bands are counted from 1");
        return n;
    };
    std::vector<int> out;
    size_t at = 0;
    while (at <= spec.size()) {
        const size_t comma = std::min(spec.find(',', at), spec.size());
        const std::string part = spec.substr(at, comma - at);
        const size_t dash = part.find('-');
        if (dash == std::string::npos) {
            out.push_back(number(part));
        } else {
            const int from = number(part.substr(0, dash)), to = number(part.substr(dash + 1));
            if (to < from) throw bad("a range runs upward");
            if (size_t(to - from) + out.size() >= kMaxSeries) throw bad("more than 10000 bands");
            for (int b = from; b <= to; ++b) out.push_back(b);
        }
        if (out.size() > kMaxSeries) throw bad("more than 10000 bands");
        at = comma + 1;
    }
    return out;
}

void refuseBandSeries(const GenOptions& o, const char* command) {
    if (!o.band_series.empty())
        throw InputError(std::string("--band: a series of bands makes one model per band, which is tsf gen's; tsf ") +
                         command + " reads one band (--band N)");
}

void addGenOptions(CLI::App* cmd, GenOptions& o, bool with_input) {
    if (with_input)
        cmd->add_option("input", o.input,
                        "Field file: grid CSV, PGM (P2/P5), PNG (grey), ESRI ASCII grid (.asc), GeoTIFF or any other "
                        "raster GDAL reads, or a CSV of points with --points. Row 0 of a raster is its top (north) "
                        "edge.")
            ->required();
    auto* in = "Input";
    cmd->add_option("--points", o.points,
                    "Read the CSV as points and bin them into hexagons: x=COL,y=COL[,w=COL] "
                    "(COL = header name or 0-based index)")->group(in);
    cmd->add_option("--aggregate", o.aggregate, "Points: value of a hexagon = count | sum | mean (of w)")
        ->check(CLI::IsMember({"count", "sum", "mean"}))->capture_default_str()->group(in);
    cmd->add_option("--bin", o.bin_size, "Points: hexagon centre spacing in data units (default: from --bins)")
        ->check(CLI::PositiveNumber)->group(in);
    cmd->add_option("--bins", o.bins,
                    "Number of hexagon columns (points: hexagons across the longer side of the points' extent, so N "
                    "columns when it is wider than tall and fewer when taller, default 30; rasters: default one per "
                    "raster column, at most 1000; left out, tsf gen uses fewer where a raster it resampled to fit would "
                    "not read by fingertip: docs/tactile.md)")
        ->check(CLI::Range(1, 100000))->group(in);
    cmd->add_option_function<std::string>(
           "--band",
           [&o](const std::string& spec) {
               std::vector<int> bands = parseBandSpec(spec);
               o.band = bands.front();
               o.band_series = bands.size() > 1 ? std::move(bands) : std::vector<int>();
           },
           "Raster band to read, 1-based: a band of a multi-band GeoTIFF, a time step or level of a NetCDF variable "
           "(tsf info lists them). tsf gen: a series, 1-12 or 1,4,7, makes one model per band on one common value "
           "scale")
        ->default_str("1")->group(in);
    cmd->add_option("--variable", o.variable,
                    "Variable to read from a file that holds several (NetCDF, HDF5, GeoPackage rasters), by name: "
                    "--variable pr; GDAL's own name works as the input too: 'NETCDF:\"file.nc\":pr' (tsf info "
                    "lists them)")
        ->group(in);
    cmd->add_flag("--ignore-georef", o.ignore_georef,
                  "Rasters: ignore the file's geotransform and coordinate system and read the plain grid, one "
                  "square pixel per value, with no ground size or scale (a rotated raster is otherwise resampled "
                  "north-up; a longitude/latitude grid has its longitudes scaled)")
        ->group(in);
    cmd->add_option("--sample", o.sample,
                    "Raster -> hexagons: auto (mode for a class map with a colour table, else mean) | mean (of the "
                    "pixels in a hexagon) | mode (their most common value) | nearest | bilinear")
        ->check(CLI::IsMember({"auto", "mean", "mode", "nearest", "bilinear"}))->capture_default_str()->group(in);
    cmd->add_flag("--categorical", o.categorical,
                  "The raster's values are class codes (land cover, soil types), even without a colour table or "
                  "class names in the file: each hexagon takes its most common class, never a mean, and the "
                  "summary and the key list the classes")
        ->group(in);
    cmd->add_option("--class-order", o.class_order,
                    "A class map's classes are ordered (soil depth classes, say), lowest first: codes or the file's "
                    "names, separated by commas; each class stands one even step of height above the one before. "
                    "Without it the classes stand at one height, told apart by texture")
        ->group(in);
    cmd->add_option("--class-names", o.class_names,
                    "A class map's class names from a CSV file of code,name lines (a header line is skipped); they "
                    "replace the file's own names for those codes")
        ->check(CLI::ExistingFile)->group(in);
    cmd->add_option("--class-groups", o.class_groups,
                    "Join a class map's codes into classes a reader needs: LO-HI=NAME or CODE=NAME, separated by ; "
                    "(e.g. \"21-24=Developed;41-43=Forest\"); each group becomes one class, coded LO")
        ->group(in);
    cmd->add_option_function<int>(
           "--classes",
           [&o](int n) {
               ClassTextureRequest rq;
               rq.max_textures = n;
               o.scene.requests.set(rq);
           },
           "A class map's textures: at most N (1-5: level, ridges east-west, dimples, ridges north-south, "
           "bumps), the commonest classes one each, the rarer ones sharing the last (the summary and the key "
           "say which)")
        ->default_str(std::to_string(kTextureCount))->group(in);
    cmd->add_option("--delimiter", o.delimiter, "CSV delimiter: , ; tab space (default: detect)")->group(in);
    cmd->add_flag("--decimal-comma", o.decimal_comma,
                  "Grid CSV: read 1,5 as 1.5 (spreadsheet exports; default: detected when the delimiter is ; "
                  "tab or space)")
        ->group(in);
    cmd->add_option_function<double>(
           "--nodata", [&o](double v) { o.nodata = v; },
           "This value means 'no data' (e.g. -9999): such cells become pits, never heights. Empty cells, "
           "nan, NA, N/A and - are always no data")
        ->group(in);
    cmd->add_option("--project", o.project,
                    "Points: auto (equal-area with PROJ when the columns are named lon/lat, or with --crs: Lambert "
                    "azimuthal centred on the data, Equal Earth for the world; x, y in km), none, equal-area, "
                    "equirect (x = longitude x cos(mean latitude)), or any PROJ/EPSG definition (e.g. EPSG:3035)")
        ->capture_default_str()->group(in);
    cmd->add_option("--crs", o.crs,
                    "Points: the coordinate system of the x, y columns when they are not longitude/latitude (e.g. "
                    "EPSG:3857); they are brought to longitude/latitude, then projected as --project says")
        ->group(in);

    auto* model = "Model (millimetres)";
    SceneParams& p = o.scene;
    // The cell size and the box also decide how a raster becomes hexagons
    // (one pillar per value when it fits), so they go to the field loader too.
    cmd->add_option_function<double>(
           "--cell", [&o, &p](double v) { p.pitch_mm = v; o.cell_mm = v; },
           "Hexagon width across flats = centre spacing, mm (default: fit --width/--depth)")
        ->check(CLI::PositiveNumber)->group(model);
    cmd->add_option_function<double>(
           "--width", [&o, &p](double v) { p.fit_width_mm = v; o.fit_width_mm = v; p.fit_box_given = true; },
           "Fit the grid into this width, mm (printer bed; default 150). With --cell: the model must fit it")
        ->check(CLI::PositiveNumber)->group(model);
    cmd->add_option_function<double>(
           "--depth", [&o, &p](double v) { p.fit_depth_mm = v; o.fit_depth_mm = v; p.fit_box_given = true; },
           "Fit the grid into this depth, mm (default 150). With --cell: the model must fit it")
        ->check(CLI::PositiveNumber)->group(model);
    cmd->add_flag_callback(
           "--regular-hexagons", [&o, &p] { p.true_aspect = o.true_aspect = false; },
           "One pillar per value of a raster: regular hexagons, rows 0.866 of a cell apart, so the model is 13% "
           "shallower north-south than the ground (default: the hexagons stretched north-south so rows stand a "
           "cell apart and the model keeps the ground's proportions)")
        ->group(model);
    cmd->add_option("--height", p.max_height_mm, "Height of the largest value above the floor, mm (left out, tsf gen lowers it where a fingertip "
                    "could not read the model, never flattening a step of 0.5 mm: docs/tactile.md)")
        ->check(CLI::NonNegativeNumber)->capture_default_str()->group(model);
    cmd->add_option("--base", p.base_mm, "Flat: base under the floor; mirrored: thinnest slab, mm")
        ->check(CLI::PositiveNumber)->capture_default_str()->group(model);
    cmd->add_option_function<std::string>(
           "--transfer",
           [&p](const std::string& t) {
               p.transfer = t == "sqrt" ? Transfer::Sqrt : t == "log" ? Transfer::Log : Transfer::Linear;
           },
           "Value -> height: linear (default) | sqrt | log (log10(1+99t)/2, two decades); left out, tsf gen "
           "may choose sqrt or log where a fingertip could not read the model (docs/tactile.md)")
        ->check(CLI::IsMember({"linear", "sqrt", "log"}))->group(model);
    cmd->add_option_function<std::string>(
           "--baseline", [&p](const std::string& t) { parseBaseline(t, p); },
           "Value at height 0: auto (0, or the minimum if any value is negative) | zero | min | NUMBER")
        ->group(model);
    cmd->add_option_function<double>(
           "--value-max", [&p](double v) { p.value_max = v; }, "Value at full height (default: the largest value)")
        ->group(model);
    cmd->add_option("--snap", p.z_snap_mm,
                    "Height grid, mm; e.g. your layer height (0.2) so steps print as steps (STL and 3MF: at least "
                    "what float32 resolves at the model's height)")
        ->check(CLI::Range(1e-6, 1.0))->capture_default_str()->group(model);
    cmd->add_option_function<std::string>(
           "--cull",
           [&p](const std::string& t) { p.cull = t == "none" ? Cull::None : t == "concave" ? Cull::Concave : Cull::Hull; },
           "Which cells to model: hull (inside the convex hull of the non-empty cells, default) | concave (fewer "
           "empty cells: gaps wider than about 4 cells stay open; still one piece) | none (all)")
        ->check(CLI::IsMember({"hull", "concave", "none"}))->group(model);
    cmd->add_flag_callback(
           "--mirror", [&p] { p.bottom = Bottom::Mirrored; },
           "Mirrored bottom: the underside shows the negated data, so cells hidden between tall neighbours "
           "can be felt from below")
        ->group(model);
    cmd->add_flag("--halves", p.halves,
                  "With --mirror: write two halves cut at the slab's middle that print without supports, flat "
                  "side down, and three pins that join them one way only: -o M.stl writes M-upper.stl, "
                  "M-lower.stl, M-pins.stl (docs/printing.md)")
        ->group(model);
    cmd->add_option_function<std::string>(
           "--tilt",
           [&p](const std::string& t) {
               p.tilt = t == "points" ? TiltSource::Points : t == "gradient" ? TiltSource::Gradient : TiltSource::None;
           },
           "Tilt each pillar top, still at its height at the centre: none (default) | points (each bin's "
           "regression plane; --points input) | gradient (the field's own slope). docs/model.md")
        ->check(CLI::IsMember({"none", "points", "gradient"}))->group(model);
    cmd->add_option("--steepness", p.steepness,
                    "Multiplies every tilt's slope (tops never go below the floor or above the height range)")
        ->check(CLI::PositiveNumber)->capture_default_str()->group(model);
    cmd->add_option("--max-slope", p.max_slope_deg,
                    "Steepest a tilted top may lean, degrees from level (at most 60); steeper planes lean this much "
                    "and the summary counts them")
        ->capture_default_str()->group(model);
    // On by default on the command line (thesis 7.1.2): a reader must never take
    // a cell kept only to hold the model together for a value. The library's
    // SceneParams default stays off so a bare Scene is the plain model.
    p.structural_texture = true;
    cmd->add_flag("--texture-structural,!--no-texture-structural", p.structural_texture,
                  "Dimple the cells kept only to hold the model together (empty bins, resampled cells at the "
                  "floor), so they are not felt as data (default on; --no-texture-structural: level tops)")
        ->group(model);
    auto* marks = "Orientation marks (docs/model.md)";
    cmd->add_option_function<std::string>(
           "--marks-on",
           [&p](const std::string& v) { p.marks.place = v == "data" ? MarkPlace::Data : MarkPlace::Tab; },
           "Where the notch and the triangle stand: tab (default: on a flat tab west of the pillars, full size "
           "whatever the cells; mirrored, the triangle on both faces; cut into halves, each half its side of the tab) or "
           "data (cut into the corner pillars and raised on the largest flat region, where they fit)")
        ->check(CLI::IsMember({"tab", "data"}))->default_str("tab")->group(marks);
    cmd->add_flag_callback("--no-notch", [&p] { p.marks.notch = false; },
                           "Leave out the V notch at the origin (south-west) corner")->group(marks);
    cmd->add_flag_callback("--no-triangle", [&p] { p.marks.triangle = false; },
                           "Leave out the raised right triangle (x leg east, the longer; y leg north)")->group(marks);
    cmd->add_option("--notch-depth", p.marks.notch_depth_mm, "How far the notch reaches into the corner, mm (on the tab: along its diagonal, always in full)")
        ->check(CLI::Range(0.5, 100.0))->capture_default_str()->group(marks);
    auto* legend = "Braille legend (docs/printing.md)";
    cmd->add_option("--title", p.words.title,
                    "Title embossed in braille on a plate grown north of the pillars, with the value range")
        ->group(legend);
    cmd->add_option("--units", p.words.units, "Units of the values, after the range in the legend (e.g. airports)")
        ->group(legend);
    cmd->add_option("--braille-table", p.words.braille_table,
                    "liblouis table for the legend and the key's braille (Unified English Braille, uncontracted, by default; en-ueb-g2.ctb contracted, en-us-g1.ctb the older US code EBAE, de-g0.utb, ...)")
        ->capture_default_str()->group(legend);
    auto* scale = "Tactile scale (docs/model.md)";
    cmd->add_flag_callback("--scale", [&p] { if (!p.requests.get<ScaleRequest>()) p.requests.set(ScaleRequest{}); },
                  "A staircase east of the pillars, on the floor: each tread at the height of a round value "
                  "(every --scale-step from the baseline), to measure a pillar in value units")
        ->group(scale);
    cmd->add_option_function<double>(
           "--scale-step", [&p](double v) { p.requests.set(ScaleRequest{v}); },
           "Values between the scale's treads (implies --scale; default: the smallest 1, 2 or 5 x 10^k whose "
           "treads are at least 1 mm apart, at most 10 steps)")
        ->check(CLI::PositiveNumber)->group(scale);
    auto* ruler = "Edge ruler (docs/model.md)";
    cmd->add_option_function<std::string>(
           "--ruler",
           [&p](const std::string& v) {
               RulerRequest rq;
               if (!v.empty()) {
                   size_t used = 0;
                   int n = 0;
                   try {
                       n = std::stoi(v, &used);
                   } catch (const std::exception&) {
                       used = 0;
                   }
                   if (used != v.size() || n < 2 || n > 1000)
                       throw CLI::ValidationError("--ruler", "expected a whole number of cells from 2 to 1000, got '" + v + "'");
                   rq.every = n;
               }
               p.requests.set(rq);
           },
           "Teeth on the bed along the south and west edges, every N columns and rows (default: N so they "
           "stand at least 10 mm apart), so a reader counts them to say where a value is; the key says the "
           "column or row each marks, and its x or y where the file gives coordinates. Flat models only")
        ->expected(0, 1)->type_name("[N]")->group(ruler);
    cmd->add_option("--triangle-leg", p.marks.triangle_leg_mm, "Preferred east leg of the triangle in the data (--marks-on data), mm (north leg 0.6 of it); on the tab it is 14 mm")
        ->check(CLI::Range(5.0, 200.0))->capture_default_str()->group(marks);
}

}  // namespace tsf::cli
