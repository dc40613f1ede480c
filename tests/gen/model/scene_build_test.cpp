// buildScene's phases alone (gen/model/phases/), on hand-made data: the
// halves' slab search, the mirrored floor and the cull's edge cases.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "gen/model/phases/cell_heights.h"
#include "gen/model/phases/halves_slab.h"
#include "gen/model/phases/kept_cells.h"
#include "gen/model/features/halves.h"
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

}  // namespace
}  // namespace tsf
