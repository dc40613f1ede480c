// The orientation marks and the planar faces as the Scene holds them: data
// only. Where they come from is gen/model/features/marks.h (placeMarks);
// every mesher, the OpenSCAD emitter and the verifier read them.
//
// Planar vertices. Every face corner is a "planar vertex" with an id: ids
// below latticeVertexIdCount(grid) are hex corners (hex_grid.h, exact integer
// lattice coordinates); larger ids index PlanarFaces::extra, points in
// lattice coordinates that need not be integers (mark corners and where a
// mark's edge crosses a hex edge).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gen/field/hex_grid.h"

namespace tsf {

/// Where the orientation marks stand.
enum class MarkPlace : uint8_t {
    Tab,   ///< on the orientation tab west of the pillars (default; gen/model/features/tab/orientation_tab.h)
    Data,  ///< in the data: the notch cut into the corner pillars, the triangle on the largest flat region
};

struct MarkParams {
    /// Tab: both marks on the tab, at full size whatever the cells (mirrored:
    /// the triangle on both faces; halves: each half its side of the tab).
    MarkPlace place = MarkPlace::Tab;
    bool notch = true;              ///< cut the orientation notch
    double notch_depth_mm = 6.0;    ///< how far the V reaches into the model from its corner (mm)
    double notch_min_depth_mm = 1.5;  ///< below this the notch is left out (cannot be found by touch)
    bool triangle = true;           ///< raise the orientation triangle where a flat region fits it
    double triangle_leg_mm = 20.0;  ///< preferred east (x) leg, mm; the north leg is kTriangleLegRatio of it
    double triangle_min_leg_mm = 12.7;  ///< smallest east leg that is used (APH: 1/2 in)
    double triangle_height_mm = 1.0;    ///< how far it stands above its region (>= 0.8 mm, US signage)
};

/// y leg / x leg of the orientation triangle: clearly different by touch.
inline constexpr double kTriangleLegRatio = 0.6;

/// MarkParams with both marks off: the plain pillars (tests of the pillar
/// rules, tools that add marks of their own).
inline MarkParams withoutMarks() {
    MarkParams m;
    m.notch = false;
    m.triangle = false;
    return m;
}

/// A point in lattice coordinates (x = i * pitch / 2, y = j * pitch / (2 sqrt 3) * y_scale).
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

/// The marks in the data (with MarkPlace::Tab, the orientation tab carries
/// both and these are none).
struct Marks {
    std::optional<Notch> notch;
    std::optional<OrientationTriangle> triangle;
};

/// The orientation marks as placed, wherever they stand (in the data, or on
/// a feature that carries them: the orientation tab), as a reader is told of
/// them and the tactile check measures them (placedMarks,
/// gen/model/features/placed_marks.h).
struct PlacedMarks {
    bool has_notch = false;
    double notch_depth_mm = 0;
    bool has_triangle = false;
    double long_leg_mm = 0, short_leg_mm = 0;
    bool underside = false;  ///< the triangle also raised on the underside (mirrored)
    /// Where the triangle stands, for a person: "on a flat tab west of the
    /// pillars" or "on a flat region of the model".
    std::string triangle_place;
    /// Where both marks are, in a few words: "on the orientation tab", "in the data".
    std::string where;
    /// Said last to a reader ("The tab holds no data."); "" for none.
    std::string note;
    double corner_x_mm = 0, corner_y_mm = 0;  ///< the model's south-west corner the marks are read from
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

/// Position in the model frame (mm, not snapped) of a planar point, for a
/// pitch and north-south stretch (hex_grid.h).
inline double planarX(const PlanarPoint& p, double pitch) { return p.i * pitch * 0.5; }
inline double planarY(const PlanarPoint& p, double pitch, double y_scale) { return p.j * pitch / (2.0 * kSqrt3) * y_scale; }

}  // namespace tsf
