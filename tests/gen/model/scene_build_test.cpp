// buildScene's phases alone (gen/model/phases/), on hand-made data: the
// halves' slab search, the mirrored floor and the cull's edge cases.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gen/model/phases/cell_heights.h"
#include "gen/model/phases/halves_slab.h"
#include "gen/model/phases/kept_cells.h"
#include "gen/model/convex_hull.h"
#include "gen/model/features/halves.h"
#include "gen/model/features/tiles.h"
#include "gen/util/error.h"
#include "tests/support/fields.h"

namespace tsf {
namespace {

TEST(HalvesSlabSearch, FindsTheThinnestSlabThatHoldsThePinsToOneSearchStep) {
    // z snap 0.01 mm: the search step kHalvesSlabSearchMm (0.1 mm) is 10 units.
    const double snap_mm = 0.01;
    const int64_t full = halvesSlabUnits(snap_mm);
    const int64_t needed = 123;  // the pins first fit in a slab 1.23 mm thick
    ASSERT_GT(full, needed + 10);
    SceneHalves model;
    model.slab_bottom_units = 40;
    model.slab_top_units = 60;  // the model's own slab: 20 units, too thin
    std::vector<int64_t> tried;
    const int64_t slab = thinnestHalvesSlabUnits(model, snap_mm, [&](int64_t units) {
        tried.push_back(units);
        return units >= needed;
    });
    EXPECT_GE(slab, needed);
    EXPECT_LT(slab, needed + 10);
    ASSERT_FALSE(tried.empty());
    for (const int64_t u : tried) {
        EXPECT_GT(u, 20);
        EXPECT_LT(u, full);
    }
}

TEST(HalvesSlabSearch, NoSlabThatFitsBelowTheFullOneGivesTheFullOne) {
    const double snap_mm = 0.01;
    SceneHalves model;
    model.slab_bottom_units = 0;
    model.slab_top_units = 20;
    EXPECT_EQ(thinnestHalvesSlabUnits(model, snap_mm, [](int64_t) { return false; }), halvesSlabUnits(snap_mm));
}

TEST(MirroredFloor, TheLowestKeptValueStandsOnTheBed) {
    const HexField field = test::fieldFromRows({{1.0, 2.0, 3.0, NAN}});
    const std::vector<uint8_t> keep = {1, 0, 1, 1};  // the cell of height 3 is culled
    SceneParams p = test::smallParams(Bottom::Mirrored);
    CellHeights h;
    h.units = {5, 3, 7, 0};
    EXPECT_EQ(lowerToMirroredFloor(field, keep, p, 0, h), 5);
    EXPECT_EQ(h.units, (std::vector<int64_t>{0, 0, 2, 0}));
}

TEST(MirroredFloor, ATextureKeepsItsReliefBelowTheLowestCell) {
    const HexField field = test::fieldFromRows({{1.0, 2.0}});
    CellHeights h;
    h.units = {5, 9};
    EXPECT_EQ(lowerToMirroredFloor(field, {1, 1}, test::smallParams(Bottom::Mirrored), 2, h), 3);
    EXPECT_EQ(h.units, (std::vector<int64_t>{2, 6}));
}

TEST(MirroredFloor, FlatOrTiltedModelsKeepTheirHeights) {
    const HexField field = test::fieldFromRows({{1.0, 2.0}});
    CellHeights h;
    h.units = {5, 9};
    EXPECT_EQ(lowerToMirroredFloor(field, {1, 1}, test::smallParams(Bottom::Flat), 0, h), 0);
    SceneParams tilted = test::smallParams(Bottom::Mirrored);
    tilted.tilt = TiltSource::Gradient;
    EXPECT_EQ(lowerToMirroredFloor(field, {1, 1}, tilted, 0, h), 0);
    EXPECT_EQ(h.units, (std::vector<int64_t>{5, 9}));
}

TEST(KeptCells, NothingAboveTheFloorKeepsTheWholeGridAndSaysSo) {
    const HexField field = test::fieldFromRows({{0.0, 0.0, 0.0}, {0.0, NAN, 0.0}});
    CellHeights h;
    h.units.assign(6, 0);
    h.nonempty.assign(6, 0);
    const KeptCells kept = cullCells(field, h, test::smallParams(Bottom::Flat, Cull::Hull));
    EXPECT_EQ(kept.keep, (std::vector<uint8_t>(6, 1)));
    ASSERT_EQ(kept.notes.size(), 1u);
    EXPECT_NE(kept.notes[0].find("flat slab"), std::string::npos);
}

TEST(KeptCells, ATileShareInTwoPiecesIsAnInputError) {
    const HexField field = test::fieldFromRows({{1.0, 1.0, 1.0, 1.0, 1.0}});
    SceneParams p = test::smallParams();
    p.requests.set(TileRequest{{1, 0, 0, 0, 1}, {}, std::nullopt});  // the two ends of a row: not one piece
    std::vector<uint8_t> keep(5, 1);
    EXPECT_THROW(keepTileShare(field.grid, p, keep), InputError);
    p.requests.set(TileRequest{{1, 1, 0, 0, 0}, {}, std::nullopt});
    keep.assign(5, 1);
    keepTileShare(field.grid, p, keep);
    EXPECT_EQ(keep, (std::vector<uint8_t>{1, 1, 0, 0, 0}));
}

// Heights as the cull reads them: a cell with data is non-empty.
CellHeights heightsOf(const HexField& f) {
    CellHeights h;
    for (double v : f.values) {
        h.units.push_back(std::isnan(v) ? 0 : 1000);
        h.nonempty.push_back(std::isnan(v) ? 0 : 1);
        h.nonempty_count += std::isnan(v) ? 0 : 1;
    }
    return h;
}

// A kept cell without data with a side on the outside (a cell left out, or
// beyond the grid).
int rimCellsWithoutData(const HexField& f, const std::vector<uint8_t>& keep) {
    int n = 0;
    for (int32_t r = 0; r < f.grid.rows; ++r)
        for (int32_t c = 0; c < f.grid.cols; ++c) {
            const size_t idx = size_t(f.grid.index(c, r));
            if (!keep[idx] || !std::isnan(f.values[idx])) continue;
            for (int e = 0; e < kHexCorners; ++e) {
                int32_t nc = 0, nr = 0;
                hexNeighbour(c, r, e, nc, nr);
                if (!f.grid.contains(nc, nr) || !keep[size_t(f.grid.index(nc, nr))]) {
                    ++n;
                    break;
                }
            }
        }
    return n;
}

// Data that ends on a slant (a rotated raster resampled north-up): the
// convex hull's edges cross the hexagons' staircase and kept a row of
// no-data pits along the rim, which a reader took for missing values and
// which left the orientation tab no pillars to stand against. Every slant,
// both ways: every cell with data kept, no pit on the rim, one piece, and
// the no-data cell inside the data still a pit.
TEST(KeptCells, DataEndingOnASlantKeepsNoPitsAlongItsEdge) {
    int had_rim_pits = 0;
    for (const double slope : {0.3, 0.5, 0.58, 1.0, 1.7, -0.5, -1.2}) {
        std::vector<std::vector<double>> rows(24, std::vector<double>(24, NAN));
        for (int r = 0; r < 24; ++r)
            for (int c = 0; c < 24; ++c) {
                const double x = c - 12, y = 12 - r;
                // A band between two parallel slanted lines, cut square north and south.
                if (std::fabs(y - slope * x) < 6.0 && std::abs(r - 12) < 9) rows[size_t(r)][size_t(c)] = 1 + r + c;
            }
        rows[12][12] = NAN;  // no data inside the data
        const HexField field = test::fieldFromRows(rows);
        const KeptCells kept = cullCells(field, heightsOf(field), test::smallParams(Bottom::Flat, Cull::Hull));
        for (size_t idx = 0; idx < field.values.size(); ++idx)
            if (!std::isnan(field.values[idx])) ASSERT_TRUE(kept.keep[idx]) << "slope " << slope << ": a value left out";
        EXPECT_EQ(rimCellsWithoutData(field, kept.keep), 0) << "slope " << slope;
        EXPECT_EQ(componentCount(field.grid, kept.keep), 1) << "slope " << slope;
        EXPECT_TRUE(kept.keep[size_t(field.grid.index(12, 12))]) << "slope " << slope << ": the pit inside the data";
        // What the plain convex hull keeps: the pits this removes were there.
        std::vector<LatticePoint> centres;
        for (int32_t r = 0; r < 24; ++r)
            for (int32_t c = 0; c < 24; ++c)
                if (!std::isnan(field.at(c, r))) centres.push_back(hexCentre(field.grid, c, r));
        const std::vector<LatticePoint> hull = convexHull(centres);
        std::vector<uint8_t> convex(field.values.size(), 0);
        for (int32_t r = 0; r < 24; ++r)
            for (int32_t c = 0; c < 24; ++c) convex[size_t(field.grid.index(c, r))] = hullContains(hull, hexCentre(field.grid, c, r));
        had_rim_pits += rimCellsWithoutData(field, convex) > 0;
    }
    EXPECT_GE(had_rim_pits, 4) << "the slants must be ones where the hull alone keeps rim pits";
}

// A no-data cell that holds the model together stays (a pit), as do all of
// them then: the model is one piece.
TEST(KeptCells, ARimCellWithoutDataThatHoldsTheModelTogetherStays) {
    const HexField field = test::fieldFromRows({{1.0, NAN, 1.0}});
    const KeptCells kept = cullCells(field, heightsOf(field), test::smallParams(Bottom::Flat, Cull::Hull));
    EXPECT_EQ(kept.keep, (std::vector<uint8_t>{1, 1, 1}));
}

}  // namespace
}  // namespace tsf
