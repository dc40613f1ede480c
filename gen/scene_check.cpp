#include "gen/scene_check.h"

#include <cmath>
#include <string>
#include <vector>

#include "gen/error.h"
#include "gen/hex_grid.h"

namespace tsf {
namespace {

std::string cellName(const Scene& s, size_t k) {
    return "cell (" + std::to_string(s.col[k]) + ", " + std::to_string(s.row[k]) + ")";
}

[[noreturn]] void fail(const std::string& what) { throw InputError("scene: " + what); }

// Marks every grid cell reachable from the cells on the stack (already
// marked), stepping only onto cells where `open` is true.
void flood(const HexGrid& g, const std::vector<uint8_t>& open, std::vector<uint8_t>& seen, std::vector<int64_t> stack) {
    while (!stack.empty()) {
        const int64_t cell = stack.back();
        stack.pop_back();
        const int32_t c = int32_t(cell % g.cols), r = int32_t(cell / g.cols);
        for (int e = 0; e < kHexCorners; ++e) {
            int32_t nc, nr;
            hexNeighbour(c, r, e, nc, nr);
            if (!g.contains(nc, nr)) continue;
            const int64_t n = g.index(nc, nr);
            if (open[size_t(n)] && !seen[size_t(n)]) {
                seen[size_t(n)] = 1;
                stack.push_back(n);
            }
        }
    }
}

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
    if (!(s.pitch_mm > 0 && std::isfinite(s.pitch_mm))) fail("pitch_mm must be a positive number");
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

    // One piece: everything reachable from the first kept cell.
    std::vector<uint8_t> kept(size_t(g.cellCount()), 0), seen(size_t(g.cellCount()), 0);
    for (size_t idx = 0; idx < kept.size(); ++idx) kept[idx] = s.kept_index[idx] >= 0;
    const int64_t first = g.index(s.col[0], s.row[0]);
    seen[size_t(first)] = 1;
    flood(g, kept, seen, {first});
    for (size_t k = 0; k < s.keptCount(); ++k)
        if (!seen[size_t(g.index(s.col[k], s.row[k]))])
            fail("the kept cells fall apart into more than one piece (" + cellName(s, k) + " is not joined to " +
                 cellName(s, 0) + ")");

    if (flat) {
        // No holes: every empty cell is joined through empty cells to the
        // outside of the grid.
        std::vector<uint8_t> empty(kept.size()), outside(kept.size(), 0);
        std::vector<int64_t> border;
        for (size_t idx = 0; idx < kept.size(); ++idx) {
            empty[idx] = !kept[idx];
            const int32_t c = int32_t(int64_t(idx) % g.cols), r = int32_t(int64_t(idx) / g.cols);
            if (empty[idx] && (c == 0 || r == 0 || c == g.cols - 1 || r == g.rows - 1)) {
                outside[idx] = 1;
                border.push_back(int64_t(idx));
            }
        }
        flood(g, empty, outside, std::move(border));
        for (size_t idx = 0; idx < kept.size(); ++idx)
            if (empty[idx] && !outside[idx])
                fail("the kept region has a hole at grid cell (" + std::to_string(int64_t(idx) % g.cols) + ", " +
                     std::to_string(int64_t(idx) / g.cols) + "); a flat bottom needs a region without holes");
    }
}

}  // namespace tsf
