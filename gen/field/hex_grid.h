// HexGrid: the hexagonal lattice every model is built on.
//
// Orientation: POINTY-TOP regular hexagons in rows ("odd-r" offset layout).
//   - cell (col, row): row 0 is the NORTH (top) row, col 0 the WEST column;
//   - odd rows are shifted EAST by half a cell;
//   - "pitch" is the distance between neighbouring centres = the hexagon's
//     width across flats = sqrt(3) * circumradius.
//
// Lattice coordinates. Every centre and every corner has exact integer
// coordinates (i, j); the model frame (x east, y north, millimetres) is
//     x = i * pitch / 2,     y = j * pitch / (2 * sqrt(3)) * y_scale.
// y_scale is 1 for regular hexagons (rows sqrt(3)/2 of a pitch apart);
// kRowsAPitchApart stretches them north-south so rows stand one pitch apart,
// as the rows of a raster with square pixels do on the ground (true aspect
// for one pillar per value: docs/model.md). The stretch is an affine map of
// the whole lattice, so the topology on the integers is the same.
// The lower-left corner of the grid's bounding box is (0, 0). Topology (which
// corner is shared by which cells) is decided on these integers only, never by
// comparing floating-point positions.
//
// Corners k = 0..5 run counter-clockwise seen from +z, starting at the
// lower-right corner: 0 lower-right, 1 upper-right, 2 top, 3 upper-left,
// 4 lower-left, 5 bottom. Edge k joins corner k and corner k+1 (mod 6) and is
// shared with neighbour k: 0 east, 1 north-east, 2 north-west, 3 west,
// 4 south-west, 5 south-east.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace tsf {

struct HexGrid {
    int32_t cols = 0;
    int32_t rows = 0;

    int64_t cellCount() const { return int64_t(cols) * rows; }
    bool contains(int32_t col, int32_t row) const { return col >= 0 && row >= 0 && col < cols && row < rows; }
    int64_t index(int32_t col, int32_t row) const { return int64_t(row) * cols + col; }
};

/// An exact lattice position; see the file comment for the mapping to mm.
struct LatticePoint {
    int64_t i = 0;
    int64_t j = 0;
    friend bool operator==(const LatticePoint&, const LatticePoint&) = default;
};

inline constexpr int kHexCorners = 6;
inline constexpr double kSqrt3 = 1.7320508075688772935;
/// The y_scale that puts rows of hexagons one pitch apart: 2 / sqrt(3).
inline constexpr double kRowsAPitchApart = 2.0 / kSqrt3;

/// Centre of cell (col, row) in lattice coordinates. Works for cells outside
/// the grid too (used for the ring of virtual neighbours).
LatticePoint hexCentre(const HexGrid& grid, int32_t col, int32_t row);

/// Corner k (0..5, see file comment) of cell (col, row) in lattice coordinates.
LatticePoint hexCorner(const HexGrid& grid, int32_t col, int32_t row, int k);

/// The cell across edge k (0..5) of (col, row); may lie outside the grid.
void hexNeighbour(int32_t col, int32_t row, int k, int32_t& ncol, int32_t& nrow);

/// Dense id of the lattice vertex at corner k of (col, row), for cells in the
/// grid. Ids are < latticeVertexIdCount(grid). Two corners of different cells
/// are the same point exactly when their ids are equal.
int64_t hexCornerId(const HexGrid& grid, int32_t col, int32_t row, int k);
int64_t latticeVertexIdCount(const HexGrid& grid);
/// The lattice point of a vertex id from hexCornerId (0 <= id < latticeVertexIdCount).
LatticePoint latticeVertexPoint(const HexGrid& grid, int64_t id);
/// The three cells (col, row) that meet at a lattice vertex; some may lie
/// outside the grid.
void latticeVertexCells(const HexGrid& grid, int64_t id, int32_t col[3], int32_t row[3]);

/// x, y (mm) of a lattice point for a given pitch (mm) and north-south
/// stretch (y_scale, see the file comment).
inline double latticeX(const LatticePoint& p, double pitch) { return double(p.i) * pitch * 0.5; }
inline double latticeY(const LatticePoint& p, double pitch, double y_scale) {
    return double(p.j) * pitch / (2.0 * kSqrt3) * y_scale;
}

/// Width and depth (mm) of the grid's bounding box for a given pitch (mm)
/// and north-south stretch.
double gridWidth(const HexGrid& grid, double pitch);
double gridDepth(const HexGrid& grid, double pitch, double y_scale);

/// The cell whose hexagon contains (x, y), both given in units of the pitch in
/// the model frame (x east, y north, origin at the grid's lower-left corner).
/// Points on a shared edge go to one of the two cells deterministically.
/// Returns false (and leaves col/row unchanged) if the point is outside every
/// cell of the grid. NaN coordinates return false.
bool hexCellAt(const HexGrid& grid, double x_pitch, double y_pitch, int32_t& col, int32_t& row);

/// The edge-connected components of the marked cells (marked[grid.index(c, r)]
/// != 0; one entry per grid cell): label[index] is the component (0, 1, ...)
/// of a marked cell, -1 for the others. Returns the number of components.
int32_t labelCellComponents(const HexGrid& grid, const std::vector<uint8_t>& marked, std::vector<int32_t>& label);

/// The number of edge-connected components of the marked cells.
int32_t componentCount(const HexGrid& grid, const std::vector<uint8_t>& marked);

/// Distance (mm) from a hexagon's centre to its farthest corner, for a pitch
/// and north-south stretch: the top corner of a stretched hexagon, a side
/// corner of a squashed one; pitch / sqrt(3) for a regular hexagon.
inline double hexCircumradius(double pitch, double y_scale) {
    const double r = pitch / kSqrt3;
    return y_scale >= 1.0 ? r * y_scale : 0.5 * std::sqrt(pitch * pitch + r * r * y_scale * y_scale);
}

/// Area of one hexagon in mm^2 for a given pitch in mm and north-south stretch.
inline double hexArea(double pitch, double y_scale) { return kSqrt3 / 2.0 * pitch * pitch * y_scale; }

}  // namespace tsf
