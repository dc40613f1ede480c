// Concave hull on the hex lattice: fewer empty cells than the convex hull,
// still one piece with one rim (thesis 7.1.3, "--cull concave").
//
// The convex hull keeps every cell between the data, which on sparse data
// (islands, a coastline, a ring) is a lot of plastic that says nothing. The
// concave hull is a morphological closing on the lattice, in hex steps:
//   1. anchors: the cells that must stay (non-empty cells, or every cell with
//      data when each cell is one input value);
//   2. closing with radius r: dilate the anchors by r steps, then erode the
//      result by r steps (beyond the grid counts as outside). Gaps and bays
//      up to about 2r cells wide are filled; wider ones stay open;
//   3. never more than the convex hull: the result is cut to `convex_keep`;
//   4. one piece: while there are several, the piece holding the first kept
//      cell is joined to the nearest other piece by a shortest path of cells
//      inside the convex hull (which is one piece, so a path exists);
//   5. one rim: empty cells enclosed by kept cells (not reachable from beyond
//      the grid through empty cells) are kept, so the flat bottom is one polygon.
// Everything is integer breadth-first search on the grid: O(cells) per step,
// O(pieces x cells) for step 4.
#pragma once

#include <cstdint>
#include <vector>

#include "gen/field/hex_grid.h"

namespace tsf {

/// Default closing radius (hex steps) of --cull concave.
inline constexpr int kDefaultConcaveRadius = 2;

/// The cells to keep (grid layout, 1 = keep) as described above. `anchor` and
/// `convex_keep` have grid.cellCount() entries; anchors must lie inside
/// `convex_keep`, and the cells of `convex_keep` must be one piece.
std::vector<uint8_t> concaveKeep(const HexGrid& grid, const std::vector<uint8_t>& anchor,
                                 const std::vector<uint8_t>& convex_keep, int radius);

}  // namespace tsf
