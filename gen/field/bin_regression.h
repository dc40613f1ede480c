// The points of one hexagonal bin as sums (moments), and the regression
// plane they give for tilting the bin's pillar top (docs/model.md, "Tilt").
//
// Frame: offsets (dx, dy) of each point from its cell's centre, in pitches
// (one pitch = the centre spacing), x east, y north.
//
// Two statistics, chosen by what the bin's value is:
//   - Density (count of points): the least-squares linear density on the
//     hexagon, f(q) = a + g . q minimising the integral of f^2 over the
//     hexagon minus 2 sum f(q_i) (the L2 projection of the points onto the
//     planes). For a regular hexagon of side s, a = n / A and
//     g = sum q_i / J with J = 5 sqrt(3) s^4 / 16 (second moment about an
//     axis through the centre), so the relative slope g / a = (A / J) q_mean
//     = 14.4 q_mean per pitch (s = 1 / sqrt 3 pitches). The top leans up
//     towards where the bin's points crowd.
//   - Weight (sum or mean of a weight column): ordinary least squares of the
//     weight w on the position, w = a + b dx + c dy, every point weighted
//     equally; (b, c) is in weight units per pitch.
// A bin with fewer than kMinRegressionPoints points, or whose points lie on
// one line (the position covariance is singular: det <= kCollinearRelDet *
// trace^2), has no plane: its top stays flat.
#pragma once

#include <cstdint>
#include <optional>

namespace tsf {

/// Fewest points that define a plane.
inline constexpr int64_t kMinRegressionPoints = 3;
/// Points whose position covariance has det <= this * trace^2 count as on one
/// line: far below any spread a real bin has (1e-9 of the trace squared is a
/// spread across the line of about 3e-5 of the spread along it), far above
/// the rounding of the sums.
inline constexpr double kCollinearRelDet = 1e-9;
/// Relative slope of the least-squares linear density per pitch of mean
/// offset: A / J for a regular hexagon with side 1 / sqrt(3) pitches.
inline constexpr double kDensitySlopePerPitch = 14.4;

/// What the bin's value is, and so which plane its tilt follows.
enum class BinStatistic : uint8_t {
    Density,    ///< count of points
    WeightMean, ///< mean of a weight column
    WeightSum,  ///< sum of a weight column (n times the mean)
};

/// Sums over the points of one bin (offsets in pitches from the cell centre).
struct BinMoments {
    int64_t n = 0;
    double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
    double sw = 0, sxw = 0, syw = 0;  ///< weight sums (0 for a count)

    void add(double dx, double dy, double w = 0.0) {
        ++n;
        sx += dx;
        sy += dy;
        sxx += dx * dx;
        sxy += dx * dy;
        syy += dy * dy;
        sw += w;
        sxw += dx * w;
        syw += dy * w;
    }
};

/// A slope (dz/dx, dz/dy) in the unit the function names.
struct PlaneSlope {
    double x = 0, y = 0;
};

/// True when the bin has at least kMinRegressionPoints points not all on one line.
bool hasRegressionPlane(const BinMoments& m);

/// Density: relative slope of the least-squares linear density, per pitch
/// (multiply by the top's height and divide by the pitch in mm for mm/mm).
/// nullopt when the bin has no plane.
std::optional<PlaneSlope> densityRelativeSlope(const BinMoments& m);

/// Weight: slope of the least-squares plane of w on position, weight units
/// per pitch. nullopt when the bin has no plane.
std::optional<PlaneSlope> weightSlope(const BinMoments& m);

}  // namespace tsf
