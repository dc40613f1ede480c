// Support-free halves of a mirrored model: where the model is cut, where
// the alignment pins go, and the two halves as Scenes of their own.
//
// A mirrored model printed in one piece stands on its underside, which is
// the mirrored relief: most of it hangs in the air and needs supports that
// scar the surface a reader feels. Cut at a horizontal plane through a slab
// every pillar crosses, it becomes two halves that each have one flat face
// (the cut) and stand on it with every pillar rising from the bed: nothing
// overhangs. The upper half is the pillars above the cut; the lower half is
// the pillars below it, turned over (a half turn about the x axis) so its
// cut lies on the bed and the underside relief faces up.
//
// The cut (decided by buildScene, stored as Scene::halves):
//   - with halves asked for, the mirror thickness T grows until every pillar
//     spans one common slab [slab_bottom, slab_top] of at least kHalvesSlabMm
//     (room for a pin hole on each side of the cut, with material above it);
//   - the cut is the slab's mid-plane, split_units (model frame, z units).
//
// Alignment (placeHalves): three holes, one in each cut face at the same
// place, take three separate printed pins. Their centres are cell centres
// whose triangle is scalene (its three sides differ by at least
// kPinLayoutMinSideDifferenceMm), so no rotation or reflection maps the
// holes onto themselves: the halves go together one way only. Every hole
// keeps kHoleEdgeMarginMm of material to the model's outer wall and stays
// clear of the cells the orientation marks draw. A hole is a 16-gon on the
// 1 um grid with its flats at the hole radius, kHoleDepthMm deep, closed by
// a cone steeper than 45 degrees (prints without a bridge or supports).
//
// Frames. Scene::halves is in the model frame. halfScene gives each half as
// a flat-bottomed Scene in its own printing frame before the lower half's
// turn (x, y as the model; z up from the cut face on the bed): the upper
// half as is, shifted down by the cut; the lower half reflected in z about
// the cut. The direct mesher turns the lower half's reflection into the
// half turn by reflecting y (gen/mesh/halves_mesh.h).
#pragma once

#include <cstdint>
#include <vector>

#include "gen/field/hex_grid.h"
#include "gen/model/features/marks.h"

namespace tsf {

struct Scene;

/// Pin diameter, mm: printed standing, a 3 mm PLA pin does not snap when
/// the halves are pressed together or pulled apart.
inline constexpr double kPinDiameterMm = 3.0;
/// Gap between pin and hole on each side, mm: the 0.2 mm per side a sliding
/// fit needs on FDM printers (docs/printing.md cites the source).
inline constexpr double kPinClearanceMm = 0.2;
/// How deep each hole goes into its half, mm, before the cone that closes it.
inline constexpr double kHoleDepthMm = 3.0;
/// The cone's height over the hole's vertex radius: 1.1 makes every cone
/// face 48.3 degrees from the horizontal (steeper than 45), which prints without
/// supports or bridging.
inline constexpr double kHoleConeRatio = 1.1;
/// Material above a hole's cone tip, mm (two nozzle widths).
inline constexpr double kHoleRoofMm = 0.8;
/// Material between a hole and the model's outer wall, mm (five perimeters
/// of a 0.4 mm nozzle).
inline constexpr double kHoleEdgeMarginMm = 2.0;
/// Sides of the polygons that stand for the round holes and pins.
inline constexpr int kHoleSides = 16;
/// The three distances between hole centres differ pairwise by at least this
/// much, mm: far more than the 4 x 0.2 mm two loose pins can take up, so a
/// turned or reflected half cannot be pushed on.
inline constexpr double kPinLayoutMinSideDifferenceMm = 2.0;
/// Number of pins (and of holes in each cut face).
inline constexpr int kPinCount = 3;

/// Which piece a Scene draws.
enum class HalfKind : uint8_t {
    Whole,  ///< the whole mirrored model (the holes are not drawn)
    Upper,  ///< the pillars above the cut, standing on the cut
    Lower,  ///< the pillars below the cut, reflected in z about it (see the file comment)
};

/// Holes radius, depth and the pins that fit them (mm).
struct PinGeometry {
    double hole_radius_mm = kPinDiameterMm / 2 + kPinClearanceMm;  ///< inscribed radius of the hole polygon
    double hole_vertex_radius_mm = 0;  ///< circumradius of the hole polygon
    double pin_radius_mm = kPinDiameterMm / 2;  ///< circumradius of the pin polygon (the pin fits in this circle)
    double hole_depth_mm = kHoleDepthMm;        ///< straight part of the hole, from the cut face
    double cone_mm = 0;                         ///< height of the cone over the straight part
    double pin_length_mm = 0;                   ///< two hole depths less the clearance at each end
};

/// The halves in the Scene (model frame unless said otherwise).
struct SceneHalves {
    HalfKind kind = HalfKind::Whole;  ///< what this Scene draws (halfScene sets Upper or Lower)
    int64_t split_units = 0;          ///< z of the cut, z units (model frame)
    int64_t slab_bottom_units = 0;    ///< highest pillar bottom: the common slab starts here
    int64_t slab_top_units = 0;       ///< lowest pillar top: the common slab ends here
    int64_t thickness_grown_units = 0;  ///< how much the mirror thickness grew for the slab
    PinGeometry pins;
    std::vector<int32_t> hole_cells;        ///< kept index of the cell each hole is centred on
    std::vector<LatticePoint> hole_centres; ///< the holes' centres (the cells' centres)
    int64_t hole_depth_units = 0;           ///< straight part of a hole, z units
    int64_t hole_apex_units = 0;            ///< tip of the cone above the cut face, z units
};

/// The slab the halves need, z units: room for a hole and its cone and roof
/// on each side of the cut (kHalvesSlabMm rounded up to the z grid).
int64_t halvesSlabUnits(double z_snap_mm);
/// The same in mm before rounding: 2 x (depth + cone + roof).
double halvesSlabMm();

/// Pin and hole sizes for kPinDiameterMm and kPinClearanceMm.
PinGeometry pinGeometry();

/// Decides the cut and the holes of a mirrored Scene whose thickness already
/// leaves the common slab (buildScene does both when params.halves is set).
/// Throws InputError when the model cannot take the pins, saying what to
/// change (cells smaller than a hole, too little room clear of the edge and
/// the marks for three holes in a scalene triangle).
void placeHalves(Scene& scene);

/// The ring of hole `h` (kHoleSides points, counter-clockwise from above, in
/// lattice coordinates; Scene::point snaps them to the 1 um grid).
std::vector<PlanarPoint> holeRing(const Scene& scene, size_t h);

/// True when no rotation or reflection other than the identity maps the
/// hole centres (mm, x y) onto themselves, with `tolerance_mm` of play: three
/// points whose three distances differ pairwise by more than twice the
/// tolerance, not on one line. Any other count of points is false.
bool isChiralLayout(const std::vector<std::pair<double, double>>& centres_mm, double tolerance_mm);

/// The hole centres of a Scene with halves, mm (x, y).
std::vector<std::pair<double, double>> holeCentresMm(const Scene& scene);

/// True when `scene` draws a half (halfScene) and kept cell `kept` has a pin
/// hole under its centre: its bottom there is the hole's cone tip
/// (SceneHalves::hole_apex_units), not z = 0.
bool isHoleCell(const Scene& scene, size_t kept);

/// The upper or lower half of a Scene with halves as a flat-bottomed Scene in
/// its printing frame (see the file comment); `kind` Upper or Lower.
Scene halfScene(const Scene& scene, HalfKind kind);

}  // namespace tsf
