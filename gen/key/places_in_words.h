// Where a set of cells lies on a model, in words a reader can use with a
// finger: "around the border", "in the north-west corner", "mostly in the
// north and the centre", "scattered across the model". For the key's
// no-data pits (and any other set of cells it names).
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace tsf {

/// cells: (col, row) on a grid of cols x rows, row 0 north, col 0 west.
/// Cells within a tenth of a side (at least one cell) of an edge are on
/// the border; when four in five are, and they lie along three or four
/// edges, the answer is "around the border" (or "along the north, west
/// and south edges"). Otherwise the model is cut in three by three
/// regions (corners, edges' middles, the centre): the region holding three
/// quarters of the cells ("in the north-west corner"), else the two or
/// three that do ("mostly in the north and the east"), else "scattered
/// across the model". "" for no cells.
std::string placesInWords(int32_t cols, int32_t rows, const std::vector<std::pair<int32_t, int32_t>>& cells);

}  // namespace tsf
