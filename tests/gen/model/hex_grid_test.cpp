#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>

#include "gen/model/convex_hull.h"
#include "gen/field/hex_grid.h"

namespace tsf {
namespace {

TEST(HexGrid, NeighboursShareTheirEdgeCorners) {
    // Edge k of a cell is edge k+3 of the neighbour across it, traversed the
    // other way: corner k == neighbour's corner k+4, corner k+1 == corner k+3.
    const HexGrid g{7, 6};
    for (int r = 0; r < g.rows; ++r) {
        for (int c = 0; c < g.cols; ++c) {
            for (int k = 0; k < 6; ++k) {
                int32_t nc, nr;
                hexNeighbour(c, r, k, nc, nr);
                EXPECT_EQ(hexCorner(g, c, r, k), hexCorner(g, nc, nr, (k + 4) % 6)) << c << "," << r << " k" << k;
                EXPECT_EQ(hexCorner(g, c, r, (k + 1) % 6), hexCorner(g, nc, nr, (k + 3) % 6));
                if (g.contains(nc, nr)) {
                    EXPECT_EQ(hexCornerId(g, c, r, k), hexCornerId(g, nc, nr, (k + 4) % 6));
                }
            }
        }
    }
}

TEST(HexGrid, CornerIdsIdentifyLatticePointsExactly) {
    const HexGrid g{9, 8};
    std::map<int64_t, LatticePoint> by_id;
    std::map<std::pair<int64_t, int64_t>, int64_t> by_point;
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c)
            for (int k = 0; k < 6; ++k) {
                const int64_t id = hexCornerId(g, c, r, k);
                const LatticePoint p = hexCorner(g, c, r, k);
                ASSERT_LT(id, latticeVertexIdCount(g));
                auto [it, fresh] = by_id.emplace(id, p);
                EXPECT_EQ(it->second, p);
                auto [it2, fresh2] = by_point.emplace(std::make_pair(p.i, p.j), id);
                EXPECT_EQ(it2->second, id);
            }
    // Every interior vertex is shared by exactly three cells.
    std::map<int64_t, int> uses;
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c)
            for (int k = 0; k < 6; ++k) ++uses[hexCornerId(g, c, r, k)];
    for (auto [id, n] : uses) EXPECT_LE(n, 3);
}

TEST(HexGrid, CentresAreOnePitchApartAndRowZeroIsNorth) {
    const HexGrid g{4, 3};
    const double pitch = 2.0;
    const LatticePoint a = hexCentre(g, 1, 1), b = hexCentre(g, 2, 1);
    EXPECT_DOUBLE_EQ(latticeX(b, pitch) - latticeX(a, pitch), pitch);
    int32_t nc, nr;
    hexNeighbour(1, 1, 1, nc, nr);  // north-east
    const LatticePoint ne = hexCentre(g, nc, nr);
    EXPECT_NEAR(std::hypot(latticeX(ne, pitch) - latticeX(a, pitch), latticeY(ne, pitch, 1.0) - latticeY(a, pitch, 1.0)), pitch, 1e-12);
    EXPECT_GT(latticeY(hexCentre(g, 0, 0), pitch, 1.0), latticeY(hexCentre(g, 0, 2), pitch, 1.0));
    // The bounding box starts at (0, 0) and holds every corner.
    double xmin = 1e9, ymin = 1e9, xmax = -1e9, ymax = -1e9;
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c)
            for (int k = 0; k < 6; ++k) {
                const LatticePoint p = hexCorner(g, c, r, k);
                xmin = std::min(xmin, latticeX(p, pitch)); xmax = std::max(xmax, latticeX(p, pitch));
                ymin = std::min(ymin, latticeY(p, pitch, 1.0)); ymax = std::max(ymax, latticeY(p, pitch, 1.0));
            }
    EXPECT_DOUBLE_EQ(xmin, 0.0);
    EXPECT_DOUBLE_EQ(ymin, 0.0);
    EXPECT_DOUBLE_EQ(xmax, gridWidth(g, pitch));
    EXPECT_NEAR(ymax, gridDepth(g, pitch, 1.0), 1e-12);
}

TEST(HexGrid, CellAtFindsTheCellOfEveryCentreAndRejectsOutside) {
    const HexGrid g{6, 5};
    for (int r = 0; r < g.rows; ++r)
        for (int c = 0; c < g.cols; ++c) {
            const LatticePoint p = hexCentre(g, c, r);
            int32_t fc = -1, fr = -1;
            ASSERT_TRUE(hexCellAt(g, latticeX(p, 1.0) + 0.2, latticeY(p, 1.0, 1.0) - 0.1, fc, fr));
            EXPECT_EQ(fc, c);
            EXPECT_EQ(fr, r);
        }
    int32_t c, r;
    EXPECT_FALSE(hexCellAt(g, -0.1, 1.0, c, r));
    EXPECT_FALSE(hexCellAt(g, 1.0, -0.01, c, r));
    EXPECT_FALSE(hexCellAt(g, NAN, 1.0, c, r));
    EXPECT_FALSE(hexCellAt(g, 100.0, 1.0, c, r));
}

TEST(ConvexHull, SquareCollinearAndSinglePoint) {
    std::vector<LatticePoint> square{{0, 0}, {4, 0}, {4, 4}, {0, 4}, {2, 2}, {2, 0}};
    auto hull = convexHull(square);
    ASSERT_EQ(hull.size(), 4u);
    EXPECT_TRUE(hullContains(hull, {2, 2}));
    EXPECT_TRUE(hullContains(hull, {4, 2}));   // on the boundary
    EXPECT_FALSE(hullContains(hull, {5, 2}));
    std::vector<LatticePoint> line{{0, 0}, {3, 3}, {6, 6}, {9, 9}};
    hull = convexHull(line);
    ASSERT_EQ(hull.size(), 2u);
    EXPECT_TRUE(hullContains(hull, {3, 3}));
    EXPECT_FALSE(hullContains(hull, {3, 4}));
    EXPECT_FALSE(hullContains(hull, {12, 12}));
    std::vector<LatticePoint> one{{5, 5}, {5, 5}};
    hull = convexHull(one);
    ASSERT_EQ(hull.size(), 1u);
    EXPECT_TRUE(hullContains(hull, {5, 5}));
    EXPECT_DOUBLE_EQ(hullDistancePitch(hull, {7, 5}), 1.0);  // two lattice units in i = one pitch
}

}  // namespace
}  // namespace tsf
