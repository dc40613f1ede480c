// `tsf render` end to end: the tsf binary, the real openscad, files on disk.
#include <gtest/gtest.h>

#include <filesystem>

#include "gen/scad/scad_emitter.h"
#include "scad_test_support.h"
#include "tests/support/run.h"
#include "verify/mesh_topology.h"
#include "runners/process_runner.h"
#include "gen/model/build_scene.h"

namespace tsf {
namespace {
namespace fs = std::filesystem;
using namespace test;

// tsf with an argument vector (no shell quoting), through the process runner.
RunResult runTsfArgv(std::vector<std::string> args) {
    args.insert(args.begin(), TSF_BINARY);
    ProcessOptions o;
    o.timeout_s = 300;
    const ProcessResult r = runProcess(args, o);
    EXPECT_EQ(r.end, ProcessResult::End::Exited) << r.output;
    RunResult out;
    out.exit_code = r.exit_code;
    out.output = r.output;
    return out;
}

std::string writeModel(const std::string& name) {
    const std::string dir = scratchDir(name);
    const std::string path = dir + "/model.scad";
    writeScad(buildScene(bumpyField(7, 6), smallParams()), ScadOptions{}, path);
    return path;
}

bool contains(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

TEST(RenderCli, RendersBinaryStlChecksItAndReportsTime) {
    const std::string scad = writeModel("cli_ok");
    const std::string stl = fs::path(scad).replace_extension(".stl").string();
    const RunResult r = runTsfArgv({"render", scad, "-o", stl});
    ASSERT_EQ(r.exit_code, kExitOk) << r.output;
    EXPECT_TRUE(contains(r.output, "with OpenSCAD version")) << r.output;
    EXPECT_TRUE(contains(r.output, "wrote " + stl + " (binary STL) in ")) << r.output;
    EXPECT_TRUE(contains(r.output, "closed, manifold, outward")) << r.output;
    EXPECT_NE(readText(stl).substr(0, 5), "solid");
    EXPECT_TRUE(analyzeTopology(readMesh(stl)).isClosedOrientedManifold());
}

TEST(RenderCli, OverridesAndParameterSetsReachOpenScad) {
    const std::string scad = writeModel("cli_params");
    const std::string dir = fs::path(scad).parent_path().string();
    ASSERT_EQ(runTsfArgv({"render", scad, "-o", dir + "/a.stl", "-q"}).exit_code, 0);
    ASSERT_EQ(runTsfArgv({"render", scad, "-o", dir + "/b.stl", "-q", "-D", "height=20"}).exit_code, 0);
    ASSERT_EQ(runTsfArgv({"render", scad, "-o", dir + "/c.stl", "-q", "-p", dir + "/model.json", "-P", "half size"}).exit_code, 0);
    const double a = signedVolume(readMesh(dir + "/a.stl"));
    const double b = signedVolume(readMesh(dir + "/b.stl"));
    const double c = signedVolume(readMesh(dir + "/c.stl"));
    EXPECT_GT(b, a * 1.3);  // twice the relief on a 2 mm base
    EXPECT_LT(c, a / 6);    // half in every direction: an eighth
}

TEST(RenderCli, AMalformedParameterIsBadInputWithTheAssertMessage) {
    const std::string scad = writeModel("cli_bad");
    const std::string stl = fs::path(scad).replace_extension(".stl").string();
    const RunResult r = runTsfArgv({"render", scad, "-o", stl, "-D", "cell=-2"});
    EXPECT_EQ(r.exit_code, kExitBadInput) << r.output;
    EXPECT_TRUE(contains(r.output, "tsf_model: cell_mm must be a number > 0 (mm), got -2")) << r.output;
    EXPECT_FALSE(fs::exists(stl));
    const RunResult bad_define = runTsfArgv({"render", scad, "-o", stl, "-D", "max_height_mm"});
    EXPECT_EQ(bad_define.exit_code, kExitBadInput) << bad_define.output;
    const RunResult typo = runTsfArgv({"render", scad, "-o", stl, "-D", "heigth=25"});
    EXPECT_EQ(typo.exit_code, kExitBadInput) << typo.output;
    EXPECT_TRUE(contains(typo.output, "assigns no variable named 'heigth'; its variables are: cell, height,")) << typo.output;
    const RunResult bad_set = runTsfArgv({"render", scad, "-o", stl, "-p", fs::path(scad).replace_extension(".json").string(),
                             "-P", "tiny"});
    EXPECT_EQ(bad_set.exit_code, kExitBadInput) << bad_set.output;
    EXPECT_TRUE(contains(bad_set.output, "no parameter set \"tiny\"")) << bad_set.output;
}

TEST(RenderCli, MissingOpenScadIsAToolFailureWithAnInstallHint) {
    const std::string scad = writeModel("cli_missing");
    const std::string stl = fs::path(scad).replace_extension(".stl").string();
    const RunResult r = runTsfArgv({"render", scad, "-o", stl, "--engine", "openscad", "--openscad", "/nonexistent/openscad"});
    EXPECT_EQ(r.exit_code, kExitToolFailed) << r.output;
    EXPECT_TRUE(contains(r.output, "apt install openscad")) << r.output;
}

TEST(RenderCli, WritesAPngPreviewOfTheExportedModel) {
    const std::string scad = writeModel("cli_png");
    const std::string dir = fs::path(scad).parent_path().string();
    const RunResult r = runTsfArgv({"render", scad, "-o", dir + "/m.stl", "--png", dir + "/m.png", "--imgsize", "320,240"});
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string png = readText(dir + "/m.png");
    ASSERT_GT(png.size(), 24u);
    EXPECT_EQ(png.substr(1, 3), "PNG");
    // IHDR: width and height, big-endian, at bytes 16..23.
    auto be32 = [&](size_t at) {
        return (uint32_t(uint8_t(png[at])) << 24) | (uint32_t(uint8_t(png[at + 1])) << 16) |
               (uint32_t(uint8_t(png[at + 2])) << 8) | uint32_t(uint8_t(png[at + 3]));
    };
    EXPECT_EQ(be32(16), 320u);
    EXPECT_EQ(be32(20), 240u);
}

// OpenSCAD calls this fine ("may not be a valid 2-manifold" is only a
// warning); tsf reads the STL back and refuses it.
TEST(RenderCli, ABrokenMeshIsNotWritten) {
    const std::string dir = scratchDir("cli_broken");
    writeText(dir + "/edge.scad", "cube(1);\ntranslate([1, 1, 0]) cube(1);\n");  // two cubes sharing one edge
    const RunResult r = runTsfArgv({"render", dir + "/edge.scad", "-o", dir + "/edge.stl", "--engine", "openscad"});
    EXPECT_EQ(r.exit_code, kExitToolFailed) << r.output;
    EXPECT_TRUE(contains(r.output, "broken mesh")) << r.output;
    EXPECT_FALSE(fs::exists(dir + "/edge.stl"));
    const RunResult kept = runTsfArgv({"render", dir + "/edge.scad", "-o", dir + "/edge.stl", "--engine", "openscad", "--no-check"});
    EXPECT_EQ(kept.exit_code, kExitOk) << kept.output;
    EXPECT_TRUE(fs::exists(dir + "/edge.stl"));
}

TEST(RenderCli, NothingToWriteIsBadInput) {
    const std::string scad = writeModel("cli_nothing");
    EXPECT_EQ(runTsfArgv({"render", scad}).exit_code, kExitBadInput);
    EXPECT_EQ(runTsfArgv({"render", scad, "-o", "model.obj"}).exit_code, kExitBadInput);
}

}  // namespace
}  // namespace tsf
