// End-to-end: no combination of paths makes tsf overwrite an input or one of
// its own outputs; files the user did not name are replaced only when tsf
// wrote them; a write that fails is the user's to fix (exit 2) and leaves no
// temporary file, a file-size limit included.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>
#include <fstream>

#include "tests/support/run.h"

namespace tsf {
namespace {
using test::kExitBadInput;
using test::readText;
using test::runCommand;
using test::runTsf;
using test::scratchDir;
using test::writeText;

const char* kField = "1,2,3\n4,5,6\n7,8,9\n";

// Files in dir whose name marks a temporary file.
int temporaryFiles(const std::filesystem::path& dir) {
    int n = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir))
        if (e.path().filename().string().find(".tmp-") != std::string::npos) ++n;
    return n;
}

TEST(OutputSafety, AnOutputThatIsTheInputIsRefused) {
    const auto dir = scratchDir();
    writeText(dir / "f.csv", kField);
    const auto r = runTsf("gen " + (dir / "f.csv").string() + " -o " + (dir / "." / "f.csv").string());
    EXPECT_EQ(r.exit_code, kExitBadInput) << r.output;
    EXPECT_NE(r.output.find("is the input and would be overwritten by -o"), std::string::npos) << r.output;
    EXPECT_EQ(readText(dir / "f.csv"), kField);
    // The same through --scad, the preview and the sidecar name.
    EXPECT_EQ(runTsf("gen " + (dir / "f.csv").string() + " -o " + (dir / "m.stl").string() + " --preview " +
                     (dir / "f.csv").string()).exit_code, kExitBadInput);
    writeText(dir / "m.stl.scene.json", "");
    EXPECT_EQ(runTsf("gen " + (dir / "m.stl.scene.json").string() + " -o " + (dir / "m.stl").string()).exit_code,
              kExitBadInput);
}

TEST(OutputSafety, TwoOutputsWithOneNameAreRefused) {
    const auto dir = scratchDir();
    writeText(dir / "f.csv", kField);
    const auto r = runTsf("gen " + (dir / "f.csv").string() + " -o " + (dir / "s.stl").string() + " --preview " +
                          (dir / "s.stl").string());
    EXPECT_EQ(r.exit_code, kExitBadInput) << r.output;
    EXPECT_NE(r.output.find("named twice as an output (-o and --preview)"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "s.stl"));
    // --scad m.scad writes m.json: an -o of that name is refused too.
    const auto j = runTsf("gen " + (dir / "f.csv").string() + " --scad " + (dir / "m.scad").string() + " -o " +
                          (dir / "m.json").string());
    EXPECT_EQ(j.exit_code, kExitBadInput) << j.output;
    EXPECT_NE(j.output.find("parameter sets"), std::string::npos) << j.output;
}

TEST(OutputSafety, AParameterSetFileTsfDidNotWriteNeedsForce) {
    const auto dir = scratchDir();
    writeText(dir / "f.csv", kField);
    const std::string mine = "{\"parameterSets\": {\"my print\": {\"height\": \"30\"}}, \"fileFormatVersion\": \"1\"}\n";
    writeText(dir / "m.json", mine);
    const std::string gen = "gen " + (dir / "f.csv").string() + " --scad " + (dir / "m.scad").string();
    const auto refused = runTsf(gen);
    EXPECT_EQ(refused.exit_code, kExitBadInput) << refused.output;
    EXPECT_NE(refused.output.find("--force"), std::string::npos) << refused.output;
    EXPECT_EQ(readText(dir / "m.json"), mine);
    EXPECT_FALSE(std::filesystem::exists(dir / "m.scad"));
    const auto forced = runTsf(gen + " --force");
    ASSERT_EQ(forced.exit_code, 0) << forced.output;
    EXPECT_NE(forced.output.find("m.json (OpenSCAD parameter sets"), std::string::npos) << forced.output;
    // Its own parameter sets tsf replaces without asking: running again just works.
    EXPECT_EQ(runTsf(gen + " --height 30").exit_code, 0);
}

TEST(OutputSafety, ItsOwnSidecarOfAnySizeIsReplacedAForeignOneIsNot) {
    const auto dir = scratchDir();
    writeText(dir / "f.csv", kField);
    const std::string gen = "gen " + (dir / "f.csv").string() + " -o " + (dir / "m.stl").string() + " --no-verify";
    ASSERT_EQ(runTsf(gen).exit_code, 0);
    // A 1000 x 1000 grid's sidecar is about 71 MiB: pad this one past 64 MiB
    // with JSON whitespace; it is still tsf's and is replaced without asking.
    {
        std::ofstream pad(dir / "m.stl.scene.json", std::ios::app | std::ios::binary);
        const std::string spaces(1 << 20, ' ');
        for (int i = 0; i < 65; ++i) pad << spaces;
    }
    ASSERT_GT(std::filesystem::file_size(dir / "m.stl.scene.json"), uintmax_t(64) << 20);
    const auto again = runTsf(gen);
    EXPECT_EQ(again.exit_code, 0) << again.output;
    EXPECT_LT(std::filesystem::file_size(dir / "m.stl.scene.json"), uintmax_t(1) << 20);
    // Someone else's file of that name still needs --force.
    writeText(dir / "m.stl.scene.json", "{\"format\": \"my-notes\"}\n");
    const auto refused = runTsf(gen);
    EXPECT_EQ(refused.exit_code, kExitBadInput) << refused.output;
    EXPECT_NE(refused.output.find("--no-scene"), std::string::npos) << refused.output;
}

TEST(OutputSafety, AMissingFolderIsTheUsersToFix) {
    const auto dir = scratchDir();
    writeText(dir / "f.csv", kField);
    const auto r = runTsf("gen " + (dir / "f.csv").string() + " -o " + (dir / "no" / "m.stl").string());
    EXPECT_EQ(r.exit_code, kExitBadInput) << r.output;
    EXPECT_NE(r.output.find("does not exist"), std::string::npos) << r.output;
}

TEST(OutputSafety, AFileSizeLimitFailsCleanly) {
    const auto dir = scratchDir();
    std::string big;
    for (int r = 0; r < 30; ++r)
        for (int c = 0; c < 30; ++c) big += std::to_string((r * c) % 7) + (c + 1 < 30 ? "," : "\n");
    writeText(dir / "f.csv", big);
    // 8 blocks of 1024 bytes: the field can be read, the STL cannot be written.
    const auto r = runCommand("bash -c 'ulimit -f 8; exec " + std::string(TSF_BINARY) + " gen " +
                              (dir / "f.csv").string() + " -o " + (dir / "m.stl").string() + "'");
    EXPECT_EQ(r.exit_code, kExitBadInput) << r.output;
    EXPECT_NE(r.output.find("File too large"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "m.stl"));
    EXPECT_EQ(temporaryFiles(dir), 0);
}

// The model file is written while the model is verified: a model refused
// after that (walls thinner than the nozzle, found by the checks) leaves the
// file of an earlier run as it was and no temporary file, as when nothing
// had been written; the same model with --keep-unprintable is written whole.
TEST(OutputSafety, AModelRefusedByItsChecksLeavesTheOldFileAlone) {
    const auto dir = scratchDir();
    writeText(dir / "m.stl", "an earlier model");
    const std::string gen = "gen " + std::string(TSF_SOURCE_DIR) + "/examples/volcano.csv --cell 2 --nozzle 3 -o " +
                            (dir / "m.stl").string();
    const auto r = runTsf(gen);
    EXPECT_EQ(r.exit_code, kExitBadInput) << r.output;
    EXPECT_NE(r.output.find("walls thinner than the 3 mm nozzle"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("nothing was written"), std::string::npos) << r.output;
    EXPECT_EQ(readText(dir / "m.stl"), "an earlier model");
    EXPECT_FALSE(std::filesystem::exists(dir / "m.stl.scene.json"));
    EXPECT_EQ(temporaryFiles(dir), 0);
    const auto kept = runTsf(gen + " --keep-unprintable");
    ASSERT_EQ(kept.exit_code, test::kExitOk) << kept.output;
    EXPECT_EQ(temporaryFiles(dir), 0);
    const auto v = runTsf("verify " + (dir / "m.stl").string() + " --scene " + (dir / "m.stl.scene.json").string());
    EXPECT_EQ(v.exit_code, test::kExitOk) << v.output;
}

// Every writer's failure is the user's to fix, whatever the format: with a
// file-size limit (prlimit --fsize, in bytes) below the size of the file
// that fails, tsf gen ends with exit 2 and the OS's reason naming that file,
// the file of an earlier run is left as it was, and no temporary file stays.
// lib3mf, which throws from a destructor when its own file writer fails,
// once ended the process here (exit 134, the temporary file left behind).
TEST(OutputSafety, EveryWritersFailureIsAnErrorAndKeepsTheOldFile) {
    const auto dir = scratchDir();
    std::string field;
    for (int r = 0; r < 12; ++r)
        for (int c = 0; c < 12; ++c) field += std::to_string((r * c) % 7) + (c + 1 < 12 ? "," : "\n");
    writeText(dir / "f.csv", field);
    struct Case {
        const char* outputs;  // the run's output options; the file that fails is `fails`
        const char* fails;
    };
    const Case cases[] = {
        {"-o m.stl --no-key --no-scene", "m.stl"},
        {"-o m.stl --ascii --no-key --no-scene", "m.stl"},
        {"-o m.3mf --no-key --no-scene", "m.3mf"},
        {"-o m.3mf --parts --no-key --no-scene", "m.3mf"},
        {"-o m.3mf --parts --parts-layout prusaslicer --no-key --no-scene", "m.3mf"},
        {"-o m.obj --no-key --no-scene", "m.obj"},
        {"-o m.off --no-key --no-scene", "m.off"},
        {"--scad m.scad --no-key --no-scene", "m.json"},  // the parameter sets come first
    };
    for (const Case& c : cases) {
        const std::string gen = "cd " + dir.string() + " && " + TSF_BINARY + " gen f.csv " + c.outputs;
        ASSERT_EQ(runCommand(gen).exit_code, 0) << c.outputs;
        const std::string old = readText(dir / c.fails);
        ASSERT_GT(old.size(), 600u) << c.outputs;
        const auto limited = runCommand("cd " + dir.string() + " && prlimit --fsize=512 " + TSF_BINARY + " gen f.csv " +
                                        c.outputs + " --height 31");
        EXPECT_EQ(limited.exit_code, kExitBadInput) << c.outputs << "\n" << limited.output;
        EXPECT_NE(limited.output.find(c.fails), std::string::npos) << c.outputs << "\n" << limited.output;
        EXPECT_NE(limited.output.find("File too large"), std::string::npos) << c.outputs << "\n" << limited.output;
        EXPECT_EQ(limited.output.find("terminate"), std::string::npos) << limited.output;
        EXPECT_EQ(readText(dir / c.fails), old) << c.outputs << ": the earlier file is intact";
        EXPECT_EQ(temporaryFiles(dir), 0) << c.outputs;
    }
    // The preview picture: with --scad, the preview is written first.
    const std::string gen = "cd " + dir.string() + " && " + TSF_BINARY + " gen f.csv --scad p.scad --preview p.png --no-key --no-scene";
    ASSERT_EQ(runCommand(gen).exit_code, 0);
    const std::string old = readText(dir / "p.png");
    const auto limited = runCommand("cd " + dir.string() + " && prlimit --fsize=512 " + TSF_BINARY +
                                    " gen f.csv --scad p.scad --preview p.png --no-key --no-scene --height 31");
    EXPECT_EQ(limited.exit_code, kExitBadInput) << limited.output;
    EXPECT_NE(limited.output.find("p.png"), std::string::npos) << limited.output;
    EXPECT_NE(limited.output.find("File too large"), std::string::npos) << limited.output;
    EXPECT_EQ(readText(dir / "p.png"), old);
    EXPECT_EQ(temporaryFiles(dir), 0);
}

// The same run writes the same bytes, 3MF included (lib3mf gave each object
// and build item a random UUID; tsf derives them from the content), so the
// model's stamp at the end of its keys is the same each time; every UUID in
// a package is still its own.
TEST(OutputSafety, TheSameRunWritesTheSameBytes) {
    const auto dir = scratchDir();
    writeText(dir / "f.csv", kField);
    for (const std::string layout : {"", " --parts", " --parts --parts-layout prusaslicer"}) {
        std::string first[2], key[2];
        for (int k = 0; k < 2; ++k) {
            ASSERT_EQ(runTsf("gen " + (dir / "f.csv").string() + " -o " + (dir / "m.3mf").string() + layout).exit_code, 0);
            first[k] = readText(dir / "m.3mf");
            key[k] = readText(dir / "m.key.txt");
        }
        EXPECT_EQ(first[0], first[1]) << layout;
        EXPECT_EQ(key[0], key[1]) << layout;
        const auto model = runCommand("unzip -p " + (dir / "m.3mf").string() + " 3D/3dmodel.model");
        std::vector<std::string> uuids;
        for (size_t at = model.output.find("UUID=\""); at != std::string::npos; at = model.output.find("UUID=\"", at + 1))
            uuids.push_back(model.output.substr(at + 6, 36));
        EXPECT_GE(uuids.size(), 3u) << layout;
        std::sort(uuids.begin(), uuids.end());
        EXPECT_EQ(std::unique(uuids.begin(), uuids.end()), uuids.end()) << layout << ": a UUID used twice";
    }
}

// A shared model carries no folder of the person who made it: the .scad
// header's command, the STL header, the 3MF's names and config, the
// parameter sets and the sidecar name files, never paths. A --title with a
// slash that is no path stays as written.
TEST(OutputSafety, NoFolderOfTheUsersTravelsWithTheFiles) {
    const auto dir = test::scratchDir() / "private_folder_name";
    std::filesystem::create_directories(dir);
    test::writeText(dir / "f.csv", "1,2,3\n4,5,6\n7,8,9\n");
    const std::string d = dir.string();
    const auto stl = runTsf("gen " + d + "/f.csv --title km/h --scad=" + d + "/m.scad -o " + d + "/m.stl");
    ASSERT_EQ(stl.exit_code, 0) << stl.output;
    const auto parts = runTsf("gen " + d + "/f.csv --parts --title km/h -o " + d + "/p.3mf");
    ASSERT_EQ(parts.exit_code, 0) << parts.output;
    for (const char* name : {"m.scad", "m.stl", "m.stl.scene.json", "m.json", "p.3mf", "p.3mf.scene.json"}) {
        if (!std::filesystem::exists(dir / name)) continue;
        const std::string bytes = readText(dir / name);
        EXPECT_EQ(bytes.find("private_folder_name"), std::string::npos) << name << " names the folder";
    }
    // A 3MF is a zip: its entries are stored, or deflated; look inside.
    const auto listing = runCommand("unzip -p " + d + "/p.3mf");
    ASSERT_EQ(listing.exit_code, 0) << listing.output.substr(0, 400);
    EXPECT_NE(listing.output.find("f.csv"), std::string::npos) << "the file name is there";
    EXPECT_EQ(listing.output.find("private_folder_name"), std::string::npos) << listing.output.substr(0, 400);
    EXPECT_NE(readText(dir / "m.scad").find("// Command:   tsf gen f.csv --title km/h --scad=m.scad -o m.stl"), std::string::npos)
        << readText(dir / "m.scad").substr(0, 400);
}

}  // namespace
}  // namespace tsf
