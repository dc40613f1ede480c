// Orientation marks: the notch and the handedness triangle (thesis 3.5, 5.1.2, 7.1.4).
//
// A reader who cannot see the model must find where it starts and which way
// x and y run:
//   - the NOTCH is a V cut through the whole height of the model at its
//     origin corner (south-west: x = 0, y = 0 in the model frame), so it is
//     felt from the side, from above and, when mirrored, from below;
//   - the TRIANGLE is a right triangle raised on the largest flat region of
//     the top (the connected equal-height cells with the largest inscribed
//     circle). Its right angle is its south-west corner; one leg runs east
//     (+x), the other north (+y), and the east leg is clearly the longer
//     (kTriangleLegRatio), so the reader can tell x from y and the model's
//     handedness, which the notch alone cannot say.
// Sizes, and where they come from, are in docs/model.md ("Orientation marks").
//
// Both marks are decided once by placeMarks (called by buildScene) and stored
// in the Scene as data (gen/model/scene_marks.h): the mark geometry (Marks)
// and the planar faces that replace the plain hexagons of the cells they
// touch (PlanarFaces). The direct
// mesher, the OpenSCAD emitter and the verifier all read these faces; none of
// them re-derives a mark.
//
// Planar vertices. Every face corner is a "planar vertex" with an id: ids
// below latticeVertexIdCount(grid) are hex corners (hex_grid.h, exact integer
// lattice coordinates); larger ids index PlanarFaces::extra, points in
// lattice coordinates that need not be integers (mark corners and where a
// mark's edge crosses a hex edge). Each such point is computed ONCE, so a
// crossing shared by two cells is one vertex of both; positions in mm are
// then rounded to the 1 um grid exactly like lattice points.
//
// Guarantees (checked when marks are placed; a mark that cannot meet them is
// left out with a note): the notch removes no pillar: each pillar it cuts
// keeps at least half its hexagon and a point kMarkClearanceMm from the cut
// where its height is read (readPoint); every corner of the notch's
// faces is at least kMarkClearanceMm from every hex corner and hex edge it
// does not lie on, so no face is a sliver; the triangle keeps
// kTriangleMarginMm from its region's edge and kReadPointClearanceMm from
// every pillar centre.
#pragma once

#include <cstdint>
#include <string>

#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// Shortest distance (mm) between a notch corner or crossing and any hex
/// corner or edge it does not lie on, and between the notch and a cell centre:
/// two 0.4 mm nozzle widths, so the cut leaves no sliver of pillar too thin to
/// print (the verifier's wall-thickness check stays quiet).
inline constexpr double kMarkClearanceMm = 0.8;
/// Shortest distance (mm) from a pillar centre to the triangle's edge: the
/// pillar's height is read there, on one side of the edge or the other.
inline constexpr double kReadPointClearanceMm = 0.2;
/// Shortest distance (mm) from the triangle to the edge of its flat region.
inline constexpr double kTriangleMarginMm = 1.0;

/// Whether the marks go on a body beside the pillars (MarkPlace::Tab, a
/// mark asked for) rather than in the data: that body (the orientation
/// tab, a feature of the registry placed in FeaturePhase::Marks) carries
/// them, and placeMarks places none.
bool marksOnTab(const SceneParams& params);

/// Places the marks params.marks asks for on a Scene whose cells, spans and
/// kinds are set, and builds the faces they need (scene.marks, scene.faces,
/// scene.drawn_by_face). Adds a note for a mark that does not fit.
void placeMarks(Scene& scene);

/// Builds scene.faces and scene.drawn_by_face from scene.marks (used by
/// placeMarks and when a Scene is read back from its sidecar). Throws
/// InputError if the marks do not fit the Scene's cells.
void buildMarkFaces(Scene& scene);

/// Where the height of kept cell `kept` is read (lattice coordinates): its
/// centre, or for a pillar the notch cuts near its centre, the point of what
/// is left farthest from the notch.
PlanarPoint readPoint(const Scene& scene, size_t kept);

/// How many z snap units a mark raises the top of kept cell `kept` at its
/// centre (the orientation triangle), 0 where no mark stands.
int64_t markRaiseAtCentre(const Scene& scene, size_t kept);

/// The read-back of the marks in the data (on a tab, the tab's feature
/// reads them back in a set of the same name): the triangle at its centroid and a fifth of the way in from each
/// corner (its region's top + its raise), and inside the notch's V a
/// quarter of the way from its apex to its mouth (empty: the notch cuts the
/// whole height). Empty without marks.
ProbeSet markProbes(const Scene& scene);

/// The title of the marks' read-back set ("marks"), in the data or on a tab.
inline constexpr const char* kMarkProbesTitle = "the orientation triangle at its height and the notch cut through";

}  // namespace tsf
