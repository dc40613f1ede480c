// The printed pieces of a model cut into halves (gen/model/features/halves.h): each half as
// it lies on the bed, and the pins that join them.
#pragma once

#include "gen/model/features/halves.h"
#include "gen/geometry/mesh.h"

namespace tsf {

struct Scene;

/// The half `kind` (Upper or Lower) of a Scene with halves, as it prints: cut
/// face on the bed (z = 0), pin holes open on it. The upper half is
/// meshScene(halfScene(scene, Upper)); the lower half is
/// meshScene(halfScene(scene, Lower)) reflected in y about the model's middle
/// (y -> depth - y, windings reversed), which with halfScene's reflection in
/// z makes a half turn about the x axis: a rigid motion of the real half.
/// Every coordinate stays on the 1 um grid.
Mesh meshHalf(const Scene& scene, HalfKind kind);

/// The inverse of the lower half's turn: a printed lower half (meshHalf)
/// back in halfScene's frame (the same reflection).
Mesh turnLowerHalf(const Mesh& printed, const Scene& scene);

/// One pin as it prints, standing: a kHoleSides-gon prism of circumradius
/// pins.pin_radius_mm and height pins.pin_length_mm, its axis at (x_mm, y_mm).
Mesh pinMesh(const PinGeometry& pins, double x_mm, double y_mm);

/// The kPinCount pins side by side (one file, kPinCount separate solids),
/// the first at the origin corner.
Mesh pinsMesh(const PinGeometry& pins);

}  // namespace tsf
