// Scene: the single description of a printable model.
//
// Both the direct mesher (gen/mesh/direct_mesher.h) and the OpenSCAD emitter
// (gen/scad/) read a Scene and nothing else, and the verifier checks meshes
// against it; that is what makes their outputs comparable.
//
// A Scene is a set of kept hex cells on a HexGrid. Each kept cell is a
// vertical prism over its hexagon from z = bottom to z = top. The model is the
// union of the prisms. Heights are integers in units of z_snap_mm, so two
// heights that print the same are the same number ("equal values are equal
// bits"); positions in x and y are snapped to kXYSnapMm.
//
// Frame: x east, y north, z up, millimetres; the grid's bounding box starts at
// (0, 0) (see hex_grid.h); the lowest bottom is z = 0.
//
// Invariants (made by buildScene, gen/model/build_scene.h; checked by the
// mesher: gen/model/scene_check.h):
//   - kept cells form one edge-connected piece;
//   - every kept cell has bottom < top;
//   - the z intervals of two neighbouring kept cells overlap by at least one
//     snap step (so the union is a 2-manifold solid without touching parts).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gen/field/hex_field.h"
#include "gen/field/hex_grid.h"
#include "gen/geometry/mesh.h"
#include "gen/model/feature_state.h"
#include "gen/model/scene_attachments.h"
#include "gen/model/scene_halves.h"
#include "gen/model/scene_marks.h"
#include "gen/model/scene_top_shapes.h"

namespace tsf {

/// Millimetre grid that x and y coordinates are rounded to (1 um).
inline constexpr double kXYSnapMm = 0.001;

/// The steepest a tilted top may lean, degrees from level, for a nozzle and
/// a layer height (mm): where a top leans down from a rim that stands above
/// its neighbour, the material under the rim is a wedge, as wide one layer
/// below the edge as layer / tan(slope). At atan(layer / nozzle) it is a
/// nozzle wide there, so the printer draws it as a wall from its second layer
/// down (the verifier measures walls there: verify/printability.h).
double maxSlopeDegFor(double nozzle_mm, double layer_mm);
/// The printer kDefaultMaxSlopeDeg is for: a 0.4 mm nozzle, 0.2 mm layers.
inline constexpr double kDefaultSlopeNozzleMm = 0.4;
inline constexpr double kDefaultSlopeLayerMm = 0.2;
/// maxSlopeDegFor(0.4, 0.2) = atan(1/2): 26.6 degrees. A finger reads it as
/// a slope, not a wall, and the rim is a 63 degree edge, twice the sharpest
/// a tactile graphic may have (docs/tactile.md).
inline constexpr double kDefaultMaxSlopeDeg = 26.565051177077990;
/// The most --max-slope may allow: above 60 degrees a top's rim is sharper
/// than the 30 degree edge a tactile graphic may have.
inline constexpr double kMaxSlopeLimitDeg = 60.0;

/// How a value becomes a height. t = (v - baseline) / (vmax - baseline) in [0, 1].
enum class Transfer {
    Linear,  ///< h = H * t             (default; heights proportional to values)
    Sqrt,    ///< h = H * sqrt(t)       (area-like quantities, counts)
    Log,     ///< h = H * log10(1 + 99 t) / 2   (two decades of range)
};

/// Where the slope of a tilted top comes from (gen/model/features/tilt.h).
enum class TiltSource : uint8_t {
    None,      ///< every top level (default)
    Points,    ///< each bin's regression plane (point input only)
    Gradient,  ///< the field's gradient
};

/// Which cells are modelled.
enum class Cull {
    None,  ///< every cell of the grid
    Hull,  ///< cells whose centre lies inside the convex hull of the non-empty cells (thesis 3.2)
    Concave,  ///< fewer empty cells: a closing of the non-empty cells, one piece (gen/model/concave_hull.h)
};

/// What is under the pillars.
enum class Bottom {
    Flat,      ///< all pillars stand on a flat base of base_mm
    Mirrored,  ///< bottom shows the negated data: every pillar has the same thickness (thesis 3.4)
};

/// Where height 0 is in data units.
enum class BaselineMode {
    Auto,   ///< 0 if no value is negative, else the smallest value
    Zero,   ///< 0 (values below it are clamped to the floor)
    Min,    ///< the smallest value
    Value,  ///< SceneParams::baseline_value
};

/// What a model says in words (tsf gen --title, --units, --braille-table):
/// its key says them, and a model with a title or units carries them in
/// braille on a plate north of the pillars (gen/model/features/legend/legend_scene.h).
struct ModelWords {
    std::string title;                      ///< first line, UTF-8
    std::string units;                      ///< after the value range ("0 to 27 airports")
    std::string braille_table = "en-ueb-g1.ctb";  ///< liblouis table of the plate and the key's BRF file
    /// The line after the title instead of the value range (a class map's
    /// "5 classes": a range of class codes means nothing); "" for the range.
    std::string range_line;
    /// Lines after the range that the plate shows only when every one fits
    /// on one braille line (a class map's classes and their textures); when
    /// one does not, none is shown and the key files name them.
    std::vector<std::string> key_lines;
    /// A title or units: the model carries them in braille.
    bool inBraille() const { return !title.empty() || !units.empty(); }
};

struct SceneParams {
    // --- size (mm) ---
    double pitch_mm = 0.0;         ///< centre spacing (hex width across flats); 0 = fit to fit_*_mm
    double fit_width_mm = 150.0;   ///< used when pitch_mm == 0: the whole grid fits this box
    double fit_depth_mm = 150.0;
    bool fit_box_given = false;    ///< the fit box was asked for: with pitch_mm > 0 the model must fit it
    /// One pillar per value of a raster (HexField::rows_a_pitch_apart): the
    /// hexagons are stretched north-south so rows stand a pitch apart and
    /// the model keeps the ground's proportions; false: regular hexagons,
    /// the model sqrt(3)/2 as deep as the ground.
    bool true_aspect = true;
    double max_height_mm = 20.0;   ///< height of the largest value above the floor
    double base_mm = 2.0;          ///< flat: base under the floor; mirrored: thinnest point of the slab
    // --- value -> height ---
    Transfer transfer = Transfer::Linear;
    BaselineMode baseline_mode = BaselineMode::Auto;
    double baseline_value = 0.0;   ///< with BaselineMode::Value
    std::optional<double> value_max;  ///< value at max_height_mm; default: the largest value
    double z_snap_mm = 0.001;      ///< height grid; may be set to the printer's layer height
    // --- shape ---
    Cull cull = Cull::Hull;
    int concave_radius = 2;        ///< Cull::Concave: closing radius in hex steps (gaps up to about 2r cells are filled)
    Bottom bottom = Bottom::Flat;
    // --- marks (gen/model/features/marks.h) ---
    MarkParams marks;
    // --- shaped tops (gen/model/features/tilt.h, gen/model/features/top_shapes.h) ---
    TiltSource tilt = TiltSource::None;
    double steepness = 1.0;        ///< multiplies every tilt's slope (> 0)
    double max_slope_deg = kDefaultMaxSlopeDeg;  ///< steepest a tilted top may lean, degrees from level
    bool structural_texture = false;  ///< dimple the cells kept only to hold the model together
    // --- what the model says in words: its key, its braille legend ---
    ModelWords words;
    /// The printer's layer (mm, 0: not known): the braille dots are made a
    /// whole number of layers high, the fewest that reach the standard's
    /// height (a 0.48 mm dot prints 0.4 mm at 0.2 mm layers; 0.6 mm is three).
    double printer_layer_mm = 0;
    // --- what the features of the registry are asked for (gen/model/feature.h) ---
    /// Each feature's request, by its own type, set by the command line; a
    /// feature asked for nothing has none here.
    FeatureStates requests;
    // --- support-free halves (gen/model/features/halves.h); mirrored only ---
    bool halves = false;           ///< cut the mirrored model into two halves that print without supports
    /// Halves: the slab every pillar crosses is grown to at least this many
    /// z units. Unset, buildScene tries the model's own slab first (the pins
    /// in pillars with room for them), then the thinnest slab that gives
    /// three pillars room, found by bisection (to kHalvesSlabSearchMm).
    std::optional<int64_t> halves_slab_units;
    // --- what the model is written as ---
    /// The model file stores float32 coordinates (STL, 3MF): a z grid finer
    /// than float32 resolves at the model's height is made coarser (the
    /// smallest 1/2/5 x 10^k mm it resolves, with a note), so that every
    /// height stays distinct and every triangle keeps its area in the file.
    bool stored_as_float32 = false;
};

/// What a kept cell stands for.
enum class CellKind : uint8_t {
    Data,    ///< a value from the input: a pillar at its height
    NoData,  ///< inside the model but without a value: a pit below the floor, never a height
};

/// The value -> height mapping actually used (after resolving Auto etc.).
struct ValueMapping {
    Transfer transfer = Transfer::Linear;
    double baseline = 0.0;   ///< value at height 0
    double value_max = 1.0;  ///< value at max_height_mm (== baseline for a constant field)
    double max_height_mm = 20.0;

    /// Height above the floor in mm (before snapping); values outside
    /// [baseline, value_max] are clamped; NaN gives 0.
    double heightMm(double value) const;
    /// Inverse of heightMm for h in [0, max_height_mm]; for a constant field returns baseline.
    double valueAt(double height_mm) const;
};

struct Scene {
    HexGrid grid;
    /// Where each cell lies in the data's own coordinates, as the field
    /// says (gen/field/data_place.h); unknown for inputs without them.
    CellPlace place;
    double pitch_mm = 1.0;
    /// North-south stretch of the lattice (hex_grid.h): 1 for regular
    /// hexagons, kRowsAPitchApart when rows stand a pitch apart to keep a
    /// raster's ground aspect (one pillar per value, SceneParams::true_aspect).
    double y_scale = 1.0;
    double z_snap_mm = 0.001;
    SceneParams params;     ///< as given (after validation)
    ValueMapping mapping;
    /// The z of height 0: flat, the base's top; mirrored, at or below the bed
    /// (minus the least height of the kept cells with data, so the model
    /// stands on z = 0 and a bottom at z is height z - floor_units).
    int64_t floor_units = 0;

    // Kept cells, struct of arrays, ordered by (row, col).
    std::vector<int32_t> col;
    std::vector<int32_t> row;
    std::vector<double> value;    ///< the cell's value; NaN = no data (modelled at the floor)
    std::vector<int64_t> top;     ///< z of the top face, in z_snap_mm units
    std::vector<int64_t> bottom;  ///< z of the bottom face, in z_snap_mm units

    std::vector<CellKind> kind;   ///< Data, or NoData (value NaN)

    std::vector<int32_t> kept_index;  ///< grid.cellCount() entries: kept index or -1

    // Marks (gen/model/features/marks.h): decided once here, drawn by every mesher.
    Marks marks;
    /// Faces that replace the plain hexagon of some kept cells (cut by the
    /// notch, or carrying the orientation triangle). Empty without marks.
    PlanarFaces faces;
    /// Per kept cell: 1 if its top/bottom/walls are drawn through `faces`
    /// instead of as a plain hexagonal prism.
    std::vector<uint8_t> drawn_by_face;
    /// Tilted tops and the dimples of structural cells (empty: every top a
    /// level hexagon). Planar ids after the faces' (gen/model/features/top_shapes.h).
    TopShapes shapes;
    /// The cut into two support-free halves and the pin holes (gen/model/features/halves.h); none unless asked for.
    std::optional<SceneHalves> halves;
    /// What the features of the registry placed (gen/model/feature.h): each
    /// holds its own state here, by its type (the tactile scale's
    /// SceneScale, a class map's textures).
    FeatureStates features;
    /// The footprints placed so far claim (gen/model/feature.h): a feature
    /// placed later keeps clear of them. Placement only: not in the sidecar.
    std::vector<FootprintClaim> claims;

    // Facts for the summary and the verifier.
    std::vector<LatticePoint> hull;  ///< convex hull of non-empty cell centres, CCW (empty if Cull::None)
    int64_t cells_with_data = 0;     ///< grid cells with a finite value
    int64_t cells_nonempty = 0;      ///< grid cells whose snapped height is above the floor
    int64_t cells_nodata_kept = 0;   ///< kept cells without data (modelled as pits)
    int64_t cells_convex = 0;        ///< Cull::Concave: cells the convex hull would keep (for the summary)
    double volume_saved_mm3 = 0;     ///< Cull::Concave: volume of the pillars the convex hull has and this one not
    int64_t mirror_thickness_units = 0;  ///< mirrored: every pillar's top - bottom
    int64_t nodata_pit_units = 0;    ///< how far a no-data cell sits below the floor (and, mirrored, above the underside)
    std::vector<std::string> notes;  ///< decisions a person should know about (constant field, ...)
    bool one_to_one = false;         ///< every kept cell holds one input value as read (HexField::one_to_one)

    size_t keptCount() const { return col.size(); }
    double zMm(int64_t units) const { return double(units) * z_snap_mm; }
    /// Snapped position (mm) of a lattice point at height `units`.
    Vec3 point(const LatticePoint& p, int64_t z_units) const;
    /// Snapped position (mm) of a point in lattice coordinates at height `units`.
    Vec3 point(const PlanarPoint& p, int64_t z_units) const;
    /// Snapped position (mm) of a planar vertex (gen/model/features/marks.h) at height `units`.
    Vec3 planarPoint(int64_t planar_id, int64_t z_units) const;
    /// The z span [bottom, top] of a face (its anchor cell's, top raised by the face's raise).
    int64_t faceTop(const PlanarFace& f) const { return top[size_t(f.anchor)] + f.raise_units; }
    int64_t faceBottom(const PlanarFace& f) const { return bottom[size_t(f.anchor)]; }
    /// Kept index of grid cell (c, r) or -1 (also -1 outside the grid).
    int32_t keptAt(int32_t c, int32_t r) const {
        return grid.contains(c, r) ? kept_index[size_t(grid.index(c, r))] : -1;
    }
    /// The kept index (-1: not kept, or beyond the grid) of the cell across
    /// edge e (0..5, hex_grid.h) of kept cell k.
    int32_t keptNeighbour(size_t k, int e) const {
        int32_t nc, nr;
        hexNeighbour(col[k], row[k], e, nc, nr);
        return keptAt(nc, nr);
    }
};

/// (v - lo) / (hi - lo) for finite v, lo < hi, also when hi - lo exceeds the
/// largest double (then computed on the halves). The OpenSCAD library's
/// _tsf_height_mm does the same, so both give the same heights.
double spanFraction(double v, double lo, double hi);

/// Round a millimetre x or y to the kXYSnapMm grid (as Scene::point does).
double snapXy(double mm);

/// Snap a millimetre value to the z grid (round half away from zero).
int64_t snapUnits(double mm, double snap_mm);

/// Text names for enums (also the CLI spellings).
const char* toString(Transfer);
const char* toString(Cull);
const char* toString(Bottom);
const char* toString(BaselineMode);
const char* toString(TiltSource);

}  // namespace tsf
