// The engine output check: a broken mesh is an engine failure.
#include <gtest/gtest.h>

#include <filesystem>

#include "engine_fixtures.h"
#include "gen/mesh/direct_mesher.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/mesh_io/stl_reader.h"
#include "runners/openscad/engine_output_check.h"
#include "gen/model/build_scene.h"

namespace tsf {
namespace {

namespace fs = std::filesystem;

//        3 (0,0,1)
//        |
//        0 ---- 1 (1,0,0)      corner tetrahedron, volume 1/6,
//       /                      faces counter-clockwise seen from outside
//      2 (0,1,0)
Mesh tetrahedron(double scale = 1, Vec3 offset = {}) {
    Mesh m;
    m.positions = {{offset.x, offset.y, offset.z},
                   {offset.x + scale, offset.y, offset.z},
                   {offset.x, offset.y + scale, offset.z},
                   {offset.x, offset.y, offset.z + scale}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

TEST(EngineOutputCheck, ClosedOutwardTetrahedronPasses) {
    const EngineOutputCheck c = checkEngineMesh(tetrahedron());
    EXPECT_TRUE(c.checked);
    EXPECT_TRUE(c.ok) << c.problem;
    EXPECT_EQ(c.triangles, 4u);
    EXPECT_EQ(c.pieces, 1u);
    EXPECT_NEAR(c.volume_mm3, 1.0 / 6.0, 1e-15);
}

TEST(EngineOutputCheck, ExpectedVolumeMustMatch) {
    EngineOutputExpectation right{1.0 / 6.0};
    EXPECT_TRUE(checkEngineMesh(tetrahedron(), right).ok);
    EngineOutputExpectation wrong{1.0 / 6.0 * (1 + 1e-3)};
    const EngineOutputCheck c = checkEngineMesh(tetrahedron(), wrong);
    EXPECT_FALSE(c.ok);
    EXPECT_NE(c.problem.find("volume"), std::string::npos) << c.problem;
}

TEST(EngineOutputCheck, MissingTriangleIsOpen) {
    Mesh m = tetrahedron();
    m.triangles.pop_back();
    const EngineOutputCheck c = checkEngineMesh(m);
    EXPECT_FALSE(c.ok);
    EXPECT_EQ(c.open_edges, 3u);
    EXPECT_NE(c.problem.find("not a closed"), std::string::npos) << c.problem;
}

TEST(EngineOutputCheck, InsideOutIsRefused) {
    Mesh m = tetrahedron();
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
    const EngineOutputCheck c = checkEngineMesh(m);
    EXPECT_FALSE(c.ok);
    EXPECT_EQ(c.open_edges, 0u);
    EXPECT_LT(c.volume_mm3, 0);
    EXPECT_NE(c.problem.find("inward"), std::string::npos) << c.problem;
}

TEST(EngineOutputCheck, OneFlippedTriangleIsInconsistent) {
    Mesh m = tetrahedron();
    std::swap(m.triangles[3][1], m.triangles[3][2]);
    const EngineOutputCheck c = checkEngineMesh(m);
    EXPECT_FALSE(c.ok);
    EXPECT_GT(c.overused_edges, 0u);
}

TEST(EngineOutputCheck, TwoPiecesAreRefused) {
    Mesh m = tetrahedron();
    const Mesh other = tetrahedron(1, {5, 0, 0});
    for (const auto& t : other.triangles) m.triangles.push_back({t[0] + 4, t[1] + 4, t[2] + 4});
    m.positions.insert(m.positions.end(), other.positions.begin(), other.positions.end());
    const EngineOutputCheck c = checkEngineMesh(m);
    EXPECT_FALSE(c.ok);
    EXPECT_EQ(c.pieces, 2u);
    EXPECT_NE(c.problem.find("2 pieces"), std::string::npos) << c.problem;
}

TEST(EngineOutputCheck, EdgeSharedByFourTrianglesIsRefused) {
    // Two tetrahedra glued along the edge 0-1 only (what a union of touching
    // prisms with rounding noise gives once STL rounds the noise away).
    Mesh m = tetrahedron();
    m.positions.push_back({0, -1, 0});   // 4
    m.positions.push_back({0, 0, -1});   // 5
    // The first one turned 180 degrees about x (2 -> 4, 3 -> 5): still outward.
    m.triangles.push_back({0, 4, 1});
    m.triangles.push_back({0, 1, 5});
    m.triangles.push_back({0, 5, 4});
    m.triangles.push_back({1, 4, 5});
    const EngineOutputCheck c = checkEngineMesh(m);
    EXPECT_FALSE(c.ok);
    EXPECT_GT(c.overused_edges, 0u) << c.problem;
}

TEST(EngineOutputCheck, RepeatedVertexAndEmptyMeshAreRefused) {
    Mesh m = tetrahedron();
    m.triangles.push_back({1, 1, 2});
    EXPECT_EQ(checkEngineMesh(m).degenerate_triangles, 1u);
    EXPECT_FALSE(checkEngineMesh(m).ok);
    const EngineOutputCheck empty = checkEngineMesh(Mesh{});
    EXPECT_FALSE(empty.ok);
    EXPECT_NE(empty.problem.find("no triangles"), std::string::npos);
}

// The volume tolerance covers the float32 rounding of an STL file, and no more:
// a real model written to STL matches the direct mesher's exact volume, the
// same model one snap step lower in one cell does not.
TEST(EngineOutputCheck, StlRoundingIsWithinToleranceButOneStepIsNot) {
    const Scene scene = buildScene(test::smallTerrain(), test::terrainParams(Bottom::Flat));
    const Mesh direct = meshScene(scene);
    const fs::path dir = test::scratchDir("output_check_rounding");
    writeMesh(direct, (dir / "m.stl").string());
    const Mesh read = readStl((dir / "m.stl").string());
    const EngineOutputCheck c = checkEngineMesh(read, {signedVolume(direct)});
    EXPECT_TRUE(c.ok) << c.problem;
    EXPECT_GT(c.volume_tolerance_mm3, 0);

    Scene lower = scene;
    lower.top[0] -= 1;  // one z snap step (0.01 mm) in one cell
    const double hex_area_mm2 = 1.5 * std::sqrt(3.0) * std::pow(scene.pitch_mm / std::sqrt(3.0), 2);
    ASSERT_GT(hex_area_mm2 * scene.z_snap_mm, c.volume_tolerance_mm3) << "the tolerance would hide one step";
    const EngineOutputCheck off = checkEngineMesh(read, {signedVolume(meshScene(lower))});
    EXPECT_FALSE(off.ok);
}

// Closed and consistently oriented by the indices, one piece, the right
// volume - but one triangle has no area: a vertex on the middle of edge 0-1
// splits face {0,1,3} in two, and the needle {0,1,4} closes the surface.
Mesh tetrahedronWithANeedle() {
    Mesh m = tetrahedron();
    m.positions.push_back({0.5, 0, 0});  // 4
    m.triangles = {{0, 2, 1}, {0, 3, 2}, {1, 2, 3}, {0, 4, 3}, {4, 1, 3}, {0, 1, 4}};
    return m;
}

TEST(EngineOutputCheck, SolidChecksRunLastAndOnlyWhenAsked) {
    const Mesh needle = tetrahedronWithANeedle();
    const EngineOutputCheck topological = checkEngineMesh(needle);
    EXPECT_TRUE(topological.ok) << "the indices alone cannot see a zero-area triangle: " << topological.problem;
    EXPECT_NEAR(topological.volume_mm3, 1.0 / 6.0, 1e-15);

    EngineOutputExpectation expect;
    expect.solid_checks = true;
    const EngineOutputCheck solid = checkEngineMesh(needle, expect);
    EXPECT_FALSE(solid.ok);
    EXPECT_NE(solid.problem.find("(1) at (0.500, 0.000, 0.000) mm"), std::string::npos) << solid.problem;
    EXPECT_TRUE(checkEngineMesh(tetrahedron(), expect).ok);

    Mesh open = tetrahedron();
    open.triangles.pop_back();
    EXPECT_NE(checkEngineMesh(open, expect).problem.find("not a closed"), std::string::npos)
        << "the topological verdict comes first";
}

TEST(EngineOutputCheck, SurfacesTouchingAtAVertexAreRefused) {
    // A second tetrahedron hung from the first one's apex 3 by its vertex 0.
    Mesh m = tetrahedron();
    const Mesh other = tetrahedron(1, {0, 0, 1});
    const auto shift = [](uint32_t v) { return v == 0 ? 3u : v + 3u; };  // other's 0 is our 3
    m.positions.insert(m.positions.end(), other.positions.begin() + 1, other.positions.end());
    for (const auto& t : other.triangles) m.triangles.push_back({shift(t[0]), shift(t[1]), shift(t[2])});
    const EngineOutputCheck c = checkEngineMesh(m);
    EXPECT_FALSE(c.ok);
    EXPECT_EQ(c.open_edges + c.overused_edges, 0u);
    EXPECT_EQ(c.pinched_vertices, 1u);
    EXPECT_NE(c.problem.find("touch"), std::string::npos) << c.problem;
}

// A stand-in engine that "renders" by writing a fixed mesh.
class MeshWritingEngine : public ScadEngine {
public:
    explicit MeshWritingEngine(Mesh mesh) : mesh_(std::move(mesh)) {}
    std::string name() const override { return "fake"; }
    std::string version() const override { return "fake 1"; }
    std::string executable() const override { return "/bin/true"; }
    bool supports(ScadExportFormat f) const override { return f == ScadExportFormat::Stl; }
    ScadRenderResult run(const ScadRenderRequest& rq, const ScadProgress&) const override {
        // The staging file has no .stl extension; write to a named file and move it.
        const std::string named = rq.output_path + ".stl";
        writeMesh(mesh_, named);
        fs::rename(named, rq.output_path);
        ScadRenderResult r;
        r.status = ScadRenderResult::Status::Ok;
        r.summary = "rendered";
        return r;
    }

private:
    Mesh mesh_;
};

TEST(RenderScadChecked, BrokenMeshIsAnEngineFailureAndWritesNothing) {
    const fs::path dir = test::scratchDir("checked_broken");
    test::writeText(dir / "m.scad", "cube(1);\n");
    test::writeText(dir / "out.stl", "old");
    Mesh open = tetrahedron(10);
    open.triangles.pop_back();
    MeshWritingEngine engine(open);
    ScadRenderRequest rq;
    rq.scad_path = (dir / "m.scad").string();
    rq.output_path = (dir / "out.stl").string();
    EngineOutputCheck check;
    const ScadRenderResult r = renderScadChecked(engine, rq, {}, {}, &check);
    EXPECT_EQ(r.status, ScadRenderResult::Status::Failed);
    EXPECT_NE(r.summary.find("fake reported success but wrote a broken mesh"), std::string::npos) << r.summary;
    EXPECT_FALSE(check.ok);
    EXPECT_EQ(test::readText(dir / "out.stl"), "old");
    size_t files = 0;
    for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++files;
    EXPECT_EQ(files, 2u) << "a temporary file was left behind";
}

TEST(RenderScadChecked, GoodMeshIsWritten) {
    const fs::path dir = test::scratchDir("checked_good");
    test::writeText(dir / "m.scad", "cube(1);\n");
    MeshWritingEngine engine(tetrahedron(10));
    ScadRenderRequest rq;
    rq.scad_path = (dir / "m.scad").string();
    rq.output_path = (dir / "out.stl").string();
    EngineOutputCheck check;
    const ScadRenderResult r = renderScadChecked(engine, rq, {}, {1000.0 / 6.0}, &check);
    EXPECT_TRUE(r.ok()) << r.summary;
    EXPECT_TRUE(check.ok) << check.problem;
    EXPECT_NEAR(signedVolume(readStl((dir / "out.stl").string())), 1000.0 / 6.0, 1e-4);
}

}  // namespace
}  // namespace tsf
