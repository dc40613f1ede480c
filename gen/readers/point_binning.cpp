#include "gen/readers/point_binning.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

constexpr double kRowBottom = 1.0 / (2.0 * kSqrt3);  // covered band starts this far above the grid's bottom (pitches)

// Hex rows needed so that the covered band, 3R/(2 sqrt 3) - 1/(2 sqrt 3)
// pitches tall, holds `h` pitches.
double rowsFor(double h) { return std::max(1.0, std::ceil((h * 2.0 * kSqrt3 + 1.0) / 3.0)); }

}  // namespace

BinLayout binLayout(const PointTable& points, const BinOptions& opts) {
    const size_t n = points.size();
    if (n == 0) throw InputError(points.source, 0, 0, "no points to bin");
    if (points.y.size() != n || (points.hasWeight() && points.weight.size() != n))
        throw InputError(points.source, 0, 0, "the point table's columns differ in length");
    if (!std::isfinite(opts.bin_size) || opts.bin_size < 0.0)
        throw InputError("bin size must be a positive number of data units, got " + formatSignificant(opts.bin_size, 4));
    if (opts.hex_cols < 0) throw InputError("hex columns must be >= 1 (0 = default), got " + std::to_string(opts.hex_cols));

    double x_min = INFINITY, x_max = -INFINITY, y_min = INFINITY, y_max = -INFINITY;
    for (size_t k = 0; k < n; ++k) {
        const double x = points.x[k], y = points.y[k];
        if (!std::isfinite(x) || !std::isfinite(y))
            throw InputError(points.source, 0, 0, "point " + std::to_string(k + 1) + " has a non-finite coordinate");
        x_min = std::min(x_min, x);
        x_max = std::max(x_max, x);
        y_min = std::min(y_min, y);
        y_max = std::max(y_max, y);
    }
    const double width = x_max - x_min;
    const double depth = y_max - y_min;
    if (!std::isfinite(width) || !std::isfinite(depth))
        throw InputError(points.source, 0, 0, "the points' coordinates span a range too large to compute with");

    BinLayout layout;
    layout.x_min = x_min;
    layout.y_min = y_min;
    const double longer = std::max(width, depth);
    if (opts.bin_size > 0.0) {
        layout.pitch = opts.bin_size;
    } else if (longer == 0.0) {
        layout.pitch = 1.0;  // all points equal: one cell of any size
    } else {
        const int bins = opts.hex_cols > 0 ? opts.hex_cols : kDefaultPointBins;
        // Target: w + 0.5 + 2 margins == bins exactly, so ceil() gives bins.
        layout.pitch = longer / (bins - 0.5 - 4.0 * kCoverMargin);
    }
    const double p = layout.pitch;
    const double w = width / p;
    const double h = depth / p;
    if (!std::isfinite(w) || !std::isfinite(h))
        throw InputError("bin size " + formatSignificant(p, 4) + " is too small for points spanning " + formatSignificant(width, 4) +
                         " x " + formatSignificant(depth, 4));
    // Columns and rows of the covering grid at a pitch.
    const auto gridAt = [&](double pitch, double& cols_out, double& rows_out) {
        rows_out = rowsFor(depth / pitch + 2.0 * kCoverMargin);
        const double lo = rows_out > 1.0 ? 0.5 : 0.0;  // a single row has no shifted odd row
        cols_out = std::max(1.0, std::ceil(width / pitch + lo + 2.0 * kCoverMargin));
    };
    double cols = 0, rows = 0;
    gridAt(p, cols, rows);
    const double x_lo = rows > 1.0 ? 0.5 : 0.0;
    if (cols * rows > double(kMaxBinCells)) {
        // The option the user gave, and a value of it that fits.
        const auto fits = [&](double pitch) {
            double c = 0, r = 0;
            gridAt(pitch, c, r);
            return c * r <= double(kMaxBinCells);
        };
        std::string fix;
        if (opts.bin_size > 0.0) {
            double larger = p * std::sqrt(cols * rows / double(kMaxBinCells));
            while (!fits(larger)) larger *= 1.01;
            // Rounded up to 3 significant digits, so the value shown fits too.
            const double step = std::pow(10.0, std::floor(std::log10(larger)) - 2);
            fix = "give a --bin of at least " + formatSignificant(std::ceil(larger / step) * step, 3);
        } else {
            const int bins = opts.hex_cols > 0 ? opts.hex_cols : kDefaultPointBins;
            int fewer = std::max(1, int(double(bins) * std::sqrt(double(kMaxBinCells) / (cols * rows))));
            while (fewer > 1 && !fits(longer / (fewer - 0.5 - 4.0 * kCoverMargin))) --fewer;
            fix = "give --bins " + std::to_string(fewer) + " or fewer (--bins " + std::to_string(bins) + " asks for " +
                  std::to_string(bins) + " hexagons along the longer side)";
        }
        throw InputError("bin size " + formatSignificant(p, 4) + " gives " + formatSignificant(cols, 4) + " x " + formatSignificant(rows, 4) +
                         " hexagons for points spanning " + formatSignificant(width, 4) + " x " + formatSignificant(depth, 4) +
                         "; the most is " + std::to_string(kMaxBinCells) + ": " + fix);
    }
    layout.grid = {int32_t(cols), int32_t(rows)};
    // Centre the bounding box in the covered rectangle.
    layout.u_min = 0.5 * (x_lo + cols) - 0.5 * w;
    layout.v_min = 0.5 * (kRowBottom + 3.0 * rows * kRowBottom) - 0.5 * h;
    return layout;
}

HexField binPoints(const PointTable& points, const BinOptions& opts) {
    const bool weighted = opts.aggregate != BinOptions::Aggregate::Count;
    if (weighted && !points.hasWeight())
        throw InputError(points.source, 0, 0,
                         std::string("aggregate '") + aggregateName(opts.aggregate) +
                             "' needs a weight column (e.g. w=population)");
    const BinLayout layout = binLayout(points, opts);
    const HexGrid& grid = layout.grid;
    const size_t cells = size_t(grid.cellCount());
    std::vector<double> sum(cells, 0.0);
    std::vector<int64_t> count(cells, 0);
    std::vector<BinMoments> moments(cells);
    for (size_t k = 0; k < points.size(); ++k) {
        const double u = (points.x[k] - layout.x_min) / layout.pitch + layout.u_min;
        const double v = (points.y[k] - layout.y_min) / layout.pitch + layout.v_min;
        int32_t c = 0, r = 0;
        const bool inside = hexCellAt(grid, u, v, c, r);
        assert(inside && "binLayout covers every point");
        if (!inside) continue;
        const size_t cell = size_t(grid.index(c, r));
        // Offset from the cell's centre in pitches (the frame of hexCellAt).
        const LatticePoint centre = hexCentre(grid, c, r);
        const double dx = u - latticeX(centre, 1.0), dy = v - latticeY(centre, 1.0, 1.0);
        if (!weighted) {
            ++count[cell];
            moments[cell].add(dx, dy);
        } else if (std::isfinite(points.weight[k])) {
            sum[cell] += points.weight[k];
            ++count[cell];
            moments[cell].add(dx, dy, points.weight[k]);
        }
    }

    HexField field;
    field.grid = grid;
    field.source = points.source;
    field.pitch_data = layout.pitch;
    field.values.resize(cells);
    {
        // Each hexagon's centre in the points' own x and y (the inverse of
        // u, v above); load_field forgets it when the points were projected.
        const auto x = [&](int32_t c, int32_t r) {
            return layout.x_min + (latticeX(hexCentre(grid, c, r), 1.0) - layout.u_min) * layout.pitch;
        };
        const auto y = [&](int32_t r) { return layout.y_min + (latticeY(hexCentre(grid, 0, r), 1.0, 1.0) - layout.v_min) * layout.pitch; };
        field.place = {.known = true,
                       .x0 = x(0, 0),
                       .x_per_col = x(1, 0) - x(0, 0),
                       .odd_row_shift_cols = 0.5,
                       .y0 = y(0),
                       .y_per_row = y(1) - y(0),
                       .axes = {points.x_name, points.y_name, ""}};
    }
    field.moments = std::move(moments);
    field.statistic = opts.aggregate == BinOptions::Aggregate::Count  ? BinStatistic::Density
                      : opts.aggregate == BinOptions::Aggregate::Sum ? BinStatistic::WeightSum
                                                                     : BinStatistic::WeightMean;
    for (size_t k = 0; k < cells; ++k) {
        switch (opts.aggregate) {
            case BinOptions::Aggregate::Count: field.values[k] = double(count[k]); break;
            case BinOptions::Aggregate::Sum: field.values[k] = sum[k]; break;
            case BinOptions::Aggregate::Mean: field.values[k] = count[k] > 0 ? sum[k] / double(count[k]) : NAN; break;
        }
    }
    std::string what;
    switch (opts.aggregate) {
        case BinOptions::Aggregate::Count:
            what = "count of points";
            field.per_hexagon = "how many points fall in it";
            break;
        case BinOptions::Aggregate::Sum:
            what = "sum of " + points.weight_name;
            field.per_hexagon = "the sum of " + points.weight_name + " over the points that fall in it";
            break;
        case BinOptions::Aggregate::Mean:
            what = "mean of " + points.weight_name;
            field.per_hexagon = "the mean of " + points.weight_name + " over the points that fall in it";
            break;
    }
    field.how = what + " per hexagon: " + std::to_string(points.size()) + " points (" + points.x_name + ", " +
                points.y_name + ") -> " + std::to_string(grid.cols) + " x " + std::to_string(grid.rows) +
                " hexagons, pitch " + formatSignificant(layout.pitch, 4) + " data units";
    if (weighted && points.missing_weights > 0)
        field.how += ", " + std::to_string(points.missing_weights) + " missing weights skipped";
    return field;
}

const char* aggregateName(BinOptions::Aggregate aggregate) {
    switch (aggregate) {
        case BinOptions::Aggregate::Sum: return "sum";
        case BinOptions::Aggregate::Mean: return "mean";
        default: return "count";
    }
}

BinOptions::Aggregate parseAggregate(const std::string& name) {
    if (name == "count") return BinOptions::Aggregate::Count;
    if (name == "sum") return BinOptions::Aggregate::Sum;
    if (name == "mean") return BinOptions::Aggregate::Mean;
    throw InputError("unknown aggregate \"" + name + "\"; expected count, sum or mean");
}

}  // namespace tsf
