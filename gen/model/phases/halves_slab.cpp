#include "gen/model/phases/halves_slab.h"

#include <algorithm>
#include <climits>

#include "gen/model/feature_registry.h"
#include "gen/model/features/halves.h"

namespace tsf {

void growSlabForHalves(const std::vector<int64_t>& h_units, int64_t flat_pit_units, Scene& s) {
    // Halves: every pillar must cross one slab thick enough for the
    // pin holes on both sides of the cut (gen/model/features/halves.h).
    // The grown slab is far thicker than two pits, so a pit is the
    // flat model's (as the OpenSCAD library computes it from the
    // grown thickness).
    const HexGrid& g = s.grid;
    int64_t highest_bottom = 0, lowest_top = INT64_MAX;
    for (size_t k = 0; k < s.col.size(); ++k) {
        const int64_t h = h_units[size_t(g.index(s.col[k], s.row[k]))];
        const int64_t pit = s.kind[k] == CellKind::NoData ? flat_pit_units : 0;
        highest_bottom = std::max(highest_bottom, h + pit);
        lowest_top = std::min(lowest_top, h - pit + s.mirror_thickness_units);
    }
    // The pins go where the pillars have room for them on both sides
    // of the cut (material there anyway: placeHalves); only when no
    // three pillars have, the slab grows to hold them everywhere.
    // At least the room each feature needs across the cut (a body that
    // lies across it, gen/model/feature.h), and a unit on each side: no
    // pillar ends at the cut (it would vanish from one half).
    int64_t room = 2;
    for (const Feature* f : features())
        if (f->room_across_cut_units) room = std::max(room, f->room_across_cut_units(s));
    const int64_t want = std::max(s.params.halves_slab_units.value_or(0), room);
    const int64_t grow = std::max<int64_t>(0, want - (lowest_top - highest_bottom));
    s.mirror_thickness_units += grow;
    s.nodata_pit_units = std::min(flat_pit_units, (s.mirror_thickness_units - 1) / 2);
    SceneHalves halves;
    halves.thickness_grown_units = grow;
    halves.slab_bottom_units = highest_bottom;
    halves.slab_top_units = lowest_top + grow;
    halves.split_units = (halves.slab_bottom_units + halves.slab_top_units) / 2;
    s.halves = halves;
}

bool lastHalvesSlabTry(const SceneParams& params, double z_snap_mm) {
    return params.halves_slab_units && *params.halves_slab_units >= halvesSlabUnits(z_snap_mm);
}

int64_t thinnestHalvesSlabUnits(const SceneHalves& halves, double z_snap_mm, const PinsFitAtSlab& pins_fit) {
    int64_t lo = halves.slab_top_units - halves.slab_bottom_units, hi = halvesSlabUnits(z_snap_mm);
    const int64_t step = std::max<int64_t>(1, snapUnits(kHalvesSlabSearchMm, z_snap_mm));
    while (hi - lo > step) {
        const int64_t mid = (lo + hi) / 2;
        if (pins_fit(mid)) hi = mid;
        else lo = mid;
    }
    return hi;
}

}  // namespace tsf
