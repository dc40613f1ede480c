#include "gen/field/resample.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

constexpr double kRowSpacing = kSqrt3 / 2.0;  // hex row spacing in pitches

int32_t clampIndex(double v, int32_t n) {
    if (!(v >= 0.0)) return 0;  // also NaN
    if (v >= double(n)) return n - 1;
    return int32_t(v);
}

struct PixelPoint {
    double x = 0.0;  ///< pixels, east
    double y = 0.0;  ///< pixels, down
};

PixelPoint hexCentrePx(const ResampleLayout& layout, int32_t col, int32_t row) {
    const LatticePoint c = hexCentre(layout.grid, col, row);
    return {layout.x0_px + latticeX(c, layout.pitch_px), layout.y0_px - latticeY(c, layout.pitch_px, 1.0)};
}

// Calls visit(grid index, value) for every pixel whose centre lies in a
// hexagon of the grid (pitch_px pixels across flats): the one pass over the
// raster that the mean and the mode both make.
template <class Visit>
void forEachPixelInHexagon(const Raster& raster, const ResampleLayout& layout, const HexGrid& grid, double pitch_px,
                           const Visit& visit) {
    for (int32_t pr = 0; pr < raster.rows; ++pr) {
        const double y_pitch = (layout.y0_px - (pr + 0.5)) / pitch_px;
        for (int32_t pc = 0; pc < raster.cols; ++pc) {
            const double x_pitch = (pc + 0.5 - layout.x0_px) / pitch_px;
            int32_t c = 0, r = 0;
            if (hexCellAt(grid, x_pitch, y_pitch, c, r)) visit(size_t(grid.index(c, r)), raster.at(pc, pr));
        }
    }
}

double nearestValue(const Raster& raster, PixelPoint p) {
    return raster.at(clampIndex(std::floor(p.x), raster.cols), clampIndex(std::floor(p.y), raster.rows));
}

double bilinearValue(const Raster& raster, PixelPoint p) {
    const double u = std::clamp(p.x - 0.5, 0.0, double(raster.cols - 1));
    const double v = std::clamp(p.y - 0.5, 0.0, double(raster.rows - 1));
    const int32_t c0 = int32_t(std::floor(u));
    const int32_t r0 = int32_t(std::floor(v));
    const double fu = u - c0;
    const double fv = v - r0;
    // A neighbour with zero weight is not read, so it cannot turn the result into NaN.
    const int32_t c1 = fu > 0.0 ? std::min(c0 + 1, raster.cols - 1) : c0;
    const int32_t r1 = fv > 0.0 ? std::min(r0 + 1, raster.rows - 1) : r0;
    const double z00 = raster.at(c0, r0), z10 = raster.at(c1, r0);
    const double z01 = raster.at(c0, r1), z11 = raster.at(c1, r1);
    if (std::isnan(z00) || std::isnan(z10) || std::isnan(z01) || std::isnan(z11)) return NAN;
    // Interpolation by differences: a constant neighbourhood gives the constant exactly.
    const double top = z00 + fu * (z10 - z00);
    const double bottom = z01 + fu * (z11 - z01);
    return top + fv * (bottom - top);
}

}  // namespace

ResampleLayout resampleLayout(int32_t raster_cols, int32_t raster_rows, int hex_cols) {
    if (raster_cols <= 0 || raster_rows <= 0)
        throw InputError("cannot resample an empty raster (" + std::to_string(raster_cols) + " x " +
                         std::to_string(raster_rows) + ")");
    if (hex_cols < 0 || hex_cols > kMaxResampleCols)
        throw InputError("hex columns " + std::to_string(hex_cols) + " out of range; expected 1.." +
                         std::to_string(kMaxResampleCols) + " (0 = one per raster column)");
    const int32_t cols = hex_cols > 0 ? hex_cols : std::min(raster_cols, kMaxResampleCols);
    ResampleLayout layout;
    // A single row needs no room for the shifted odd row.
    const double p_single = double(raster_cols) / cols;
    if (std::round(raster_rows / (p_single * kRowSpacing)) <= 1.0) {
        layout.pitch_px = p_single;
        layout.grid = {cols, 1};
    } else {
        layout.pitch_px = double(raster_cols) / (cols + 0.5);
        const double rows = std::max(1.0, std::round(raster_rows / (layout.pitch_px * kRowSpacing)));
        if (rows * cols > double(kMaxResampleCells))
            throw InputError("resampling " + std::to_string(raster_cols) + " x " + std::to_string(raster_rows) +
                             " pixels to " + std::to_string(cols) + " hex columns gives " +
                             formatSignificant(rows * cols, 4) + " hexagons; the most is " +
                             std::to_string(kMaxResampleCells) + " (use fewer hex columns)");
        layout.grid = {cols, int32_t(rows)};
    }
    const double width = gridWidth(layout.grid, layout.pitch_px);
    const double depth = gridDepth(layout.grid, layout.pitch_px, 1.0);
    layout.x0_px = 0.5 * (raster_cols - width);
    layout.y0_px = 0.5 * (raster_rows + depth);
    return layout;
}

namespace {

/// "the file read decimated, each value the mean of about 20 x 20 of its
/// pixels ...; then " for a decimated raster (raster.h), "" otherwise.
std::string decimatedPrefix(const Raster& raster) {
    if (raster.pixels_repeated && raster.decimation <= 1)
        return "the pixels made square on the ground (rows or columns repeated, nearest pixel); then ";
    if (raster.decimation <= 1) return "";
    return std::string("the file read decimated, each value the ") + (raster.categorical ? "most common class" : "mean") +
           " of about " + std::to_string(raster.decimation) + " x " + std::to_string(raster.decimation) +
           " of its pixels (it is larger than tsf reads whole); then ";
}

}  // namespace

HexField resampleRaster(const Raster& raster, const ResampleOptions& opts) {
    const ResampleLayout layout = resampleLayout(raster.cols, raster.rows, opts.hex_cols);
    if (raster.values.size() != size_t(raster.cols) * size_t(raster.rows))
        throw InputError(raster.source, 0, 0,
                         "the raster holds " + std::to_string(raster.values.size()) + " values, not " +
                             std::to_string(raster.cols) + " x " + std::to_string(raster.rows));
    const HexGrid& grid = layout.grid;
    const double p = layout.pitch_px;

    HexField field;
    field.grid = grid;
    field.source = raster.source;
    field.pitch_data = p * raster.cell_size;
    field.values.assign(size_t(grid.cellCount()), NAN);
    if (raster.place.known) {
        // Each hexagon stands for its centre: a column p pixels east of the
        // last, an odd row half a column further, a row p sqrt(3) / 2 pixels
        // south of the row north of it.
        const PixelPlace& px = raster.place;
        const PixelPoint first = hexCentrePx(layout, 0, 0);
        field.place = {.known = true,
                       .x0 = px.x_west + px.dx * first.x,
                       .x_per_col = px.dx * p,
                       .odd_row_shift_cols = 0.5,
                       .y0 = px.y_north - px.dy * first.y,
                       .y_per_row = -px.dy * p * kSqrt3 / 2.0,
                       .axes = px.axes};
    }

    switch (opts.method) {
        case ResampleOptions::Method::Nearest:
        case ResampleOptions::Method::Bilinear:
            for (int32_t r = 0; r < grid.rows; ++r)
                for (int32_t c = 0; c < grid.cols; ++c) {
                    const PixelPoint centre = hexCentrePx(layout, c, r);
                    field.at(c, r) = opts.method == ResampleOptions::Method::Nearest ? nearestValue(raster, centre)
                                                                                     : bilinearValue(raster, centre);
                }
            break;
        case ResampleOptions::Method::Mean: {
            std::vector<double> sum(size_t(grid.cellCount()), 0.0);
            std::vector<int64_t> finite(size_t(grid.cellCount()), 0);
            std::vector<int64_t> inside(size_t(grid.cellCount()), 0);
            forEachPixelInHexagon(raster, layout, grid, p, [&](size_t k, double v) {
                ++inside[k];
                if (std::isnan(v)) return;
                sum[k] += v;
                ++finite[k];
            });
            for (int32_t r = 0; r < grid.rows; ++r)
                for (int32_t c = 0; c < grid.cols; ++c) {
                    const size_t k = size_t(grid.index(c, r));
                    if (inside[k] == 0) field.at(c, r) = nearestValue(raster, hexCentrePx(layout, c, r));
                    else if (finite[k] > 0) field.at(c, r) = sum[k] / double(finite[k]);
                }
            break;
        }
        case ResampleOptions::Method::Mode: {
            // Per hexagon the classes seen and their counts: few per hexagon
            // in class maps, so a short list searched linearly.
            std::vector<std::vector<std::pair<double, int64_t>>> seen(size_t(grid.cellCount()));
            std::vector<uint8_t> inside(size_t(grid.cellCount()), 0);
            forEachPixelInHexagon(raster, layout, grid, p, [&](size_t k, double v) {
                inside[k] = 1;
                if (std::isnan(v)) return;
                auto& list = seen[k];
                auto it = std::find_if(list.begin(), list.end(), [v](const auto& e) { return e.first == v; });
                if (it == list.end()) list.push_back({v, 1});
                else ++it->second;
            });
            for (int32_t r = 0; r < grid.rows; ++r)
                for (int32_t c = 0; c < grid.cols; ++c) {
                    const size_t k = size_t(grid.index(c, r));
                    if (!inside[k]) {
                        field.at(c, r) = nearestValue(raster, hexCentrePx(layout, c, r));
                        continue;
                    }
                    const auto& list = seen[k];
                    if (list.empty()) continue;  // every pixel without data
                    auto best = list.front();
                    for (const auto& e : list)
                        if (e.second > best.second || (e.second == best.second && e.first < best.first)) best = e;
                    field.at(c, r) = best.first;
                }
            break;
        }
    }

    std::string what;
    switch (opts.method) {
        case ResampleOptions::Method::Mean:
            what = "mean of the pixels in each hexagon";
            field.per_hexagon = "the mean of the values that fall in it";
            break;
        case ResampleOptions::Method::Nearest:
            what = "nearest pixel to each hexagon centre";
            field.per_hexagon = "the value nearest its centre";
            break;
        case ResampleOptions::Method::Bilinear:
            what = "bilinear interpolation at each hexagon centre";
            field.per_hexagon = "the values around its centre, blended";
            break;
        case ResampleOptions::Method::Mode:
            what = "most common class of the pixels in each hexagon";
            field.per_hexagon = "the most common class of the values that fall in it";
            break;
    }
    field.how = decimatedPrefix(raster) + what + ": " + std::to_string(raster.cols) + " x " + std::to_string(raster.rows) +
                " px -> " + std::to_string(grid.cols) + " x " + std::to_string(grid.rows) + " hexagons, pitch " +
                formatSignificant(p, 4) + " px";
    return field;
}

Raster squarePixels(const Raster& raster) {
    if (std::abs(raster.row_aspect - 1.0) <= 1e-9 || raster.empty()) return raster;
    Raster out = raster;
    // The shorter side repeated: more rows when rows stand farther apart,
    // more columns when they stand closer. Each new pixel takes the pixel
    // under its centre.
    const int64_t cols = raster.row_aspect < 1 ? std::llround(double(raster.cols) / raster.row_aspect) : raster.cols;
    const int64_t rows = raster.row_aspect > 1 ? std::llround(double(raster.rows) * raster.row_aspect) : raster.rows;
    // The readers' own limit on a raster (gen/readers/raster_limits.h); a
    // file's reader squares larger ones while it reads them decimated.
    constexpr int64_t kMaxSquaredSide = 20'000, kMaxSquaredValues = 100'000'000;
    if (cols > kMaxSquaredSide || rows > kMaxSquaredSide || cols * rows > kMaxSquaredValues)
        throw InputError(raster.source, 0, 0,
                         "the raster's pixels are " + formatSignificant(raster.row_aspect, 3) +
                             " times as tall as wide on the ground; made square they would be " + std::to_string(cols) +
                             " x " + std::to_string(rows) + ", more than tsf holds (--bins N resamples it smaller)");
    out.cols = int32_t(cols);
    out.rows = int32_t(rows);
    out.values.assign(size_t(cols) * size_t(rows), NAN);
    for (int64_t r = 0; r < rows; ++r) {
        const auto sr = int32_t(std::min<int64_t>(raster.rows - 1, int64_t((double(r) + 0.5) * raster.rows / double(rows))));
        for (int64_t c = 0; c < cols; ++c) {
            const auto sc = int32_t(std::min<int64_t>(raster.cols - 1, int64_t((double(c) + 0.5) * raster.cols / double(cols))));
            out.values[size_t(r * cols + c)] = raster.at(sc, sr);
        }
    }
    if (raster.row_aspect < 1) out.cell_size = raster.cell_size * raster.row_aspect;
    out.row_aspect = 1.0;
    // The same extent in more, or fewer, pixels.
    out.place.dx = raster.place.dx * double(raster.cols) / double(cols);
    out.place.dy = raster.place.dy * double(raster.rows) / double(rows);
    out.pixels_repeated = true;
    out.facts.push_back({"resampled", std::to_string(raster.cols) + " x " + std::to_string(raster.rows) + " -> " +
                                          std::to_string(cols) + " x " + std::to_string(rows) +
                                          " square pixels (nearest) to keep the ground's aspect"});
    return out;
}

HexField rasterOneToOne(const Raster& raster) {
    if (raster.empty()) throw InputError(raster.source, 0, 0, "the raster is empty");
    HexField field;
    field.grid = {raster.cols, raster.rows};
    field.source = raster.source;
    field.values = raster.values;
    field.pitch_data = raster.cell_size;
    // A decimated file's values are already means of its pixels: one pillar
    // per value read, but not per value of the file.
    field.one_to_one = raster.decimation <= 1 && !raster.pixels_repeated;
    field.rows_a_pitch_apart = true;
    field.row_aspect = raster.row_aspect;
    field.place = pixelCells(raster.place);
    if (raster.decimation > 1)
        field.per_hexagon = raster.categorical ? "the most common class of a block of the file's values"
                                               : "the mean of a block of the file's values";
    field.how = decimatedPrefix(raster) + (raster.pixels_repeated ? "one pillar per square pixel: " : "one pillar per value: ") +
                std::to_string(raster.cols) + " x " + std::to_string(raster.rows) +
                " values -> " + std::to_string(raster.cols) + " x " + std::to_string(raster.rows) +
                " hexagons (odd rows shifted half a cell east)";
    return field;
}

HexField placeRaster(const Raster& raster, const RasterPlacement& pl) {
    if (raster.empty()) throw InputError(raster.source, 0, 0, "the raster is empty");
    const bool square = std::abs(raster.row_aspect - 1.0) <= 1e-9;
    const bool stretchable = pl.true_aspect && raster.row_aspect <= kMaxStretchedRowAspect &&
                             raster.row_aspect >= 1.0 / kMaxStretchedRowAspect;
    if (!square && (!stretchable || pl.hex_cols > 0)) return placeRaster(squarePixels(raster), pl);
    ResampleOptions rs;
    rs.method = pl.method;
    if (pl.hex_cols > 0) {
        rs.hex_cols = pl.hex_cols;
        return resampleRaster(raster, rs);
    }
    const HexGrid grid{raster.cols, raster.rows};
    if (pl.pitch_mm > 0) return rasterOneToOne(raster);
    // One pillar per value: its rows a pitch apart with true aspect (times
    // the pixels' shape on the ground).
    const double one_to_one_y_scale = pl.true_aspect ? kRowsAPitchApart * raster.row_aspect : 1.0;
    const double pitch =
        std::min(pl.fit_width_mm / gridWidth(grid, 1.0), pl.fit_depth_mm / gridDepth(grid, 1.0, one_to_one_y_scale));
    const double min_cell_mm = std::max(kMinTactileCellMm, pl.min_cell_mm);
    if (pitch >= min_cell_mm) return rasterOneToOne(raster);
    // Too many values for pillars a finger can tell apart: the most columns
    // whose cells are still min_cell_mm wide, in both directions, over
    // square pixels.
    if (!square) {
        RasterPlacement resample = pl;
        resample.true_aspect = false;  // square pixels: no stretch to keep
        return placeRaster(squarePixels(raster), resample);
    }
    int cols = std::max(1, int(std::floor(pl.fit_width_mm / min_cell_mm - 0.5)));
    cols = std::min<int>(cols, raster.cols);
    for (; cols > 1; --cols) {
        const ResampleLayout l = resampleLayout(raster.cols, raster.rows, cols);
        const double p = std::min(pl.fit_width_mm / gridWidth(l.grid, 1.0), pl.fit_depth_mm / gridDepth(l.grid, 1.0, 1.0));
        if (p >= min_cell_mm) break;
    }
    rs.hex_cols = cols;
    HexField f = resampleRaster(raster, rs);
    f.how += "; resampled because one pillar per value would be " + formatSignificant(pitch, 4) +
             " mm across, below the " + formatSignificant(min_cell_mm, 4) +
             (min_cell_mm > kMinTactileCellMm ? " mm the nozzle prints as pillars" : " mm a fingertip tells apart") +
             " (--bins N or --cell MM to choose)";
    return f;
}

const char* resampleMethodName(ResampleOptions::Method method) {
    switch (method) {
        case ResampleOptions::Method::Nearest: return "nearest";
        case ResampleOptions::Method::Bilinear: return "bilinear";
        default: return "mean";
    }
}

ResampleOptions::Method parseResampleMethod(const std::string& name) {
    if (name == "mean") return ResampleOptions::Method::Mean;
    if (name == "nearest") return ResampleOptions::Method::Nearest;
    if (name == "bilinear") return ResampleOptions::Method::Bilinear;
    if (name == "mode") return ResampleOptions::Method::Mode;
    throw InputError("unknown sampling method \"" + name + "\"; expected auto, mean, mode, nearest or bilinear");
}

}  // namespace tsf
