// The tactile scale: a staircase beside the pillars whose treads stand at the
// printed heights of round values, so a reader can measure a pillar in value
// units by finding the step level with its top (thesis 7.1.1: a reader can
// compare heights but cannot read a value; the base under the floor is
// accounted for because the staircase stands on a foot whose top IS the
// floor, the height of the baseline value).
//
// Levels. With a step d (data units), the levels are the multiples k d above
// the baseline and up to value_max; each level's height is the pillars' own:
// floor + snapUnits(ValueMapping::heightMm(k d)), so a pillar of value k d and
// the step for k d have equal tops, to the bit. A level whose height is less
// than kScaleMinRiserMm above the floor is left out (only the first can be);
// every later level must rise at least kScaleMinRiserMm above the one before.
// The step is chosen (chooseScaleStep) as the smallest "nice" number (1, 2 or
// 5 x 10^k) whose levels satisfy that with at most kScaleMaxAutoSteps steps;
// `--scale-step` gives it, and is refused when its levels do not satisfy it.
//
// Shape (frame of scene.h, mm). The scale stands against the model's east
// side: the foot is the box [x0, x1] x [y0, y1] x [0, floor], its west face
// x0 the easternmost hexagon edge of the kept cells (lattice i = x0_i). The
// steps are boxes [xs, x1] x [step.y_south, step.y_north] x [0, step.top]
// in a row from y0 northwards, lowest first; between the pillars and the
// steps the foot's top (the floor) is a strip kScaleGapMm wide. The foot
// touches the model exactly along the east walls of `contacts` (kept cells
// whose east edge lies on x0, between y0 and y1), from z = 0 to the floor:
// between two contacts the foot also fills the notch of the hexagon outline
// (see SceneScale::fillers; -1 there between two contacts further apart,
// where the foot's west face stands free of the shorter rows between them,
// and closes a ring around any culled cells there: a hole down to the bed);
// every vertex of the contact is a lattice corner
// at height 0 or the floor,
// shared with the pillars' mesh, so the joined model needs no boolean
// operation (gen/mesh/direct_mesher.cpp) and the scale alone is a closed body of
// its own (meshScaleBody). y0 and y1 lie on lattice rows between contacts.
//
// Limits (InputError, exit 2, saying what to change): a mirrored model (no
// floor to stand on), a field without a range, a --scale-step whose levels
// are too close or too many, or no run along the east side clear of the
// braille legend (any footprint claimed before it) and of cells without data.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/feature.h"
#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"
#include "gen/model/scene_scale.h"

namespace tsf {

/// Smallest height difference between neighbouring levels, mm: above the
/// 1/32 in (0.8 mm) US sign rules ask raised characters to stand above their
/// background, so each step's edge is felt as an edge (docs/model.md).
inline constexpr double kScaleMinRiserMm = 1.0;
/// At most this many steps when tsf chooses the step: a reader counts them.
inline constexpr int kScaleMaxAutoSteps = 10;
/// At most this many steps for a --scale-step.
inline constexpr int kScaleMaxSteps = 40;
/// Length of a tread along y, mm: APH's 1/4 in (6.4 mm) below which two
/// symbols may not be told apart.
inline constexpr double kScaleTreadMm = 6.4;
/// Width of the steps across x, mm: APH's 1/2 in (12.7 mm) smallest
/// recognisable shape side.
inline constexpr double kScaleStepWidthMm = 12.7;
/// Floor strip between the pillars and the steps, mm.
inline constexpr double kScaleGapMm = 4.0;
/// Clear space kept from what other features claim (the braille legend's
/// plate, gen/model/feature.h: FootprintClaim), mm.
inline constexpr double kScaleClearanceMm = 2.0;
/// How far west of the easternmost hexagon edge the foot may stand, in
/// cells, on an outline whose east side offers no clear run there.
inline constexpr int64_t kScaleMaxSetbackCells = 8;

/// One level of the scale.
struct ScaleLevel {
    double value = 0;           ///< data units (a multiple of the step)
    int64_t height_units = 0;   ///< above the floor, z snap units (the pillars' snapped height)
};

/// The levels of step `step` (> 0) for `mapping` on a z grid of z_snap_mm,
/// as described above. Sets *error to why they do not make a scale (levels
/// too close, none, too many) and returns them anyway.
std::vector<ScaleLevel> scaleLevels(const ValueMapping& mapping, double step, double z_snap_mm, int max_steps,
                                    std::string* error);

/// The smallest 1/2/5 x 10^k step whose levels make a scale of at most
/// kScaleMaxAutoSteps steps; none when no step does (a range too low to
/// rise kScaleMinRiserMm).
std::optional<double> chooseScaleStep(const ValueMapping& mapping, double z_snap_mm);


/// The scale's piece of a generated OpenSCAD file (scale_scad.cpp): the
/// staircase as data for scad_lib/tsf_scale.scad; none without a scale.
std::optional<ScadPiece> scaleScadPiece(const Scene& scene);

/// Places the scale params.scale asks for (none when it asks for nothing),
/// clear of every footprint claimed before it (gen/model/feature.h).
/// Called by buildScene through the registry (FeaturePhase::Beside), after
/// the marks, the legend, the tab and the top shapes.
void placeScale(Scene& scene);

/// The scale the Scene carries (its state in Scene::features); null without one.
const SceneScale* sceneScale(const Scene& scene);


/// z (units) of the scale's top at (x, y) mm, or none outside its footprint
/// (or without a scale).
std::optional<int64_t> scaleTopAt(const Scene& scene, double x_mm, double y_mm);

/// The scale as a closed solid. `joined`: without the foot's west wall where
/// it touches the model (the part of a joined mesh). lattice_id[v] is the
/// lattice vertex id (hex_grid.h) a vertex stands on, -1 for the scale's own.
JoinedBody meshScaleBody(const Scene& scene, bool joined);

/// The scale's x, y box (mm): its foot and steps; none without a scale.
std::optional<BoxMm> scaleBoxMm(const Scene& scene);

/// The scale as an attachment (gen/model/scene_attachments.h), part "scale":
/// its foot covers, from z = 0 to the floor, each contact's east edge (0),
/// its north-east edge (1) below a filled notch and its south-east edge (5)
/// above one, and each filler's east edge (0). None without a scale.
std::optional<Attachment> scaleAttachment(const Scene& scene, Assembly assembly);

/// Checks the scale as placeScale leaves it (what the mesher relies on to
/// join it without a boolean operation): steps above one another from y0
/// to y1, contacts and fillers kept cells that rise to the floor. Throws
/// InputError ("scene: scale: ..."); nothing without a scale.
void checkScale(const Scene& scene);

/// The scale's read-back: the foot's floor strip and the middle of every
/// tread. Empty without a scale.
ProbeSet scaleProbes(const Scene& scene);

}  // namespace tsf
