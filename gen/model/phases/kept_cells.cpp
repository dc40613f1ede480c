#include "gen/model/phases/kept_cells.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "gen/model/concave_hull.h"
#include "gen/model/convex_hull.h"
#include "gen/util/error.h"

namespace tsf {

namespace {

// The hull's straight edges cross the hexagons' staircase: where the data
// ends on a slant (a rotated raster resampled north-up, a round coast), the
// hull keeps a row of cells without data along its rim, each a pit 1 mm
// deep in the model's edge. A reader takes a pit for "no data here", where
// there is only the edge of the data; and those pits break the run of
// pillars the orientation tab stands against, so it cannot follow the
// outline and hangs from one pillar. So the cells without data that touch
// the outside (a cell not kept, or beyond the grid) are left out, one
// layer: the model then ends where its data does. No value is lost; no-data
// inside the model, or deeper in a bay, stays a pit. When leaving them out
// would cut the model in two, they all stay.
void dropRimCellsWithoutData(const HexField& field, std::vector<uint8_t>& keep) {
    const HexGrid& g = field.grid;
    std::vector<size_t> rim;
    for (int32_t r = 0; r < g.rows; ++r)
        for (int32_t c = 0; c < g.cols; ++c) {
            const size_t idx = size_t(g.index(c, r));
            if (!keep[idx] || !std::isnan(field.values[idx])) continue;
            for (int e = 0; e < kHexCorners; ++e) {
                int32_t nc = 0, nr = 0;
                hexNeighbour(c, r, e, nc, nr);
                if (!g.contains(nc, nr) || !keep[size_t(g.index(nc, nr))]) {
                    rim.push_back(idx);
                    break;
                }
            }
        }
    if (rim.empty()) return;
    std::vector<uint8_t> without = keep;
    for (size_t idx : rim) without[idx] = 0;
    bool any = false;
    for (uint8_t k : without) any = any || k;
    if (any && componentCount(g, without) == 1) keep.swap(without);
}

}  // namespace

KeptCells cullCells(const HexField& field, const CellHeights& heights, const SceneParams& params) {
    const HexGrid& g = field.grid;
    const size_t n = size_t(g.cellCount());
    KeptCells out;
    std::vector<uint8_t>& keep = out.keep;
    keep.assign(n, 0);
    if (params.cull == Cull::None) {
        std::fill(keep.begin(), keep.end(), 1);
        return out;
    }
    if (heights.nonempty_count == 0) {
        // Nothing rises above the floor: there is no hull to cull with. Keep
        // the whole grid as a flat slab rather than print nothing.
        std::fill(keep.begin(), keep.end(), 1);
        out.notes.push_back("no cell rises above the floor: the whole grid is kept as a flat slab");
        return out;
    }
    // The hull spans the non-empty cells; when every cell is one input
    // value, it spans every cell with data: a typed 0 is a value, and
    // only cells without data are left out.
    std::vector<LatticePoint> centres;
    centres.reserve(size_t(heights.nonempty_count));
    for (int32_t r = 0; r < g.rows; ++r)
        for (int32_t c = 0; c < g.cols; ++c) {
            const size_t idx = size_t(g.index(c, r));
            if (heights.nonempty[idx] || (field.one_to_one && !std::isnan(field.values[idx])))
                centres.push_back(hexCentre(g, c, r));
        }
    out.hull = convexHull(centres);
    for (int32_t r = 0; r < g.rows; ++r)
        for (int32_t c = 0; c < g.cols; ++c) keep[size_t(g.index(c, r))] = hullContains(out.hull, hexCentre(g, c, r));
    if (componentCount(g, keep) > 1) {
        // A thin hull (one cell, or cells on a line) can miss the cells
        // between its corners. Every cell within one circumradius of the
        // hull touches it, and such cells form one piece (docs/model.md).
        const double reach = 1.0 / kSqrt3 + 1e-9;  // circumradius in pitches, plus rounding slack
        for (int32_t r = 0; r < g.rows; ++r)
            for (int32_t c = 0; c < g.cols; ++c)
                keep[size_t(g.index(c, r))] = hullDistancePitch(out.hull, hexCentre(g, c, r)) <= reach;
        out.notes.push_back("the hull of the non-empty cells is too thin to hold the model together; "
                            "cells touching it were added so the model is one piece");
    }
    dropRimCellsWithoutData(field, keep);
    if (params.cull == Cull::Concave) {
        std::vector<uint8_t> anchor(n, 0);
        for (size_t idx = 0; idx < n; ++idx)
            anchor[idx] = heights.nonempty[idx] || (field.one_to_one && !std::isnan(field.values[idx]));
        std::vector<uint8_t> concave = concaveKeep(g, anchor, keep, std::max(0, params.concave_radius));
        for (size_t idx = 0; idx < n; ++idx) {
            out.cells_convex += keep[idx];
            out.dropped_by_concave.push_back(keep[idx] && !concave[idx] ? uint8_t(1) : uint8_t(0));
        }
        keep.swap(concave);
    }
    return out;
}


void listKeptCells(const HexField& field, const std::vector<uint8_t>& keep, Scene& s) {
    const HexGrid& g = s.grid;
    s.kept_index.assign(keep.size(), -1);
    for (int32_t r = 0; r < g.rows; ++r) {
        for (int32_t c = 0; c < g.cols; ++c) {
            const size_t idx = size_t(g.index(c, r));
            if (!keep[idx]) continue;
            s.kept_index[idx] = int32_t(s.col.size());
            s.col.push_back(c);
            s.row.push_back(r);
            s.value.push_back(field.values[idx]);
            s.kind.push_back(std::isnan(field.values[idx]) ? CellKind::NoData : CellKind::Data);
            s.cells_nodata_kept += std::isnan(field.values[idx]);
        }
    }
}

void noteConcaveSavings(const HexField& field, const std::vector<uint8_t>& dropped_by_concave, Scene& s) {
    if (dropped_by_concave.empty()) return;
    // What the convex hull would have printed there: empty pillars (floor
    // height, or a pit without data) of the full slab, in z units.
    const bool flat = s.params.bottom == Bottom::Flat;
    const int64_t slab = flat ? snapUnits(s.params.base_mm, s.z_snap_mm) : s.mirror_thickness_units;
    int64_t dropped = 0, units = 0;
    for (size_t idx = 0; idx < dropped_by_concave.size(); ++idx) {
        if (!dropped_by_concave[idx]) continue;
        ++dropped;
        const bool nodata = std::isnan(field.values[idx]);
        units += slab - (nodata ? (flat ? 1 : 2) * s.nodata_pit_units : 0);
    }
    s.volume_saved_mm3 = double(units) * s.z_snap_mm * hexArea(s.pitch_mm, s.y_scale);
    std::ostringstream note;
    note.precision(3);
    note << "concave hull: " << s.keptCount() << " cells kept, " << dropped << " fewer than the convex hull ("
         << (s.cells_convex > 0 ? 100.0 * double(dropped) / double(s.cells_convex) : 0.0) << "%), saving about "
         << s.volume_saved_mm3 / 1000.0 << " cm^3 of material";
    s.notes.push_back(note.str());
}

}  // namespace tsf
