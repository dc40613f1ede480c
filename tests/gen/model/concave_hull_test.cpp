// --cull concave: fewer empty cells than the convex hull, never a cell with a
// value left out, one piece, one rim; checked on the mesh by the verifier.
#include <gtest/gtest.h>

#include "gen/model/concave_hull.h"
#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "tests/support/mesh_invariants.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {
using test::fieldFromFunction;

// Four islands of data in the corners of an empty 30 x 30 field, and a ring.
HexField islands() {
    return fieldFromFunction(30, 30, [](int c, int r) {
        const bool corner = (c < 4 || c > 25) && (r < 4 || r > 25);
        return corner ? 1.0 + (c + r) % 3 : 0.0;
    });
}

SceneParams params(Cull cull, Bottom bottom = Bottom::Flat) {
    SceneParams p = test::smallParams(bottom, cull);
    return p;
}

TEST(ConcaveHull, SparseIslandsKeepFewerCellsInOnePiece) {
    for (Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        const Scene convex = buildScene(islands(), params(Cull::Hull, bottom));
        const Scene concave = buildScene(islands(), params(Cull::Concave, bottom));
        EXPECT_LT(concave.keptCount(), convex.keptCount() / 2);
        EXPECT_EQ(concave.cells_convex, int64_t(convex.keptCount()));
        EXPECT_GT(concave.volume_saved_mm3, 0);
        // Every non-empty cell is still there.
        const HexField field = islands();
        for (int32_t r = 0; r < field.grid.rows; ++r)
            for (int32_t c = 0; c < field.grid.cols; ++c)
                if (field.at(c, r) > 0) EXPECT_GE(concave.keptAt(c, r), 0) << c << "," << r;
        const Mesh mesh = meshScene(concave);
        const test::Invariants inv = test::checkInvariants(mesh);
        EXPECT_TRUE(inv.closedManifold()) << inv.describe();
        EXPECT_EQ(inv.components, 1u);
        EXPECT_EQ(inv.euler, 2);  // one piece without a hole through it
        const VerifyReport r = verifyModel(mesh, &concave, VerifyOptions{});
        EXPECT_TRUE(r.passed()) << formatReport(r);
        // Less material than the convex hull by about what the summary says.
        const double v_convex = signedVolume(meshScene(convex));
        EXPECT_NEAR(v_convex - signedVolume(mesh), concave.volume_saved_mm3, 0.01 * concave.volume_saved_mm3);
    }
}

TEST(ConcaveHull, NarrowGapsAreFilledAndWideBaysStayOpen) {
    // A C shape: the bay is 10 cells wide; a 1-cell notch in its back wall is filled.
    const HexField f = fieldFromFunction(20, 20, [](int c, int r) {
        const bool wall = c < 4 || r < 4 || r > 15;
        const bool notch = c == 2 && r == 10;
        return wall && !notch ? 5.0 : 0.0;
    });
    const Scene s = buildScene(f, params(Cull::Concave));
    EXPECT_GE(s.keptAt(2, 10), 0);   // the one-cell gap is closed
    EXPECT_LT(s.keptAt(12, 10), 0);  // the middle of the wide bay stays open
    const Scene convex = buildScene(f, params(Cull::Hull));
    EXPECT_GE(convex.keptAt(12, 10), 0);
}

TEST(ConcaveHull, EnclosedEmptyCellsAreKeptSoThereIsOneRim) {
    // A ring of data around a wide empty middle: the middle is kept (no hole through the model).
    const HexField f = fieldFromFunction(20, 20, [](int c, int r) {
        const bool ring = c < 3 || c > 16 || r < 3 || r > 16;
        return ring ? 2.0 : 0.0;
    });
    const Scene s = buildScene(f, params(Cull::Concave));
    EXPECT_GE(s.keptAt(10, 10), 0);
    const test::Invariants inv = test::checkInvariants(meshScene(s));
    EXPECT_EQ(inv.euler, 2);
}

TEST(ConcaveHull, LibraryJoinsPiecesInsideTheConvexRegion) {
    const HexGrid g{9, 3};
    std::vector<uint8_t> anchor(27, 0), convex(27, 1);
    anchor[size_t(g.index(0, 1))] = 1;
    anchor[size_t(g.index(8, 1))] = 1;
    const std::vector<uint8_t> keep = concaveKeep(g, anchor, convex, 1);
    EXPECT_EQ(componentCount(g, keep), 1);
    for (size_t i = 0; i < keep.size(); ++i)
        if (anchor[i]) EXPECT_TRUE(keep[i]);
    size_t kept = 0;
    for (uint8_t k : keep) kept += k;
    EXPECT_LT(kept, 27u);  // a path, not the whole grid
}

}  // namespace
}  // namespace tsf
