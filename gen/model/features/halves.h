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
#include <utility>
#include <vector>

#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// The slab the halves need, z units: room for a hole and its cone and roof
/// on each side of the cut (kHalvesSlabMm rounded up to the z grid).
int64_t halvesSlabUnits(double z_snap_mm);
/// The same in mm before rounding: 2 x (depth + cone + roof).
double halvesSlabMm();

/// Pin and hole sizes for kPinDiameterMm and kPinClearanceMm.
PinGeometry pinGeometry();

/// Decides the holes of a mirrored Scene with its cut (buildScene does both
/// when params.halves is set). A hole goes where every pillar it reaches
/// has room for it on both sides of the cut - the hole, its cone and a roof
/// above, below the cut and above it - in material that is there anyway:
/// the pillars are as thick as the mirror, and those of middle height reach
/// far to both sides. False when no three such places make a scalene
/// triangle (the caller may grow the slab every pillar crosses, so all have
/// room, and try again); with or_throw, an InputError instead, saying what
/// to change (cells smaller than a hole, too little room clear of the edge
/// and the marks). Cells smaller than a hole always throw.
bool placeHalves(Scene& scene, bool or_throw = true);

/// The ring of hole `h` (kHoleSides points, counter-clockwise from above, in
/// lattice coordinates; Scene::point snaps them to the 1 um grid).
std::vector<PlanarPoint> holeRing(const Scene& scene, size_t h);

/// The pin holes into the flat bottom of a half (halfScene, kind Upper or
/// Lower), as cuts (gen/model/scene_attachments.h); none for a whole model.
std::vector<BottomHole> halfBottomHoles(const Scene& scene);

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
