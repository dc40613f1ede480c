// The orientation tab: a place for the orientation marks that is not data.
//
// Dense rasters leave no flat region for the handedness triangle and no
// corner pillar wide enough for a deep notch (thesis 3.5 places both in the
// data; 7.1.4 admits they do not always fit). The tab is a flat plate west
// of the pillars, from z = 0 to the floor, that carries both marks at full
// size whatever the cells:
//   - the NOTCH: a V cut into the tab's south-west corner, which is the
//     model's south-west corner (the tab reaches as far south as the lowest
//     pillar, and nothing lies west of it); its apex lies notch_depth_mm
//     (6 mm by default) from that corner along the diagonal, its sides open
//     kTabNotchOpeningDeg;
//   - the TRIANGLE: a right triangle raised triangle_height_mm on the tab's
//     top, right angle south-west, east leg kTabTriangleLegMm (the longer),
//     north leg kTriangleLegRatio of it.
// The tab never covers, lowers or reshapes a data cell: it stands against
// the westernmost hexagon walls of pillars that rise to the floor at every
// corner (their "contacts"), from 0 to the floor, exactly as the tactile
// scale's foot stands against the east walls (gen/model/features/scale.h),
// and fills the notch of the hexagon outline between two contacts one row
// apart. On a flat model whose west side is not a straight line, where that
// joint would not hold a hand's push (gen/geometry/joint_stress.h), the tab
// follows the outline instead: from a southernmost pillar's bottom tip
// north along every wall it meets. Every vertex where it meets the pillars is a lattice corner at
// height 0 or the floor, so the joined model needs no boolean operation.
//
// On a mirrored model (every pillar the same thickness, the underside the
// negated data) the tab lies in the z band that every pillar it stands
// against holds, as thick as the base (at least kTabMinThicknessMm, at most
// the band; thicker where its one-pillar joint would not hold a hand's
// push) in the band's middle, and carries the triangle on both
// faces at the same place: a reader who turns the model over finds the
// underside's triangle with its long leg running the other way, mirrored
// exactly as the data is, which tells the two sides apart. There the tab
// stands against one pillar: the outline's notch between two would be a slot
// open above and below it, which the tab would ring (a handle).
//
// Cut into halves (gen/model/features/halves.h), the tab lies across the
// cut, as thick as the base on each side of it (the slab the model is cut
// at keeps that room whatever the marks: the feature's
// room_across_cut_units): each half keeps its side, standing on the cut
// face, with the marks on its face away from the cut (its cut_into_half,
// which halfScene calls), and the two together make one tab.
//
// A feature of the registry (tab_feature.h), placed in FeaturePhase::Marks
// (after the top shapes and the legend) by placeTab when the marks go on a
// tab (marksOnTab, gen/model/features/marks.h). When the west side has no
// run of contacts clear of pits, tilted corners below the floor and the
// legend's plate, placeTab notes why and buildScene places the marks in the
// data where they fit. Its state (OrientationTab, tab_state.h) is kept in
// Scene::features; the marks' facts and key, the halves and the tiles ask
// for it through the contract (tab_feature.h: the marks it carries, its
// room across the cut and its side of it, the tile that carries it).
#pragma once

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/feature.h"
#include "gen/model/features/tab/tab_state.h"
#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// Opening of the notch's V, degrees: narrower than the thesis' 90 degrees,
/// which at a square corner would cut a step, not a V a fingertip follows.
inline constexpr double kTabNotchOpeningDeg = 60.0;
/// East leg of the triangle on the tab, mm: above APH's 1/2 in (12.7 mm)
/// smallest recognisable shape side, with room for rounding and measuring.
inline constexpr double kTabTriangleLegMm = 14.0;
/// Clear space between the triangle and the tab's east and north edges, mm
/// (the pillars rise right behind the east edge).
inline constexpr double kTabMarginMm = 3.0;
/// How far the tab's east edge stands back west of the pillars beyond the
/// cells it stands against, mm: more than two nozzle widths, so no slot
/// beside a pillar is too narrow to print.
inline constexpr double kTabSetbackMm = 1.0;
/// Clear space between the notch's apex and the triangle, mm.
inline constexpr double kTabNotchClearanceMm = 1.75;
/// Thinnest tab on a mirrored model, mm (eight 0.2 mm layers); a mirrored
/// model's pillars thinner than this give the tab their thickness.
inline constexpr double kTabMinThicknessMm = 1.6;
/// Clear space kept from the braille legend's plate, mm.
inline constexpr double kTabLegendClearanceMm = 2.0;

/// The tab's width (x, mm) for these marks: what it adds to the model's
/// width west of the pillars, whatever the cell.
double tabWidthMm(const MarkParams& marks);

/// Places the orientation tab when the Scene asks for it (see above); when it
/// finds no place, leaves the Scene without one (sceneTab: null) with a note
/// saying why.
void placeTab(Scene& scene);

/// z (units) of the tab's top at (x, y) mm (the floor, or the triangle's
/// top), none outside its outline.
std::optional<int64_t> tabTopAt(const Scene& scene, double x_mm, double y_mm);

/// The area of the tab's outline, mm^2 (the footprint it adds to the model).
double tabAreaMm2(const OrientationTab& tab);

/// The tab as a closed solid. `joined`: without its walls against the
/// pillars (the part of a joined mesh). lattice_id[v] is the lattice vertex
/// id a vertex stands on (a contact's corner), -1 for the tab's own.
JoinedBody meshTabBody(const Scene& scene, bool joined);

/// The tab's x, y box (mm); none without a tab.
std::optional<BoxMm> tabBoxMm(const Scene& scene);
/// The footprint the tab claims (gen/model/feature.h): features placed after
/// it keep clear of its box.
std::optional<FootprintClaim> tabClaim(const Scene& scene);

/// The tab as an attachment (gen/model/scene_attachments.h), part "marks":
/// it covers its touched walls over its z span. None without a tab.
std::optional<Attachment> tabAttachment(const Scene& scene, Assembly assembly);

/// The tab's places to read back: its top near its north-west corner, the
/// triangle's middle and a point near each corner (the tab's top + the
/// raise), and along the notch's diagonal a point 0.3 mm short of the apex
/// (empty: the V reaches its full depth) and one 0.3 mm beyond it (the tab's
/// top: no deeper). Empty without a tab.
std::vector<SurfaceProbe> tabProbes(const Scene& scene);

/// Checks the Scene's tab (none: nothing): checkTab, and every wall it
/// covers holds its whole z band. Throws InputError ("scene: orientation
/// tab: ...").
void checkTabInScene(const Scene& scene);

/// The tab's piece of a generated OpenSCAD file (tab_scad.cpp): the
/// "Orientation marks" switch show_orientation_tab and its body as data for
/// scad_lib/tsf_tab.scad, with its own assert; none without a tab.
std::optional<ScadPiece> tabScadPiece(const Scene& scene);

/// Checks a tab read from a file against the Scene: outline, joined edges,
/// touched cells and their lattice corners agree. Throws InputError saying what does not.
void checkTab(const Scene& scene, const OrientationTab& tab);

}  // namespace tsf
