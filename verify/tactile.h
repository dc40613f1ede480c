// The model as a hand reads it: checks against tactile-graphics numbers.
//
// The solid checks prove a mesh is a printable solid; these ask whether a
// fingertip can read it (tsf verify --tactile, docs/tactile.md):
//   - tactile_sharp_points: a vertex of the touched surface whose material
//     fills less solid angle than a cone of kSharpPointHalfAngleDeg (a
//     needle, the spike of an over-tilted top);
//   - tactile_knife_edges: a convex edge of the touched surface whose two
//     faces meet at less than kKnifeEdgeDeg (a blade);
//   - tactile_finger_reach: places a fingertip cannot reach the bottom of: a
//     ball of the fingertip's radius lowered over the top surface stops more
//     than kUnreachedDepthMm above it (narrow pits, empty bins between tall
//     pillars), for an adult's fingertip (a failure) and a child's (stated);
//   - tactile_marks (with a Scene): the orientation marks are there and of a
//     size a fingertip recognises (notch depth, triangle legs);
//   - tactile_slender_pillars (with a Scene): a pillar standing free above
//     its neighbours far enough for a hand's push at its top to break it;
//   - tactile_height_steps (with a Scene, a warning): neighbouring pillars
//     whose heights differ by less than one printed layer (they print the
//     same, or a layer apart by rounding);
//   - tactile_braille (with a Scene that has a legend): the dots as they will
//     print, their height rounded to whole layers and their base against the
//     nozzle, inside the braille standards' range.
// The thresholds live in kTactileThresholds, each with its source; the
// report says which a model misses and by how much.
//
// Units: millimetres and degrees, model frame (x east, y north, z up). The
// touched surface is every face not lying on the bed (the lowest z).
#pragma once

#include <cstddef>
#include <vector>

#include "gen/geometry/joint_stress.h"
#include "gen/geometry/mesh.h"
#include "verify/finger_reach.h"
#include "verify/report.h"

namespace tsf {

struct Scene;

/// One threshold of the tactile checks and where its number comes from.
struct TactileThreshold {
    const char* id;      ///< the check it belongs to
    const char* what;    ///< what it bounds
    double value;
    const char* unit;
    const char* source;  ///< the publication or the reasoning behind the number
};

/// Narrowest cone (half-angle, degrees) a point of the touched surface may be.
inline constexpr double kSharpPointHalfAngleDeg = 20.0;
/// Smallest angle (degrees) two faces may meet at along a convex edge.
inline constexpr double kKnifeEdgeDeg = 30.0;
/// Fingertip radii (mm): half the width of an adult's and a young child's index fingertip.
inline constexpr double kAdultFingertipRadiusMm = 8.0;
inline constexpr double kChildFingertipRadiusMm = 5.5;
/// Smallest orientation marks (mm): the notch's depth and the triangle's shorter leg.
inline constexpr double kMinNotchDepthMm = 3.2;
inline constexpr double kMinTriangleLegMm = 6.35;
inline constexpr double kMinTriangleLongLegMm = 12.7;
/// Spacing (mm) under which two neighbouring features merge under a
/// fingertip (1/8 in): the notch is at least this deep, cells are not advised smaller.
inline constexpr double kMergeSpacingMm = 3.2;
/// Lowest printed braille dot, mm: NLS Specification 800's dot height (paper
/// braille; lower dots are read poorly). The highest is kMaxBrailleDotHeightMm
/// (gen/model/features/legend/legend.h).
inline constexpr double kMinPrintedDotHeightMm = 0.48;
/// Narrowest dot base, in nozzle widths: two perimeters make a dome.
inline constexpr double kMinDotBaseNozzles = 2.0;
// kHandPushN and kPrintedPlaInterlayerMpa: gen/geometry/joint_stress.h.

/// Every threshold above with its source (docs/tactile.md prints the same table).
const std::vector<TactileThreshold>& tactileThresholds();

struct TactileOptions {
    size_t max_offenders = 10;
    double sample_mm = 0.5;  ///< spacing of the top surface's height samples (coarsened on very large models)
    double layer_mm = 0.2;   ///< the printer's layer: braille dots print a whole number of layers high
    double nozzle_mm = 0.4;  ///< the printer's nozzle: a dot narrower than two widths prints as a blob
};

struct TactileResult {
    std::vector<Check> checks;
    std::vector<Stage> stages;
};

/// Runs the tactile checks on `mesh` (closed or not: a check that needs a
/// closed, oriented mesh says so and is skipped). `scene` (nullable) adds
/// the marks check.
TactileResult checkTactile(const Mesh& mesh, const Scene* scene, const TactileOptions& options);

/// Only the two checks a model's height, transfer or cell size can fix,
/// tactile_finger_reach and tactile_slender_pillars, by the same code on the
/// same samples as checkTactile and in its order: what a search over
/// settings asks of each model it tries (the sharp points, marks and braille
/// a setting does not change are not measured again).
TactileResult checkLegibility(const Mesh& mesh, const Scene& scene, const TactileOptions& options);

/// tactile_slender_pillars alone, as checkTactile gives it: read from the
/// Scene's pillars, so a model it fails needs no mesh to be known to fail.
Check checkSlenderPillars(const Scene& scene, const TactileOptions& options);

}  // namespace tsf
