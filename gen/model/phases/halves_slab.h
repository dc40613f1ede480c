// The slab a mirrored model is cut into halves at (gen/model/features/halves.h):
// every pillar crosses it, it is thick enough for the orientation tab on
// both sides of the cut, and, when no three pillars have room for the pins
// in the model's own slab, it grows to the thinnest that gives them room,
// found by building the Scene again at each slab tried.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "gen/model/scene.h"

namespace tsf {

/// Sets s.halves (the slab every pillar crosses, and the cut half way
/// through it) and grows s.mirror_thickness_units to at least the tab's
/// room and the slab asked for (s.params.halves_slab_units), all in z
/// units; s.nodata_pit_units becomes the flat model's pit (flat_pit_units),
/// as the OpenSCAD library computes it from the grown thickness. h_units:
/// the cells' heights by grid index.
void growSlabForHalves(const std::vector<int64_t>& h_units, int64_t flat_pit_units, Scene& s);

/// Whether placing the halves may throw rather than report no room: when
/// this build is the search's try of a slab that holds the pins everywhere
/// (halvesSlabUnits), nothing thicker would help.
bool lastHalvesSlabTry(const SceneParams& params, double z_snap_mm);

/// A whole build of the Scene with the slab this many z units thick
/// (SceneParams::halves_slab_units): whether its halves have room for the pins.
using PinsFitAtSlab = std::function<bool(int64_t slab_units)>;

/// The thinnest slab, z units, that gives the pins room: bisection between
/// the model's own slab (halves: its bounds; too thin) and one that holds
/// the pins everywhere (never fails for want of room), to
/// kHalvesSlabSearchMm. Each try is a whole build (pins_fit).
int64_t thinnestHalvesSlabUnits(const SceneHalves& halves, double z_snap_mm, const PinsFitAtSlab& pins_fit);

}  // namespace tsf
