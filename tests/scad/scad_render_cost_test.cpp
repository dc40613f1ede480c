// scadRenderWarning: silent for a grid the engines render quickly, and a
// warning with the cell count, seconds and gigabytes for one they do not.
#include <gtest/gtest.h>

#include "gen/scad/scad_render_cost.h"
#include "tests/support/fields.h"
#include "gen/model/build_scene.h"

namespace tsf {
namespace {

Scene sceneOf(int cols, int rows) {
    SceneParams p;
    p.cull = Cull::None;
    return buildScene(test::fieldFromFunction(cols, rows, [](int c, int r) { return 1.0 + (c * 7 + r * 3) % 5; }), p);
}

TEST(ScadRenderCost, SmallGridIsSilent) {
    const ScadRenderCost c = estimateScadRender(sceneOf(40, 40), ScadOptions::Strategy::Polyhedron);
    EXPECT_EQ(c.cells, 1600u);
    EXPECT_TRUE(c.desktop_2021.within);
    EXPECT_TRUE(c.wasm_2025.within);
    EXPECT_EQ(scadRenderWarning(c, "m.scad"), "");
}

TEST(ScadRenderCost, LargeGridWarnsWithTheNumbers) {
    const ScadRenderCost c = estimateScadRender(sceneOf(400, 400), ScadOptions::Strategy::Polyhedron);
    EXPECT_EQ(c.cells, 160000u);
    EXPECT_FALSE(c.wasm_2025.within);
    EXPECT_GT(c.desktop_2021.seconds, 10.0);
    EXPECT_GT(c.desktop_2021.peak_mb, 1000.0);
    const std::string w = scadRenderWarning(c, "m.scad");
    EXPECT_NE(w.find("m.scad has 160000 cells"), std::string::npos) << w;
    EXPECT_NE(w.find("OpenSCAD 2021.01 about "), std::string::npos) << w;
    EXPECT_NE(w.find(" GB"), std::string::npos) << w;
}

TEST(ScadRenderCost, CsgIsSlowerThanThePolyhedronForTheSameCells) {
    const Scene s = sceneOf(100, 100);
    const ScadRenderCost poly = estimateScadRender(s, ScadOptions::Strategy::Polyhedron);
    const ScadRenderCost csg = estimateScadRender(s, ScadOptions::Strategy::Csg);
    EXPECT_GT(csg.desktop_2021.seconds, 10 * poly.desktop_2021.seconds);
    EXPECT_FALSE(csg.desktop_2021.within);  // CGAL did not finish 10 000 cells in 15 minutes
    EXPECT_NE(scadRenderWarning(csg, "m.scad"), "");
}

}  // namespace
}  // namespace tsf
