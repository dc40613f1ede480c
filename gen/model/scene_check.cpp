#include "gen/model/scene_check.h"

#include <cmath>
#include <string>
#include <vector>

#include "gen/util/error.h"
#include "gen/field/hex_grid.h"
#include "gen/model/attachments.h"
#include "gen/model/features/top_shapes.h"

namespace tsf {
namespace {

std::string cellName(const Scene& s, size_t k) {
    return "cell (" + std::to_string(s.col[k]) + ", " + std::to_string(s.row[k]) + ")";
}

[[noreturn]] void fail(const std::string& what) { throw InputError("scene: " + what); }

void checkLists(const Scene& s) {
    const size_t n = s.keptCount();
    if (s.row.size() != n || s.value.size() != n || s.top.size() != n || s.bottom.size() != n)
        fail("the cell lists (col, row, value, top, bottom) differ in length");
    if (s.grid.cols < 0 || s.grid.rows < 0 || int64_t(s.kept_index.size()) != s.grid.cellCount())
        fail("kept_index must have one entry per grid cell");
    size_t listed = 0;
    for (size_t idx = 0; idx < s.kept_index.size(); ++idx) {
        const int32_t k = s.kept_index[idx];
        if (k < 0) continue;
        ++listed;
        if (size_t(k) >= n || !s.grid.contains(s.col[size_t(k)], s.row[size_t(k)]) ||
            s.grid.index(s.col[size_t(k)], s.row[size_t(k)]) != int64_t(idx))
            fail("kept_index and the cell lists disagree at grid cell " + std::to_string(idx));
    }
    if (listed != n) fail("kept_index does not list every kept cell once");
}

}  // namespace

void checkScene(const Scene& s) {
    if (s.keptCount() == 0 && s.row.empty() && s.top.empty() && s.bottom.empty()) return;
    checkLists(s);
    // buildScene's smallest cell: 50 xy snap steps, so that snapping cannot
    // distort a hexagon or join two of its corners.
    if (!(s.pitch_mm >= 50 * kXYSnapMm && std::isfinite(s.pitch_mm)))
        fail("pitch_mm must be a number of at least " + std::to_string(50 * kXYSnapMm) + " mm");
    if (!(s.z_snap_mm > 0 && std::isfinite(s.z_snap_mm))) fail("z_snap_mm must be a positive number");
    const HexGrid& g = s.grid;
    const bool flat = s.params.bottom == Bottom::Flat;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (!(s.bottom[k] < s.top[k]))
            fail(cellName(s, k) + ": the bottom (" + std::to_string(s.bottom[k]) + ") must be below the top (" +
                 std::to_string(s.top[k]) + ")");
        if (flat && s.bottom[k] != 0)
            fail(cellName(s, k) + ": with a flat bottom every cell's bottom is 0, found " + std::to_string(s.bottom[k]));
        for (int e = 0; e < kHexCorners; ++e) {
            int32_t nc, nr;
            hexNeighbour(s.col[k], s.row[k], e, nc, nr);
            const int32_t o = s.keptAt(nc, nr);
            if (o < 0) continue;
            if (!(s.bottom[size_t(o)] < s.top[k] && s.bottom[k] < s.top[size_t(o)]))
                fail(cellName(s, k) + " and its neighbour " + cellName(s, size_t(o)) +
                     " do not overlap in z; neighbouring pillars must overlap by at least one snap step");
        }
    }

    // One piece.
    std::vector<uint8_t> kept(size_t(g.cellCount()), 0);
    for (size_t idx = 0; idx < kept.size(); ++idx) kept[idx] = s.kept_index[idx] >= 0;
    std::vector<int32_t> label;
    if (labelCellComponents(g, kept, label) > 1) {
        for (size_t k = 1; k < s.keptCount(); ++k)
            if (label[size_t(g.index(s.col[k], s.row[k]))] != label[size_t(g.index(s.col[0], s.row[0]))])
                fail("the kept cells fall apart into more than one piece (" + cellName(s, k) + " is not joined to " +
                     cellName(s, 0) + ")");
    }

    if (flat) {
        // No holes: every piece of empty cells reaches the grid's edge (and
        // so the outside).
        std::vector<uint8_t> empty(kept.size());
        for (size_t idx = 0; idx < kept.size(); ++idx) empty[idx] = !kept[idx];
        const int32_t pieces = labelCellComponents(g, empty, label);
        std::vector<uint8_t> reaches_edge(size_t(pieces), 0);
        for (int32_t r = 0; r < g.rows; ++r)
            for (int32_t c = 0; c < g.cols; ++c) {
                const int32_t l = label[size_t(g.index(c, r))];
                if (l >= 0 && (c == 0 || r == 0 || c == g.cols - 1 || r == g.rows - 1)) reaches_edge[size_t(l)] = 1;
            }
        for (int32_t r = 0; r < g.rows; ++r)
            for (int32_t c = 0; c < g.cols; ++c) {
                const int32_t l = label[size_t(g.index(c, r))];
                if (l >= 0 && !reaches_edge[size_t(l)])
                    fail("the kept region has a hole at grid cell (" + std::to_string(c) + ", " + std::to_string(r) +
                         "); a flat bottom needs a region without holes");
            }
    }
    checkTopShapes(s);
    checkAttachments(s);
}

}  // namespace tsf
