// Tiles of a model larger than the bed (gen/model/features/tiles.h,
// pipeline/verified_tiles.h, verify/tiles_check.h): every cell in exactly
// one tile at its height, each tile one piece that fits the bed, dovetail
// teeth that lock, the code pitted under each tile, and an assembly check
// that catches a tile put together wrong.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/attachments.h"
#include "gen/model/build_scene.h"
#include "gen/model/feature_registry.h"
#include "gen/model/features/tab/tab_state.h"
#include "gen/model/features/tiles.h"
#include "pipeline/verified_tiles.h"
#include "tests/support/fields.h"
#include "tests/support/input_error.h"
#include "tests/support/mesh_invariants.h"
#include "verify/overhang.h"

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;

HexField hill() {
    return test::fieldFromFunction(60, 36, [](int c, int r) { return 2.0 + std::sin(c * 0.2) + std::cos(r * 0.25); });
}

// 4 mm cells: about 242 x 125 mm, with the orientation marks on the tab.
SceneParams hillParams() {
    SceneParams p = test::smallParams();
    p.marks = MarkParams{};
    p.pitch_mm = 4.0;
    return p;
}

constexpr double kBedW = 90, kBedD = 90;  // a 100 x 100 mm bed less 5 mm each side

TEST(TilePlan, EveryCellInOneTileEachTileWholeAndOnTheBed) {
    const Scene s = buildScene(hill(), hillParams());
    ASSERT_TRUE(sceneTab(s));
    const TileLayout L = planTiles(s, attachmentBoxes(s), kBedW, kBedD);
    EXPECT_GE(L.rows * L.cols, 6);  // 267 x 125 mm with the tab cannot go in fewer than 3 x 2
    EXPECT_LE(L.rows * L.cols, 12);
    std::vector<int64_t> cells(size_t(L.rows * L.cols), 0);
    for (size_t k = 0; k < s.keptCount(); ++k) {
        const int32_t t = L.tile_of_cell[size_t(s.grid.index(s.col[k], s.row[k]))];
        ASSERT_GE(t, 0);
        ASSERT_LT(t, L.rows * L.cols);
        ++cells[size_t(t)];
    }
    for (int32_t t = 0; t < L.rows * L.cols; ++t) {
        EXPECT_EQ(cells[size_t(t)], L.cells[size_t(t)]);
        if (cells[size_t(t)] == 0) continue;
        std::vector<uint8_t> mask(L.tile_of_cell.size(), 0);
        for (size_t i = 0; i < mask.size(); ++i) mask[i] = L.tile_of_cell[i] == t;
        EXPECT_EQ(componentCount(s.grid, mask), 1) << "tile " << t;
    }
    // Each tile's cells (and the tab on the marks' tile) fit the bed, from the Scene's corners.
    for (int32_t t = 0; t < L.rows * L.cols; ++t) {
        double x0 = 1e9, x1 = -1e9, y0 = 1e9, y1 = -1e9;
        for (size_t k = 0; k < s.keptCount(); ++k) {
            if (L.tile_of_cell[size_t(s.grid.index(s.col[k], s.row[k]))] != t) continue;
            for (int e = 0; e < 6; ++e) {
                const Vec3 p = s.point(hexCorner(s.grid, s.col[k], s.row[k], e), 0);
                x0 = std::min(x0, p.x), x1 = std::max(x1, p.x), y0 = std::min(y0, p.y), y1 = std::max(y1, p.y);
            }
        }
        if (t == L.marks_tile) {
            x0 = std::min(x0, -23.0);  // the tab, 23 mm west of the pillars
        }
        if (x0 > x1) continue;
        EXPECT_LE(x1 - x0, kBedW + 1e-9) << "tile " << t;
        EXPECT_LE(y1 - y0, kBedD + 1e-9) << "tile " << t;
    }
    // The tab's cells and the marks are in one tile.
    ASSERT_GE(L.marks_tile, 0);
    for (const auto& [k, e] : sceneTab(s)->touched)
        EXPECT_EQ(L.tile_of_cell[size_t(s.grid.index(s.col[size_t(k)], s.row[size_t(k)]))], L.marks_tile);
}

// A dovetail locks: along a lattice row across a vertical seam the east
// tile holds a cell between two cells of the west tile (the cell the head
// of a tooth hooks behind), and down a lattice column across a horizontal
// seam the south tile holds one between two of the north tile.
TEST(TilePlan, TeethLockTheSeams) {
    const Scene s = buildScene(hill(), hillParams());
    const TileLayout L = planTiles(s, attachmentBoxes(s), kBedW, kBedD);
    ASSERT_GT(L.seams, 0);
    EXPECT_EQ(L.bare_seams, 0);  // a plain rectangle of cells: every seam has room for a tooth
    EXPECT_GE(L.teeth, L.seams);
    const auto tileAt = [&](int32_t c, int32_t r) {
        return s.keptAt(c, r) < 0 ? -1 : L.tile_of_cell[size_t(s.grid.index(c, r))];
    };
    // Pairs of tiles (either order) where one holds a cell between two of the other's.
    std::set<std::pair<int32_t, int32_t>> locked;
    const auto hooked = [&](int32_t a, int32_t b, int32_t d) {
        if (a >= 0 && b >= 0 && a == d && b != a) locked.insert({std::min(a, b), std::max(a, b)});
    };
    for (int32_t r = 0; r < s.grid.rows; ++r)
        for (int32_t c = 0; c + 2 < s.grid.cols; ++c) hooked(tileAt(c, r), tileAt(c + 1, r), tileAt(c + 2, r));
    for (int32_t c = 0; c < s.grid.cols; ++c)
        for (int32_t r = 0; r + 2 < s.grid.rows; ++r) {
            // Down a column of the lattice: (c, r), its south-east neighbour, that one's south-west.
            int32_t nc, nr, mc, mr;
            hexNeighbour(c, r, 5, nc, nr);
            hexNeighbour(nc, nr, 4, mc, mr);
            hooked(tileAt(c, r), tileAt(nc, nr), tileAt(mc, mr));
        }
    // Every seam the plan toothed locks (and nothing else does: a straight zigzag seam has no hook).
    EXPECT_EQ(int32_t(locked.size()), L.seams - L.bare_seams);
}

TEST(TilePlan, RefusesWhatItCannotCutYet) {
    SceneParams mirrored = hillParams();
    mirrored.bottom = Bottom::Mirrored;
    const Scene m = buildScene(hill(), mirrored);
    EXPECT_THROW(planTiles(m, attachmentBoxes(m), kBedW, kBedD), InputError);
    SceneParams big = hillParams();
    big.pitch_mm = 30;
    const Scene b = buildScene(hill(), big);
    EXPECT_THROW(planTiles(b, attachmentBoxes(b), kBedW, kBedD), InputError);  // cells too large for the bed
}

// The 16-gon code pit's volume from its radius and heights alone (not the
// code's rings): a prism one wall high and a cone to the apex.
double pitVolume(const Scene& tile) {
    const double r = sceneTile(tile)->pit_radius_mm;
    const double area = 0.5 * kHoleSides * r * r * std::sin(2 * kPi / kHoleSides);
    double v = 0;
    for (const BottomHole& h : sceneTile(tile)->code_pits)
        v += area * (tile.zMm(h.depth_units) + tile.zMm(h.apex_units - h.depth_units) / 3);
    return v;
}

TEST(Tiles, EachTileVerifiedAndTogetherTheyAreTheModel) {
    const HexField f = hill();
    const Scene s = buildScene(f, hillParams());
    ModelRequest rq;
    const VerifiedTiles v = makeVerifiedTiles(f, s, kBedW, kBedD, rq);
    ASSERT_TRUE(v.assembly);
    EXPECT_TRUE(v.assembly->passed());
    ASSERT_GE(v.tiles.size(), 6u);
    double tiles_volume = 0, pits = 0;
    size_t with_marks = 0;
    for (const VerifiedTile& t : v.tiles) {
        ASSERT_TRUE(t.model.report);
        EXPECT_TRUE(t.model.report->passed());
        const test::Invariants inv = test::checkInvariants(t.model.mesh);
        EXPECT_TRUE(inv.closedManifold());
        EXPECT_EQ(measureOverhang(t.model.mesh).area_mm2, 0.0);  // the code pits print face down
        const Bounds b = meshBounds(t.model.mesh);
        EXPECT_LE(b.max.x - b.min.x, kBedW + 1e-6);
        EXPECT_LE(b.max.y - b.min.y, kBedD + 1e-6);
        // The code: a corner pit, one per column number east, one per row number south.
        const SceneTile& st = *sceneTile(t.scene);
        ASSERT_EQ(st.code_cells.size(), size_t(st.place.row + st.place.col + 3)) << tileName(st.place);
        const size_t corner = size_t(st.code_cells[0]);
        for (int32_t e = 1; e <= st.place.col + 1; ++e) {
            const size_t k = size_t(st.code_cells[size_t(e)]);
            EXPECT_EQ(t.scene.row[k], t.scene.row[corner]);
            EXPECT_GT(t.scene.col[k], t.scene.col[corner]);
        }
        for (int32_t n = 1; n <= st.place.row + 1; ++n) {
            const size_t k = size_t(st.code_cells[size_t(st.place.col + 1 + n)]);
            EXPECT_EQ(t.scene.col[k], t.scene.col[corner]);
            EXPECT_GT(t.scene.row[k], t.scene.row[corner]);  // rows count south
        }
        with_marks += sceneTab(t.scene) != nullptr;
        tiles_volume += signedVolume(t.model.mesh);
        pits += pitVolume(t.scene);
    }
    EXPECT_EQ(with_marks, 1u);
    // The tiles' material is the one-piece model's (pillars, tab, notch) less the pits.
    const double expected = signedVolume(meshScene(s)) - pits;
    EXPECT_NEAR(tiles_volume, expected, 1e-3 * pits);
    // The pillars of the model: every tile's cells are the model's, at their spans.
    double model_pillars = 0, tile_pillars = 0;
    model_pillars = test::sceneVolume(s);
    for (const VerifiedTile& t : v.tiles) tile_pillars += test::sceneVolume(t.scene);
    EXPECT_NEAR(tile_pillars, model_pillars, 1e-9 * model_pillars);
}

// Marks in the data (the notch cut into the corner pillars, the triangle on
// the largest flat region) are drawn on the tiles where the model has them,
// each whole on one tile, and no other tile gets marks of its own.
TEST(Tiles, MarksInTheDataStayWhereTheModelHasThem) {
    // The hill, with a plateau in the east for the triangle.
    const HexField f = test::fieldFromFunction(60, 36, [](int c, int r) {
        return c > 40 && r > 8 && r < 28 ? 4.0 : 2.0 + std::sin(c * 0.2) + std::cos(r * 0.25);
    });
    SceneParams p = hillParams();
    p.marks.place = MarkPlace::Data;
    p.cull = Cull::None;
    const Scene s = buildScene(f, p);
    ASSERT_TRUE(s.marks.notch);
    ASSERT_TRUE(s.marks.triangle);
    const VerifiedTiles v = makeVerifiedTiles(f, s, kBedW, kBedD, ModelRequest{});
    ASSERT_TRUE(v.assembly);
    EXPECT_TRUE(v.assembly->passed());
    int notches = 0, triangles = 0;
    for (const VerifiedTile& t : v.tiles) {
        if (t.scene.marks.notch) {
            ++notches;
            EXPECT_EQ(t.scene.marks.notch->apex.i, s.marks.notch->apex.i);
            EXPECT_EQ(t.scene.marks.notch->apex.j, s.marks.notch->apex.j);
        }
        if (t.scene.marks.triangle) {
            ++triangles;
            EXPECT_EQ(t.scene.marks.triangle->corner.i, s.marks.triangle->corner.i);
            EXPECT_EQ(t.scene.marks.triangle->corner.j, s.marks.triangle->corner.j);
        }
    }
    EXPECT_EQ(notches, 1);
    EXPECT_EQ(triangles, 1);
}

TEST(Tiles, TheAssemblyCheckCatchesAWrongTile) {
    const HexField f = hill();
    const Scene s = buildScene(f, hillParams());
    const VerifiedTiles v = makeVerifiedTiles(f, s, kBedW, kBedD, ModelRequest{});
    std::vector<const Scene*> scenes;
    std::vector<const Mesh*> meshes;
    for (const VerifiedTile& t : v.tiles) {
        scenes.push_back(&t.scene);
        meshes.push_back(&t.model.mesh);
    }
    const Mesh whole = meshScene(s);
    const TilesCheckInput in{kBedW, kBedD, v.layout.seams, v.layout.bare_seams, v.layout.teeth};
    // The model the tiles make up keeps the code cells level (no dimples
    // here: not binned points), so the plain model is the reference.
    EXPECT_TRUE(checkTiles(s, whole, scenes, meshes, in).passed());

    // A pillar a step too high in one tile.
    Scene raised = v.tiles[1].scene;
    raised.top[3] += 1;
    std::vector<const Scene*> wrong = scenes;
    wrong[1] = &raised;
    const TilesCheckResult r1 = checkTiles(s, whole, wrong, meshes, in);
    EXPECT_FALSE(r1.passed());
    EXPECT_EQ(r1.checks[0].id, "tiles_cells");
    EXPECT_EQ(r1.checks[0].status, CheckStatus::Fail);

    // A tile left out: its cells are missing and the material is short.
    std::vector<const Scene*> fewer(scenes.begin() + 1, scenes.end());
    std::vector<const Mesh*> fewer_meshes(meshes.begin() + 1, meshes.end());
    const TilesCheckResult r2 = checkTiles(s, whole, fewer, fewer_meshes, in);
    EXPECT_EQ(r2.checks[0].status, CheckStatus::Fail);
    EXPECT_EQ(r2.checks[1].status, CheckStatus::Fail);

    // One tile's mesh twice (another tile's printed in its place).
    std::vector<const Mesh*> swapped = meshes;
    swapped[0] = meshes[1];
    EXPECT_EQ(checkTiles(s, whole, scenes, swapped, in).checks[1].status, CheckStatus::Fail);

    // A bed smaller than the tiles.
    TilesCheckInput small = in;
    small.bed_width_mm = 20;
    EXPECT_EQ(checkTiles(s, whole, scenes, meshes, small).checks[2].status, CheckStatus::Fail);
}

// Binned points: the structural cells carry dimples; a code pit goes under
// a level top, and the model the tiles make up is the one with those cells
// level (so the assembly check compares like with like).
TEST(Tiles, CodeCellsOfStructuralCellsStayLevel) {
    HexField f = test::asBinnedPoints(test::fieldFromFunction(60, 36, [](int c, int r) {
        return (c * 7 + r * 3) % 11 == 0 ? 3.0 : 0.0;
    }));
    SceneParams p = hillParams();
    p.structural_texture = true;
    const Scene s = buildScene(f, p);
    ASSERT_GT(s.shapes.cells_textured, 0);
    const VerifiedTiles v = makeVerifiedTiles(f, s, kBedW, kBedD, ModelRequest{});
    ASSERT_TRUE(v.assembly);
    EXPECT_TRUE(v.assembly->passed());
    for (const VerifiedTile& t : v.tiles)
        for (int32_t k : sceneTile(t.scene)->code_cells) EXPECT_FALSE(isStructural(t.scene.shapes, size_t(k)));
}

// A tile reaches the mesher, the read-back and the dimples through the
// registry (gen/model/feature_registry.h) as a piece of the model: its
// share of the cells, its code pits as cuts into the bottom, its code
// cells kept level; a whole model has none of them.
TEST(Tiles, ATileIsAPieceOfTheModelThroughTheRegistry) {
    const HexField f = hill();
    const Scene s = buildScene(f, hillParams());
    EXPECT_EQ(sceneTile(s), nullptr);
    EXPECT_TRUE(featureBottomHoles(s).empty());
    const TileLayout L = planTiles(s, attachmentBoxes(s), kBedW, kBedD);
    ASSERT_GT(L.rows * L.cols, 1);
    const SceneParams p = tileParams(s, L, 0);
    std::vector<uint8_t> keep(size_t(f.grid.cellCount()), 1);
    keepFeatureShares(f.grid, p, keep);
    EXPECT_EQ(keep, p.requests.get<TileRequest>()->cells);
    const Scene tile = buildScene(f, p);
    const SceneTile* t = sceneTile(tile);
    ASSERT_NE(t, nullptr);
    ASSERT_FALSE(t->code_cells.empty()) << (tile.notes.empty() ? "" : tile.notes.back());
    EXPECT_EQ(featureBottomHoles(tile).size(), t->code_pits.size());
    EXPECT_EQ(sceneBottomHoles(tile).size(), t->code_pits.size());
    for (int32_t k : t->code_cells) EXPECT_TRUE(featureKeepsLevel(tile, size_t(k)));
    size_t level = 0;
    for (size_t k = 0; k < tile.keptCount(); ++k) level += featureKeepsLevel(tile, k);
    EXPECT_EQ(level, t->code_cells.size());
}

}  // namespace
}  // namespace tsf
