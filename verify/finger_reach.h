// Where a fingertip cannot reach the surface it should read: the measure
// behind tactile_finger_reach (verify/tactile.h), on its own so that the
// verifier, tsf gen's self-check and gen's choice of defaults run the same
// code at the same sampling.
//
// The top surface is sampled from above on a grid anchored at whole
// multiples of the step in the model frame (so the same mesh, in double or
// read back from float32, gives the same samples). A ball of the fingertip's
// radius is lowered over it: the surface closed by the ball (the lowest each
// ball centre can go, then the lowest the balls reach over each sample). A
// sample is deep when the ball stops more than kUnreachedDepthMm above it.
// A deep sample is read all the same when the surface continues from it,
// never climbing more than kUnreachedDepthMm above it, to a sample the ball
// reaches (the foot of a wall, read a little further out); the others are
// unreached, and each connected group of them is one place.
//
// Monotone where physics says so: a smaller ball fits wherever a larger one
// touched (inside it, tangent at the same point), so the smaller finger's
// reach is capped by the larger one's (the sampled discs could miss that by
// rounding); with it, a smaller fingertip leaves every sample at most as deep
// and no sample unreached that a larger one reads, so its unreached area and
// its deepest place are never larger. Raising the surface beside a place never
// makes it shallower.
//
// Units: millimetres, model frame (x east, y north, z up).
#pragma once

#include <cstdint>
#include <vector>

#include "gen/geometry/mesh.h"
#include "verify/height_field.h"
#include "verify/report.h"

namespace tsf {

/// Depth (mm) below where a rigid fingertip stops that a pressing finger
/// still reaches (tactile_finger_reach's threshold; its source is in
/// tactileThresholds()).
inline constexpr double kUnreachedDepthMm = 2.0;

/// What one fingertip leaves unreached.
struct FingerReach {
    double radius_mm = 0;
    int64_t places = 0;     ///< connected groups of unreached samples
    double deepest_mm = 0;  ///< the deepest unreached sample's depth below the ball
    double area_mm2 = 0;    ///< all unreached samples together
    double no_value_area_mm2 = 0;  ///< unreached samples with no value to read (not places)
    /// Every place, deepest first: its deepest sample (at_mm), that depth
    /// (amount, mm) and its area in the detail.
    std::vector<Offender> worst;
};

/// The sampled top and what each fingertip leaves unreached.
struct FingerReachResult {
    double step_mm = 0;              ///< the top's sample spacing
    std::vector<FingerReach> fingers;  ///< in the order of the radii asked for
};

/// The surface `top` closed by a ball of radius `r_mm` lowered onto it from
/// above: over each sample, the lowest point of the balls whose centres
/// stand as low as the surface lets them (a sample's height when the ball
/// fits into it, higher where it does not). Samples with nothing over them
/// are the table at `table_mm`, and the table goes on beyond the samples.
/// One entry per sample, row by row, as top.z.
std::vector<double> closedByBall(const TopHeightField& top, double r_mm, double table_mm);

/// The top of `mesh` sampled every `sample_mm` (coarser above a million
/// samples), anchored at whole steps, with a margin of `margin_mm` around
/// the mesh's bounds for the fingertip to come down beside it.
TopHeightField sampledTop(const Mesh& mesh, double sample_mm, double margin_mm);

/// The fingertips' reach over `top`, each radius (mm, largest first) capped
/// by the one before it. `table_mm`: the height of the table around the
/// model (samples with nothing over them). `no_value` (empty, or one entry
/// per sample): samples with no value to read (the pit of a cell without
/// data: a hole is what it says), never a place, their unreached area
/// counted apart.
FingerReachResult fingerReach(const TopHeightField& top, double table_mm, const std::vector<double>& radii_mm,
                              const std::vector<uint8_t>& no_value = {});

/// The mesh's top sampled (sampledTop, margin the largest radius), then fingerReach.
FingerReachResult fingerReach(const Mesh& mesh, double sample_mm, const std::vector<double>& radii_mm);

}  // namespace tsf
