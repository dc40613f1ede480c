#include "gen/model/phases/pillar_spans.h"

#include <algorithm>
#include <cstdlib>

#include "gen/model/phases/halves_slab.h"

namespace tsf {

void stackPillars(const std::vector<int64_t>& h_units, int64_t mirror_shift_units, Scene& s) {
    const HexGrid& g = s.grid;
    const size_t kept = s.col.size();
    const int64_t base_units = snapUnits(s.params.base_mm, s.z_snap_mm);
    // A cell without data is a pit below the floor (half the base, at most
    // 1 mm): a finger finds a hole, never the lowest value.
    s.nodata_pit_units = std::min<int64_t>(base_units / 2, std::max<int64_t>(1, snapUnits(1.0, s.z_snap_mm)));
    s.top.resize(kept);
    s.bottom.resize(kept);
    if (s.params.bottom == Bottom::Flat) {
        s.floor_units = base_units;
        for (size_t k = 0; k < kept; ++k) {
            s.bottom[k] = 0;
            s.top[k] = base_units + h_units[size_t(g.index(s.col[k], s.row[k]))];
            if (s.kind[k] == CellKind::NoData) s.top[k] -= s.nodata_pit_units;
        }
        return;
    }
    // The slab T: the largest step between neighbouring kept cells plus the base.
    int64_t max_step = 0;
    for (size_t k = 0; k < kept; ++k) {
        const int64_t h = h_units[size_t(g.index(s.col[k], s.row[k]))];
        for (int e = 0; e < kHexCorners; ++e) {
            int32_t nc, nr;
            hexNeighbour(s.col[k], s.row[k], e, nc, nr);
            const int32_t other = s.keptAt(nc, nr);
            if (other >= 0) max_step = std::max<int64_t>(max_step, std::llabs(h - h_units[size_t(g.index(nc, nr))]));
        }
    }
    s.floor_units = -mirror_shift_units;
    s.mirror_thickness_units = max_step + base_units;
    const int64_t flat_pit = s.nodata_pit_units;
    // A pit is cut from both faces of the slab: leave the cell at least
    // one step thick (a flat field's slab is only the base thick).
    s.nodata_pit_units = std::min(s.nodata_pit_units, (s.mirror_thickness_units - 1) / 2);
    if (s.params.halves) growSlabForHalves(h_units, flat_pit, s);
    for (size_t k = 0; k < kept; ++k) {
        s.bottom[k] = h_units[size_t(g.index(s.col[k], s.row[k]))];
        s.top[k] = s.bottom[k] + s.mirror_thickness_units;
        if (s.kind[k] == CellKind::NoData) {
            s.bottom[k] += s.nodata_pit_units;
            s.top[k] -= s.nodata_pit_units;
        }
    }
}

}  // namespace tsf
