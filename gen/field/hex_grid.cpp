#include "gen/field/hex_grid.h"

#include <cassert>
#include <cmath>

namespace tsf {
namespace {
// Corner offsets from the centre in lattice units, counter-clockwise from the
// lower-right corner (see hex_grid.h).
constexpr std::array<std::array<int, 2>, 6> kCornerOffset = {{{1, -1}, {1, 1}, {0, 2}, {-1, 1}, {-1, -1}, {0, -2}}};

int parity(int32_t row) { return row & 1; }  // two's complement: row -1 is odd
}  // namespace

LatticePoint hexCentre(const HexGrid& grid, int32_t col, int32_t row) {
    const int64_t q = int64_t(grid.rows) - 1 - row;  // rows counted from the south
    return {2 * int64_t(col) + parity(row) + 1, 3 * q + 2};
}

LatticePoint hexCorner(const HexGrid& grid, int32_t col, int32_t row, int k) {
    assert(k >= 0 && k < kHexCorners);
    LatticePoint c = hexCentre(grid, col, row);
    return {c.i + kCornerOffset[k][0], c.j + kCornerOffset[k][1]};
}

void hexNeighbour(int32_t col, int32_t row, int k, int32_t& ncol, int32_t& nrow) {
    assert(k >= 0 && k < kHexCorners);
    const int odd = parity(row);
    switch (k) {
        case 0: ncol = col + 1; nrow = row; break;            // east
        case 1: ncol = col + odd; nrow = row - 1; break;      // north-east
        case 2: ncol = col - 1 + odd; nrow = row - 1; break;  // north-west
        case 3: ncol = col - 1; nrow = row; break;            // west
        case 4: ncol = col - 1 + odd; nrow = row + 1; break;  // south-west
        default: ncol = col + odd; nrow = row + 1; break;     // south-east
    }
}

namespace {
// Every lattice vertex is either the top corner ("N") or the bottom corner
// ("S") of exactly one cell of the grid extended by a one-cell ring.
int64_t vertexId(const HexGrid& grid, int32_t col, int32_t row, int type) {
    assert(col >= -1 && col <= grid.cols && row >= -1 && row <= grid.rows);
    return ((int64_t(row) + 1) * (int64_t(grid.cols) + 2) + (int64_t(col) + 1)) * 2 + type;
}
constexpr int kTopVertex = 0;
constexpr int kBottomVertex = 1;
}  // namespace

int64_t hexCornerId(const HexGrid& grid, int32_t col, int32_t row, int k) {
    int32_t nc = col, nr = row;
    switch (k) {
        case 2: return vertexId(grid, col, row, kTopVertex);
        case 5: return vertexId(grid, col, row, kBottomVertex);
        case 1: hexNeighbour(col, row, 1, nc, nr); return vertexId(grid, nc, nr, kBottomVertex);
        case 3: hexNeighbour(col, row, 2, nc, nr); return vertexId(grid, nc, nr, kBottomVertex);
        case 4: hexNeighbour(col, row, 4, nc, nr); return vertexId(grid, nc, nr, kTopVertex);
        default: hexNeighbour(col, row, 5, nc, nr); return vertexId(grid, nc, nr, kTopVertex);
    }
}

LatticePoint latticeVertexPoint(const HexGrid& grid, int64_t id) {
    const int type = int(id & 1);
    const int64_t cell = id >> 1;
    const int32_t col = int32_t(cell % (int64_t(grid.cols) + 2)) - 1;
    const int32_t row = int32_t(cell / (int64_t(grid.cols) + 2)) - 1;
    return hexCorner(grid, col, row, type == kTopVertex ? 2 : 5);
}

void latticeVertexCells(const HexGrid& grid, int64_t id, int32_t col[3], int32_t row[3]) {
    const int type = int(id & 1);
    const int64_t cell = id >> 1;
    col[0] = int32_t(cell % (int64_t(grid.cols) + 2)) - 1;
    row[0] = int32_t(cell / (int64_t(grid.cols) + 2)) - 1;
    // The top corner of h is corner 0 of NW(h) and corner 4 of NE(h); the
    // bottom corner of h is corner 1 of SW(h) and corner 3 of SE(h).
    hexNeighbour(col[0], row[0], type == kTopVertex ? 2 : 4, col[1], row[1]);
    hexNeighbour(col[0], row[0], type == kTopVertex ? 1 : 5, col[2], row[2]);
}

int64_t latticeVertexIdCount(const HexGrid& grid) {
    return (int64_t(grid.rows) + 2) * (int64_t(grid.cols) + 2) * 2;
}

double gridWidth(const HexGrid& grid, double pitch) {
    if (grid.cols == 0 || grid.rows == 0) return 0.0;
    // Even rows span i in [0, 2*cols], odd rows [1, 2*cols + 1].
    const int64_t imax = 2 * int64_t(grid.cols) + (grid.rows > 1 ? 1 : 0);
    return double(imax) * pitch * 0.5;
}

double gridDepth(const HexGrid& grid, double pitch, double y_scale) {
    if (grid.cols == 0 || grid.rows == 0) return 0.0;
    return latticeY({0, 3 * int64_t(grid.rows) + 1}, pitch, y_scale);
}

bool hexCellAt(const HexGrid& grid, double x, double y, int32_t& col, int32_t& row) {
    if (!std::isfinite(x) || !std::isfinite(y) || grid.cols <= 0 || grid.rows <= 0) return false;
    // Centre of row q (from the south) is at y = (3q + 2) / (2 sqrt 3) pitches;
    // the containing hexagon is the nearest centre, found among two rows.
    const double qf = (y * 2.0 * kSqrt3 - 2.0) / 3.0;
    const double q0 = std::floor(qf);
    double best = INFINITY;
    int32_t best_col = 0, best_row = 0;
    for (int dq = 0; dq <= 1; ++dq) {
        const double q = q0 + dq;
        if (q < 0 || q >= grid.rows) continue;
        const int32_t r = int32_t(grid.rows - 1 - int64_t(q));
        const double cf = x - 0.5 * (parity(r) + 1);
        const double c0 = std::floor(cf);
        for (int dc = 0; dc <= 1; ++dc) {
            const double c = c0 + dc;
            if (c < 0 || c >= grid.cols) continue;
            const LatticePoint ctr = hexCentre(grid, int32_t(c), r);
            const double dx = x - double(ctr.i) * 0.5;
            const double dy = y - double(ctr.j) / (2.0 * kSqrt3);
            const double d2 = dx * dx + dy * dy;
            if (d2 < best) { best = d2; best_col = int32_t(c); best_row = r; }
        }
    }
    if (!(best < INFINITY)) return false;
    // Nearest centre is the containing hexagon only if the point is within the
    // hexagon (the grid's outer cells do not extend to infinity).
    const LatticePoint ctr = hexCentre(grid, best_col, best_row);
    const double dx = std::fabs(x - double(ctr.i) * 0.5);
    const double dy = std::fabs(y - double(ctr.j) / (2.0 * kSqrt3));
    // Pointy-top hexagon with across-flats width 1: |dx| <= 1/2 and
    // |dx| / 2 + |dy| * sqrt(3) / 2 <= 1/2.
    const double kSlack = 1e-12;  // relative to the unit pitch: keeps points exactly on the rim
    if (dx > 0.5 + kSlack || 0.5 * dx + 0.5 * kSqrt3 * dy > 0.5 + kSlack) return false;
    col = best_col;
    row = best_row;
    return true;
}

int32_t labelCellComponents(const HexGrid& grid, const std::vector<uint8_t>& marked, std::vector<int32_t>& label) {
    label.assign(marked.size(), -1);
    std::vector<int64_t> stack;
    int32_t count = 0;
    for (int64_t start = 0; start < int64_t(marked.size()); ++start) {
        if (!marked[size_t(start)] || label[size_t(start)] >= 0) continue;
        label[size_t(start)] = count;
        stack.push_back(start);
        while (!stack.empty()) {
            const int64_t cell = stack.back();
            stack.pop_back();
            const int32_t c = int32_t(cell % grid.cols), r = int32_t(cell / grid.cols);
            for (int k = 0; k < kHexCorners; ++k) {
                int32_t nc, nr;
                hexNeighbour(c, r, k, nc, nr);
                if (!grid.contains(nc, nr)) continue;
                const int64_t n = grid.index(nc, nr);
                if (marked[size_t(n)] && label[size_t(n)] < 0) {
                    label[size_t(n)] = count;
                    stack.push_back(n);
                }
            }
        }
        ++count;
    }
    return count;
}

int32_t componentCount(const HexGrid& grid, const std::vector<uint8_t>& marked) {
    std::vector<int32_t> label;
    return labelCellComponents(grid, marked, label);
}

}  // namespace tsf
