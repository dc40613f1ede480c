// The whole flow through the libraries alone, as docs/design.md shows it:
// field -> Scene -> {direct mesh, OpenSCAD} -> verify, no command line.
#include <gtest/gtest.h>

#include "gen/mesh/direct_mesher.h"
#include "gen/readers/load_field.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/scad/scad_emitter.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "tests/support/files.h"
#include "runners/openscad/engine_output_check.h"
#include "runners/openscad/openscad_runner.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {

TEST(LibraryFlow, FieldToSceneToMeshAndOpenScadToVerifiedSolid) {
    const std::string dir = test::scratchDir("library_flow").string();
    FieldLoadOptions in;
    in.input = test::sourcePath("examples/volcano.csv");
    in.bins = 20;
    const Scene scene = buildScene(loadField(in), SceneParams{});
    const Mesh mesh = meshScene(scene);
    writeMesh(mesh, dir + "/volcano.stl");
    writeScad(scene, ScadOptions{}, dir + "/volcano.scad");
    const VerifyReport report = verifyModel(mesh, &scene, VerifyOptions{});
    EXPECT_TRUE(report.passed()) << formatReport(report);

    ScadRenderRequest rq;
    rq.scad_path = dir + "/volcano.scad";
    rq.output_path = dir + "/volcano.openscad.stl";
    EngineOutputExpectation expect;
    expect.volume_mm3 = signedVolume(mesh);
    expect.solid_checks = true;
    EngineOutputCheck check;
    const ScadRenderResult r = renderScadChecked(*makeOpenScadEngine(), rq, {}, expect, &check);
    EXPECT_TRUE(r.ok()) << r.summary;
    EXPECT_TRUE(check.ok) << check.problem;
}

}  // namespace
}  // namespace tsf
