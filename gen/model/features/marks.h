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
// in the Scene as data: the mark geometry (Marks) and the planar faces that
// replace the plain hexagons of the cells they touch (PlanarFaces). The direct
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

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gen/field/hex_grid.h"

namespace tsf {

struct Scene;

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
/// y leg / x leg of the orientation triangle: clearly different by touch.
inline constexpr double kTriangleLegRatio = 0.6;

struct MarkParams {
    bool notch = true;              ///< cut the orientation notch
    double notch_depth_mm = 6.0;    ///< how far the V reaches into the model from its corner (mm)
    double notch_min_depth_mm = 1.5;  ///< below this the notch is left out (cannot be found by touch)
    bool triangle = true;           ///< raise the orientation triangle where a flat region fits it
    double triangle_leg_mm = 20.0;  ///< preferred east (x) leg, mm; the north leg is kTriangleLegRatio of it
    double triangle_min_leg_mm = 12.7;  ///< smallest east leg that is used (APH: 1/2 in)
    double triangle_height_mm = 1.0;    ///< how far it stands above its region (>= 0.8 mm, US signage)
};

/// MarkParams with both marks off: the plain pillars (tests of the pillar
/// rules, tools that add marks of their own).
inline MarkParams withoutMarks() {
    MarkParams m;
    m.notch = false;
    m.triangle = false;
    return m;
}

/// A point in lattice coordinates (x = i * pitch / 2, y = j * pitch / (2 sqrt 3)).
struct PlanarPoint {
    double i = 0, j = 0;
};

struct Notch {
    /// The V as a triangle, counter-clockwise: apex (inside the model) and the
    /// two ends of its mouth (outside the model), lattice coordinates.
    PlanarPoint apex, mouth_a, mouth_b;
    double depth_mm = 0;     ///< from the model's corner to the apex along the bisector
    double width_mm = 0;     ///< opening where the V meets the corner's outline, mm
    double opening_deg = 90;
};

struct OrientationTriangle {
    PlanarPoint corner;      ///< right angle (south-west corner)
    PlanarPoint east;        ///< end of the x leg
    PlanarPoint north;       ///< end of the y leg
    double leg_x_mm = 0, leg_y_mm = 0;
    int64_t raise_units = 0;  ///< height above its region, z snap units
    int32_t anchor = -1;      ///< kept index of a cell of the region it stands on
};

struct Marks {
    std::optional<Notch> notch;
    std::optional<OrientationTriangle> triangle;
};

/// What lies across one edge of a face.
struct Across {
    enum class Kind : uint8_t { Outside, Face, Cell };
    Kind kind = Kind::Outside;
    int32_t index = -1;  ///< Face: index into PlanarFaces::faces; Cell: kept index of a cell drawn as a plain hexagon
};

/// A planar face: part of the model's footprint with one z span.
struct PlanarFace {
    int32_t anchor = -1;      ///< kept cell whose span [bottom, top] the face has
    int64_t raise_units = 0;  ///< added to the top (the orientation triangle)
    /// Kept cells whose hexagons this face replaces (all have the anchor's span).
    std::vector<int32_t> cells;
    /// Boundary loops of planar vertex ids, the face on the left (outer loop
    /// counter-clockwise seen from +z, holes clockwise).
    std::vector<std::vector<int64_t>> rings;
    /// across[r][k]: what lies across the edge rings[r][k] -> rings[r][k + 1].
    std::vector<std::vector<Across>> across;
    /// The face triangulated (planar vertex ids, counter-clockwise from +z),
    /// using every ring vertex and no other point.
    std::vector<std::array<int64_t, 3>> triangles;
    /// For a cell the notch cuts: where its height is read (its centre, or the
    /// point of what is left farthest from the notch when the centre is near it).
    std::optional<PlanarPoint> read_point;
};

struct PlanarFaces {
    std::vector<PlanarPoint> extra;  ///< planar id latticeVertexIdCount(grid) + n
    std::vector<PlanarFace> faces;
    bool empty() const { return faces.empty(); }
};

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

/// Position in the model frame (mm, not snapped) of a planar point.
inline double planarX(const PlanarPoint& p, double pitch) { return p.i * pitch * 0.5; }
inline double planarY(const PlanarPoint& p, double pitch) { return p.j * pitch / (2.0 * kSqrt3); }

}  // namespace tsf
