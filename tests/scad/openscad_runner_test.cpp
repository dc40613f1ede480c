// The OpenSCAD runner: message parsing, -D parsing, and renderScad's
// guarantees (atomic output, time limit, clear failures) with the real binary.
#include <gtest/gtest.h>

#include <filesystem>

#include "gen/util/error.h"
#include "runners/openscad/openscad_messages.h"
#include "runners/process_runner.h"
#include "runners/openscad/openscad_runner.h"
#include "scad_test_support.h"

namespace tsf {
namespace {
namespace fs = std::filesystem;
using namespace test;

TEST(OpenScadMessages, ParsesErrorsWarningsTracesAndAsserts) {
    const std::string out =
        "Compiling design (CSG Tree generation)...\n"
        "ERROR: Assertion '(x > 0)' failed: \"tsf_model: cell_mm must be a number > 0 (mm), got -1\" in file tsf_model.scad, line 177\n"
        "TRACE: called by 'tsf_model' in file model.scad, line 40\n"
        "WARNING: Ignoring unknown variable 'foo' in file /tmp/a b/model.scad, line 3\n"
        "ECHO: \"hello\", 3\n"
        "ERROR: Parser error: syntax error in file \"/tmp/m.scad\", line 12\n"
        "Can't parse file 'm.scad'!\n"
        "Total rendering time: 0:00:00.000\n";
    const std::vector<ScadMessage> m = parseOpenScadOutput(out);
    ASSERT_EQ(m.size(), 6u);
    EXPECT_EQ(m[0].kind, ScadMessage::Kind::Error);
    EXPECT_EQ(m[0].assert_message, "tsf_model: cell_mm must be a number > 0 (mm), got -1");
    EXPECT_EQ(m[0].file, "tsf_model.scad");
    EXPECT_EQ(m[0].line, 177);
    EXPECT_EQ(m[1].kind, ScadMessage::Kind::Trace);
    EXPECT_EQ(m[1].file, "model.scad");
    EXPECT_EQ(m[1].line, 40);
    EXPECT_EQ(m[2].kind, ScadMessage::Kind::Warning);
    EXPECT_EQ(m[2].file, "/tmp/a b/model.scad");
    EXPECT_EQ(m[2].line, 3);
    EXPECT_EQ(m[3].kind, ScadMessage::Kind::Echo);
    EXPECT_EQ(m[3].text, "\"hello\", 3");
    EXPECT_EQ(m[4].file, "/tmp/m.scad");
    EXPECT_EQ(m[4].line, 12);
    EXPECT_TRUE(m[4].assert_message.empty());
    EXPECT_EQ(m[5].kind, ScadMessage::Kind::Error);
    EXPECT_EQ(formatScadMessage(m[5]), "Can't parse file 'm.scad'!");
    EXPECT_EQ(formatScadMessage(m[2]), "WARNING: Ignoring unknown variable 'foo' in file /tmp/a b/model.scad, line 3");
}

TEST(OpenScadRunner, DefinesAreNameEqualsValueAndBareWordsAreStrings) {
    EXPECT_EQ(parseScadDefine("max_height_mm=25").value, "25");
    EXPECT_EQ(parseScadDefine(" transfer = log ").name, "transfer");
    EXPECT_EQ(parseScadDefine("transfer=log").value, "\"log\"");
    EXPECT_EQ(parseScadDefine("transfer=\"sqrt\"").value, "\"sqrt\"");
    EXPECT_EQ(parseScadDefine("mirrored_bottom=true").value, "true");
    EXPECT_EQ(parseScadDefine("v=[1, 2]").value, "[1, 2]");
    EXPECT_THROW(parseScadDefine("max_height_mm"), InputError);
    EXPECT_THROW(parseScadDefine("=3"), InputError);
    EXPECT_THROW(parseScadDefine("2x=3"), InputError);
    EXPECT_THROW(parseScadDefine("x="), InputError);
}

TEST(OpenScadRunner, FormatsFollowTheExtension) {
    ScadExportFormat f{};
    ASSERT_TRUE(scadFormatForPath("a/b.STL", f));
    EXPECT_EQ(f, ScadExportFormat::Stl);
    ASSERT_TRUE(scadFormatForPath("b.3mf", f));
    EXPECT_EQ(f, ScadExportFormat::ThreeMf);
    ASSERT_TRUE(scadFormatForPath("b.png", f));
    EXPECT_EQ(f, ScadExportFormat::Png);
    EXPECT_FALSE(scadFormatForPath("b.obj", f));
    EXPECT_FALSE(scadFormatForPath("b", f));
}

TEST(OpenScadRunner, AMissingBinaryIsReportedWithAnInstallHint) {
    try {
        makeOpenScadEngine("/nonexistent/openscad");
        FAIL() << "no exception";
    } catch (const ScadEngineMissing& e) {
        EXPECT_NE(std::string(e.what()).find("apt install openscad"), std::string::npos) << e.what();
    }
    EXPECT_NE(openscad().version().find("OpenSCAD"), std::string::npos);
}

TEST(OpenScadRunner, StlIsBinaryAndThreeMfIsAZip) {
    const std::string dir = scratchDir("runner_formats");
    writeText(dir + "/cube.scad", "cube([1.234567891, 2, 3]);\n");
    ScadRenderRequest rq;
    rq.scad_path = dir + "/cube.scad";
    rq.output_path = dir + "/cube.stl";
    ScadRenderResult r = renderScad(openscad(), rq);
    ASSERT_TRUE(r.ok()) << errorText(r);
    const std::string stl = readText(rq.output_path);
    ASSERT_EQ(stl.size(), 84u + 12 * 50);  // binary: header, count, 12 facets
    EXPECT_NE(stl.substr(0, 5), "solid");
    // Binary keeps the float32 of 1.234567891 (ASCII would keep 6 digits).
    const Mesh mesh = readMesh(rq.output_path);
    double max_x = 0;
    for (const Vec3& p : mesh.positions) max_x = std::max(max_x, p.x);
    EXPECT_EQ(max_x, double(float(1.234567891)));

    rq.output_path = dir + "/cube.3mf";
    rq.format = ScadExportFormat::ThreeMf;
    r = renderScad(openscad(), rq);
    ASSERT_TRUE(r.ok()) << errorText(r);
    EXPECT_EQ(readText(rq.output_path).substr(0, 2), "PK");
    EXPECT_EQ(readMesh(rq.output_path).triangleCount(), 12u);
}

// A failed render leaves an existing output untouched and no partial file.
TEST(OpenScadRunner, AFailedRenderLeavesTheOldOutputAlone) {
    const std::string dir = scratchDir("runner_atomic");
    writeText(dir + "/bad.scad", "assert(false, \"this model is broken\");\ncube(1);\n");
    writeText(dir + "/out.stl", "previous");
    ScadRenderRequest rq;
    rq.scad_path = dir + "/bad.scad";
    rq.output_path = dir + "/out.stl";
    const ScadRenderResult r = renderScad(openscad(), rq);
    EXPECT_FALSE(r.ok());
    ASSERT_FALSE(r.errors().empty());
    EXPECT_EQ(r.errors().front().assert_message, "this model is broken");
    EXPECT_EQ(r.errors().front().line, 1);
    EXPECT_EQ(readText(dir + "/out.stl"), "previous");
    size_t files = 0;
    for (const auto& e : fs::directory_iterator(dir)) files += e.is_regular_file();
    EXPECT_EQ(files, 2u);
}

TEST(OpenScadRunner, AnEmptyModelIsAFailure) {
    const std::string dir = scratchDir("runner_empty");
    writeText(dir + "/empty.scad", "echo(\"nothing here\");\n");
    ScadRenderRequest rq;
    rq.scad_path = dir + "/empty.scad";
    rq.output_path = dir + "/out.stl";
    const ScadRenderResult r = renderScad(openscad(), rq);
    EXPECT_FALSE(r.ok());
    EXPECT_NE(r.summary.find("empty"), std::string::npos) << r.summary;
    EXPECT_FALSE(fs::exists(rq.output_path));
}

TEST(OpenScadRunner, ParserErrorsInOverridesNameTheOverride) {
    const std::string dir = scratchDir("runner_define");
    writeText(dir + "/m.scad", "a = 1;\nb = 2;\ncube(a + b);\n");
    ScadRenderRequest rq;
    rq.scad_path = dir + "/m.scad";
    rq.output_path = dir + "/out.stl";
    rq.defines = {{"a", "2"}, {"b", "3 +"}};
    const ScadRenderResult r = renderScad(openscad(), rq);
    ASSERT_FALSE(r.ok());
    ASSERT_FALSE(r.errors().empty());
    EXPECT_NE(r.errors().front().text.find("-D b=3 +"), std::string::npos) << errorText(r);
}

TEST(OpenScadRunner, BadInputsAreRefusedBeforeOpenScadRuns) {
    const std::string dir = scratchDir("runner_inputs");
    writeText(dir + "/m.scad", "cube(1);\n");
    writeText(dir + "/m.json", R"({"parameterSets": {"small": {"a": "1"}}, "fileFormatVersion": "1"})");
    ScadRenderRequest rq;
    rq.scad_path = dir + "/missing.scad";
    rq.output_path = dir + "/out.stl";
    EXPECT_THROW(renderScad(openscad(), rq), InputError);
    rq.scad_path = dir + "/m.scad";
    rq.parameter_file = dir + "/m.json";
    rq.parameter_set = "large";  // OpenSCAD would silently ignore it
    try {
        renderScad(openscad(), rq);
        FAIL() << "no exception";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("has no parameter set \"large\"; it has: \"small\""), std::string::npos)
            << e.what();
    }
    rq.output_path = dir + "/no/such/folder/out.stl";
    rq.parameter_set = "small";
    EXPECT_THROW(renderScad(openscad(), rq), InputError);
    EXPECT_FALSE(fs::exists(dir + "/out.stl"));
}

// OpenSCAD 2025 goes on after a failed assert() and exports the rest with
// exit status 0; an ERROR line must still fail the render. A stand-in
// program that behaves that way plays the 2025 binary.
TEST(OpenScadRunner, AnErrorLineFailsTheRenderEvenWithExitStatusZero) {
    const std::string dir = scratchDir("runner_error_status0");
    const std::string fake = dir + "/openscad-2025";
    writeText(fake,
              "#!/bin/sh\n"
              "if [ \"$1\" = \"--version\" ]; then echo 'OpenSCAD version 2025.01.19'; exit 0; fi\n"
              "out=''\n"
              "while [ $# -gt 0 ]; do if [ \"$1\" = -o ]; then out=\"$2\"; shift; fi; shift; done\n"
              "printf 'partial' > \"$out\"\n"
              "echo \"ERROR: Assertion 'false' failed: \\\"dropped a module\\\" in file m.scad, line 1\"\n"
              "exit 0\n");
    fs::permissions(fake, fs::perms::owner_all);
    writeText(dir + "/m.scad", "assert(false, \"dropped a module\");\ncube(1);\n");
    const auto engine = makeOpenScadEngine(fake);
    EXPECT_EQ(engine->version(), "OpenSCAD version 2025.01.19");
    ScadRenderRequest rq;
    rq.scad_path = dir + "/m.scad";
    rq.output_path = dir + "/out.stl";
    const ScadRenderResult r = renderScad(*engine, rq);
    EXPECT_FALSE(r.ok());
    ASSERT_FALSE(r.errors().empty());
    EXPECT_EQ(r.errors().front().assert_message, "dropped a module");
    EXPECT_FALSE(fs::exists(rq.output_path));
}

TEST(OpenScadRunner, TimeLimitStopsALongRender) {
    const std::string dir = scratchDir("runner_timeout");
    // Several seconds of recursion before any geometry.
    writeText(dir + "/slow.scad", "function f(i) = i <= 0 ? 0 : 1 + f(i - 1);\nn = [for (k = [0:2000]) f(3000)];\ncube(1);\n");
    ScadRenderRequest rq;
    rq.scad_path = dir + "/slow.scad";
    rq.output_path = dir + "/out.stl";
    rq.timeout_s = 0.5;
    const ScadRenderResult r = renderScad(openscad(), rq);
    EXPECT_EQ(r.status, ScadRenderResult::Status::TimedOut);
    EXPECT_NE(r.summary.find("time limit"), std::string::npos);
    EXPECT_LT(r.elapsed_s, 0.5 + kTerminateGraceS + 2.0);
    EXPECT_FALSE(fs::exists(rq.output_path));
}

}  // namespace
}  // namespace tsf

namespace tsf {
namespace {

TEST(OpenScadRunner, ACameraWithADistanceIsHonoured) {
    // Distance 0 (the default) lets OpenSCAD frame the model; any distance,
    // or an eye and a centre, is the user's camera and is passed as given.
    using Flags = std::vector<std::string>;
    EXPECT_EQ(cameraFramingFlags(kDefaultPngCamera), (Flags{"--autocenter", "--viewall"}));
    EXPECT_EQ(cameraFramingFlags("0,0,0,55,0,25,500"), Flags{}) << "at 500 mm";
    EXPECT_EQ(cameraFramingFlags("100,100,100,0,0,0"), Flags{});
    // A distance with translate 0,0,0 looks at the model's centre.
    EXPECT_EQ(cameraLookingAt("0,0,0,55,0,25,500", 75, 60, 10), "75,60,10,55,0,25,500");
    EXPECT_EQ(cameraLookingAt("5,0,0,55,0,25,500", 75, 60, 10), "5,0,0,55,0,25,500");
    EXPECT_EQ(cameraLookingAt(kDefaultPngCamera, 75, 60, 10), kDefaultPngCamera);
}

}  // namespace
}  // namespace tsf
