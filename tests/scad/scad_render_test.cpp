// Generated .scad files rendered by the real OpenSCAD (2021.01): the STL of
// each strategy is the same solid as the direct mesher's, edits to a value or
// a parameter change exactly what they should, and malformed parameters stop
// the render with the library's assert messages.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include "gen/mesh/direct_mesher.h"
#include "gen/util/error.h"
#include "gen/scad/scad_emitter.h"
#include "scad_test_support.h"
#include "verify/mesh_topology.h"
#include "verify/column_grid.h"
#include "verify/readback.h"
#include "verify/verify_model.h"
#include "gen/model/build_scene.h"

namespace tsf {
namespace {
using namespace test;
using Strategy = ScadOptions::Strategy;

// Two volumes of the same solid from float32 STL coordinates: relative error
// of a float32 coordinate is 2^-24 ~ 6e-8; the task's bar is 1e-6.
constexpr double kVolumeRelTolerance = 1e-6;

struct Rendered {
    std::string scad_path;
    std::string stl_path;
    Mesh mesh;
};

Rendered generateAndRender(const Scene& scene, Strategy strategy, const std::string& name,
                           const std::vector<ScadDefine>& defines = {}) {
    Rendered out;
    const std::string dir = scratchDir(name);
    out.scad_path = dir + "/model.scad";
    out.stl_path = dir + "/model.stl";
    ScadOptions o;
    o.strategy = strategy;
    writeScad(scene, o, out.scad_path);
    const ScadRenderResult r = renderStl(out.scad_path, out.stl_path, defines);
    EXPECT_TRUE(r.ok()) << errorText(r);
    EXPECT_TRUE(r.warnings().empty()) << formatScadMessage(r.warnings().front());
    if (r.ok()) out.mesh = readMesh(out.stl_path);
    return out;
}

// Heights of a mesh seen along vertical rays at six points per kept cell,
// each 80 % of the way from the centre to a corner: the first surface from
// above and from below. Together with the centre rays of the values read
// back, this sees a wall in the wrong place or a missing step.
void expectCornerRaysMatch(const Mesh& mesh, const Scene& scene) {
    const ColumnGrid caster(mesh);
    const Bounds b = meshBounds(mesh);
    const double above = b.max.z + 10, below = b.min.z - 10;
    // Half a z step: a surface on the right step is within it (float32 STL
    // rounding of z is far smaller than any step used here).
    const double tolerance_mm = scene.z_snap_mm / 2;
    int bad = 0;
    for (size_t k = 0; k < scene.keptCount() && bad < 5; ++k) {
        const LatticePoint ctr = hexCentre(scene.grid, scene.col[k], scene.row[k]);
        for (int e = 0; e < kHexCorners; ++e) {
            const LatticePoint cnr = hexCorner(scene.grid, scene.col[k], scene.row[k], e);
            const double x = (0.2 * double(ctr.i) + 0.8 * double(cnr.i)) * scene.pitch_mm / 2;
            const double y = (0.2 * double(ctr.j) + 0.8 * double(cnr.j)) * scene.pitch_mm / (2 * std::sqrt(3.0));
            const auto down = caster.firstHit({x, y, above}, {0, 0, -1});
            const auto up = caster.firstHit({x, y, below}, {0, 0, 1});
            const bool ok = down && up && std::fabs(down->point_mm.z - scene.zMm(scene.top[k])) <= tolerance_mm &&
                            std::fabs(up->point_mm.z - scene.zMm(scene.bottom[k])) <= tolerance_mm;
            if (!ok) ++bad;
            EXPECT_TRUE(ok) << "cell " << scene.col[k] << "," << scene.row[k] << " corner " << e << ": top "
                            << (down ? down->point_mm.z : NAN) << " (want " << scene.zMm(scene.top[k]) << "), bottom "
                            << (up ? up->point_mm.z : NAN) << " (want " << scene.zMm(scene.bottom[k]) << ")";
        }
    }
}

// The OpenSCAD mesh and the direct mesher's are the same solid: the
// verifier's agreement check passes (verify/agreement.h: the surfaces cover
// the same planes, Hausdorff distance within 1 um), both are closed and
// outward with equal volume (and equal to the Scene's own sum), every cell's
// top and bottom is at its height at its centre and near each corner, and
// there is no material outside the kept cells.
void expectSameSolidAsDirectMesh(const Mesh& scad_mesh, const Scene& scene) {
    const Mesh direct = meshScene(scene);
    const MeshTopology topo = analyzeTopology(scad_mesh);
    EXPECT_TRUE(topo.isClosedOrientedManifold()) << topo.border_edges.size() << " open edges, "
                                                 << topo.misoriented_edges.size() << " flipped";
    EXPECT_EQ(topo.components.size(), 1u);
    const double v_scad = signedVolume(scad_mesh), v_direct = signedVolume(direct), v_scene = sceneVolume(scene);
    EXPECT_GT(v_scad, 0);
    EXPECT_NEAR(v_scad, v_direct, kVolumeRelTolerance * v_direct);
    EXPECT_NEAR(v_scad, v_scene, kVolumeRelTolerance * v_scene);

    VerifyOptions vo;
    vo.printability = false;
    vo.reference = &direct;
    vo.reference_name = "direct mesher";
    const VerifyReport report = verifyModel(scad_mesh, &scene, vo);
    EXPECT_TRUE(report.passed()) << formatReport(report);
    ASSERT_TRUE(report.agreement.has_value());
    EXPECT_LE(report.agreement->hausdorff_to_reference_mm, kDefaultAgreementToleranceMm);
    EXPECT_LE(report.agreement->hausdorff_from_reference_mm, kDefaultAgreementToleranceMm);
    ASSERT_TRUE(report.readback.has_value());
    EXPECT_EQ(report.readback->cells_checked, scene.keptCount());
    EXPECT_EQ(report.readback->over_tolerance, 0u);
    EXPECT_EQ(report.readback->missed, 0u);
    EXPECT_EQ(report.readback->outside_cells_hit, 0u);
    expectCornerRaysMatch(scad_mesh, scene);
}

struct Case {
    const char* name;
    Strategy strategy;
    Bottom bottom;
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class Agreement : public ::testing::TestWithParam<Case> {};

TEST_P(Agreement, OpenScadStlIsTheDirectMeshersSolid) {
    const Case c = GetParam();
    // 9 x 8 = 72 cells: small enough for the CSG union in a couple of seconds.
    const Scene scene = buildScene(bumpyField(9, 8), smallParams(c.bottom));
    ASSERT_GT(scene.cells_nodata_kept, 0);
    ASSERT_LT(int64_t(scene.keptCount()), scene.grid.cellCount());
    const Rendered r = generateAndRender(scene, c.strategy, std::string("agree_") + c.name);
    expectSameSolidAsDirectMesh(r.mesh, scene);
}

INSTANTIATE_TEST_SUITE_P(StrategyAndBottom, Agreement,
                         ::testing::Values(Case{"poly_flat", Strategy::Polyhedron, Bottom::Flat},
                                           Case{"poly_mirrored", Strategy::Polyhedron, Bottom::Mirrored},
                                           Case{"csg_flat", Strategy::Csg, Bottom::Flat},
                                           Case{"csg_mirrored", Strategy::Csg, Bottom::Mirrored}),
                         [](const auto& info) { return std::string(info.param.name); });

// The library copied beside the file (use <tsf_lib/tsf.scad>) renders the same solid.
TEST(ScadRender, LibraryBesideRendersTheSameSolid) {
    const Scene scene = buildScene(bumpyField(9, 8), smallParams(Bottom::Mirrored));
    const std::string dir = scratchDir("beside");
    ScadOptions o;
    o.inline_library = false;
    writeScad(scene, o, dir + "/model.scad");
    const ScadRenderResult r = renderStl(dir + "/model.scad", dir + "/model.stl");
    ASSERT_TRUE(r.ok()) << errorText(r);
    EXPECT_TRUE(r.warnings().empty());
    expectSameSolidAsDirectMesh(readMesh(dir + "/model.stl"), scene);
}

// The other value -> height rules, negative data, a coarse z step, a fitted
// (irrational-looking) pitch and no culling, on a larger polyhedron model.
TEST(ScadRender, PolyhedronAgreesForEveryTransferBaselineAndSnap) {
    const HexField field = fieldFromFunction(20, 17, [](int c, int r) {
        if ((c + 2 * r) % 13 == 0) return kNaN;
        return 30.0 * std::sin(0.31 * c) * std::cos(0.23 * r) + 0.37 * c - 4.0;
    });
    struct Variant {
        Transfer transfer;
        Bottom bottom;
        Cull cull;
        double z_snap_mm;
        BaselineMode baseline;
    };
    int n = 0;
    for (const Variant v : {Variant{Transfer::Sqrt, Bottom::Flat, Cull::Hull, 0.2, BaselineMode::Auto},
                            Variant{Transfer::Log, Bottom::Mirrored, Cull::None, 0.001, BaselineMode::Min},
                            Variant{Transfer::Linear, Bottom::Mirrored, Cull::Hull, 0.05, BaselineMode::Zero}}) {
        SceneParams p;
        p.marks = withoutMarks();  // the pillar rules alone; marks have their own tests
        p.pitch_mm = 0;  // fit to 97 x 83 mm: an arbitrary double
        p.fit_width_mm = 97;
        p.fit_depth_mm = 83;
        p.max_height_mm = 17.5;
        p.base_mm = 1.6;
        p.transfer = v.transfer;
        p.bottom = v.bottom;
        p.cull = v.cull;
        p.z_snap_mm = v.z_snap_mm;
        p.baseline_mode = v.baseline;
        const Scene scene = buildScene(field, p);
        SCOPED_TRACE(std::string(toString(v.transfer)) + " " + toString(v.bottom));
        const Rendered r = generateAndRender(scene, Strategy::Polyhedron, "variants_" + std::to_string(++n));
        expectSameSolidAsDirectMesh(r.mesh, scene);
    }
}

// Change one number in the generated file: exactly that cell moves, to the
// height the new value asks for, with either strategy.
class EditOneValue : public ::testing::TestWithParam<Strategy> {};

TEST_P(EditOneValue, ChangesExactlyThatCell) {
    const Strategy strategy = GetParam();
    HexField field = bumpyField(9, 8);
    const SceneParams params = smallParams();
    const Scene scene = buildScene(field, params);
    const int32_t col = 5, row = 3;
    ASSERT_GE(scene.keptAt(col, row), 0);
    ASSERT_FALSE(std::isnan(field.at(col, row)));
    const Rendered before = generateAndRender(scene, strategy, std::string("edit_value_") + toString(strategy));

    const bool lower = field.at(col, row) > 5;
    const double new_value = lower ? 1.25 : 9.75;
    writeText(before.scad_path, withValue(readText(before.scad_path), col, row, lower ? "1.25" : "9.75"));
    const std::string edited_stl = before.stl_path + ".edited.stl";
    const ScadRenderResult r = renderStl(before.scad_path, edited_stl);
    ASSERT_TRUE(r.ok()) << errorText(r);
    const Mesh after = readMesh(edited_stl);

    // Against the unedited Scene exactly one cell is off, and it is (col, row).
    const ColumnGrid caster(after);
    ReadbackOptions ro;
    ro.max_offenders = 5;
    const ReadbackResult old_scene = readBack(after, scene, caster, ro);
    ASSERT_EQ(old_scene.figures.over_tolerance, 1u);
    EXPECT_EQ(old_scene.figures.worst.front().col, col);
    EXPECT_EQ(old_scene.figures.worst.front().row, row);

    // And it matches the Scene of the edited field, with the same mapping
    // (value_max / baseline stay as written in the file).
    field.at(col, row) = new_value;
    SceneParams edited = params;
    edited.baseline_mode = BaselineMode::Value;
    edited.baseline_value = scene.mapping.baseline;
    edited.value_max = scene.mapping.value_max;
    const Scene edited_scene = buildScene(field, edited);
    ASSERT_EQ(edited_scene.keptCount(), scene.keptCount());
    expectSameSolidAsDirectMesh(after, edited_scene);
}

INSTANTIATE_TEST_SUITE_P(BothStrategies, EditOneValue, ::testing::Values(Strategy::Polyhedron, Strategy::Csg),
                         [](const auto& info) { return std::string(toString(info.param)); });

// Writing a number over undef adds a pillar there; the library does not re-run the hull.
TEST(ScadRender, WritingANumberOverUndefAddsAPillar) {
    const Scene scene = buildScene(bumpyField(9, 8), smallParams());
    int32_t col = -1, row = -1;
    for (int32_t r = 0; r < scene.grid.rows && col < 0; ++r)
        for (int32_t c = 0; c < scene.grid.cols; ++c)
            if (scene.keptAt(c, r) < 0) {
                int32_t nc, nr;
                hexNeighbour(c, r, 0, nc, nr);
                if (scene.keptAt(nc, nr) >= 0) { col = c; row = r; break; }
            }
    ASSERT_GE(col, 0) << "the field has no culled cell next to a kept one";
    const Rendered before = generateAndRender(scene, Strategy::Polyhedron, "edit_add");
    writeText(before.scad_path, withValue(readText(before.scad_path), col, row, "10"));
    const ScadRenderResult r = renderStl(before.scad_path, before.stl_path);
    ASSERT_TRUE(r.ok()) << errorText(r);
    const Mesh after = readMesh(before.stl_path);
    const double area = std::sqrt(3.0) / 2 * scene.pitch_mm * scene.pitch_mm;
    const double pillar_mm = scene.zMm(snapUnits(scene.params.base_mm, scene.z_snap_mm) +
                                       snapUnits(scene.mapping.heightMm(10), scene.z_snap_mm));
    // One more hexagon (snapped corners: area within 1e-3 relative).
    EXPECT_NEAR(signedVolume(after) - signedVolume(before.mesh), area * pillar_mm, 1e-3 * area * pillar_mm);
    EXPECT_TRUE(analyzeTopology(after).isClosedOrientedManifold());
}

// -D overrides and saved parameter sets re-render with the new parameters.
TEST(ScadRender, ParameterOverridesAndSetsChangeTheModel) {
    const HexField field = bumpyField(9, 8);
    const Scene scene = buildScene(field, smallParams());
    const Rendered base = generateAndRender(scene, Strategy::Polyhedron, "params");

    const std::string taller = base.stl_path + ".taller.stl";
    ScadRenderResult r = renderStl(base.scad_path, taller, {parseScadDefine("height=15"), parseScadDefine("transfer=sqrt")});
    ASSERT_TRUE(r.ok()) << errorText(r);
    SceneParams p = smallParams();
    p.max_height_mm = 15;
    p.transfer = Transfer::Sqrt;
    expectSameSolidAsDirectMesh(readMesh(taller), buildScene(field, p));

    const std::string json = base.scad_path.substr(0, base.scad_path.size() - 5) + ".json";
    const std::string mirrored = base.stl_path + ".mirrored.stl";
    r = renderStl(base.scad_path, mirrored, {}, json, "mirrored bottom");
    ASSERT_TRUE(r.ok()) << errorText(r);
    expectSameSolidAsDirectMesh(readMesh(mirrored), buildScene(field, smallParams(Bottom::Mirrored)));

    const std::string layers = base.stl_path + ".layers.stl";
    r = renderStl(base.scad_path, layers, {}, json, "layer steps 0.2 mm");
    ASSERT_TRUE(r.ok()) << errorText(r);
    p = smallParams();
    p.z_snap_mm = 0.2;
    expectSameSolidAsDirectMesh(readMesh(layers), buildScene(field, p));
}

// Malformed parameters and values stop OpenSCAD with the library's assert
// message (naming the parameter or the cell), never a silent wrong model.
TEST(ScadRender, MalformedParametersGiveAssertMessages) {
    const Scene scene = buildScene(bumpyField(6, 5), smallParams());
    const Rendered base = generateAndRender(scene, Strategy::Polyhedron, "malformed");
    const std::string text = readText(base.scad_path);
    struct Bad {
        std::vector<ScadDefine> defines;
        std::string edited_text;  ///< "" = the generated file
        std::string expect;       ///< part of the assert message
    };
    const std::vector<Bad> cases = {
        {{parseScadDefine("cell=-1")}, "", "cell_mm must be a number > 0"},
        {{parseScadDefine("cell=\"wide\"")}, "", "cell_mm must be a number > 0"},
        {{parseScadDefine("transfer=cubic")}, "", "transfer must be \"linear\", \"sqrt\" or \"log\""},
        {{parseScadDefine("snap=0")}, "", "z_step_mm must be a number between"},
        {{parseScadDefine("base=0.0001"), parseScadDefine("snap=0.2")}, "", "base_mm must be a number >= z_step_mm"},
        {{parseScadDefine("height=-3")}, "", "max_height_mm must be a number >= 0"},
        {{parseScadDefine("mirror=1")}, "", "mirrored must be true or false"},
        {{parseScadDefine("value_max=undef")}, "", "value_max must be a finite number"},
        {{}, withValue(text, 2, 1, "\"abc\""), "values[1][2] (row 1, column 2) must be a finite number"},
        {{}, withValue(text, 4, 3, "1/0"), "values[3][4] (row 3, column 4) must be a finite number"},
        {{}, withValue(text, 4, 3, "[1, 2]"), "values[3][4] (row 3, column 4) must be a finite number"},
    };
    int n = 0;
    for (const Bad& bad : cases) {
        SCOPED_TRACE(bad.expect);
        std::string scad = base.scad_path;
        if (!bad.edited_text.empty()) {
            scad = base.scad_path + ".bad" + std::to_string(++n) + ".scad";
            writeText(scad, bad.edited_text);
        }
        const std::string stl = base.stl_path + ".bad.stl";
        const ScadRenderResult r = renderStl(scad, stl, bad.defines);
        ASSERT_FALSE(r.ok());
        std::string asserts;
        for (const ScadMessage& m : r.errors()) asserts += m.assert_message + "\n";
        EXPECT_NE(asserts.find(bad.expect), std::string::npos) << errorText(r);
        EXPECT_FALSE(std::filesystem::exists(stl));
    }
    // A row that lost an entry.
    std::vector<std::string> lines = splitLines(text);
    const ValuesBlock block = readValuesBlock(lines);
    std::string& row2 = lines[block.line_index[2]];
    row2.erase(row2.find('[') + 1, row2.find(',') - row2.find('['));
    const std::string short_row = base.scad_path + ".short.scad";
    writeText(short_row, joinLines(lines));
    const ScadRenderResult r = renderStl(short_row, base.stl_path + ".bad.stl");
    ASSERT_FALSE(r.ok());
    ASSERT_FALSE(r.errors().empty());
    EXPECT_NE(r.errors().front().assert_message.find("every row of values must have 6 entries like row 0; row 2 has 5"),
              std::string::npos)
        << errorText(r);
}

}  // namespace
}  // namespace tsf
