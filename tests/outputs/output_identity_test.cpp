// Byte-identical outputs: tsf gen writes every file of a set of small models
// (each feature at least once: the orientation tab, the legend plate, the
// scale, class textures, halves, tiles, a mirrored bottom, GDAL input) and
// each file's size and XXH3-64 hash (gen/util/file_stamp.h) must equal the
// list in tests/outputs/golden_outputs.txt. A refactoring that means to
// change nothing proves it here; a change that means to change an output
// regenerates the list and shows, in review, which files changed:
//
//   TSF_UPDATE_GOLDEN=1 ctest --test-dir build -R OutputIdentity
//
// (or run build/test_outputs with TSF_UPDATE_GOLDEN=1 set), which writes the
// list into the source tree instead of comparing with it.
//
// Every output is deterministic: no time, path or host is written into a
// model, a .scad, a sidecar, a key or a braille file (a run in another
// folder gives the same bytes; OutputIdentity.SameBytesInAnotherFolder).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "gen/util/file_stamp.h"
#include "tests/support/files.h"
#include "tests/support/run.h"
#include "tests/support/fields.h"

namespace tsf {
namespace {

namespace fs = std::filesystem;

/// Three classes of land cover as an ESRI grid of codes (categorical input).
std::string coverAsc() {
    std::string grid = "ncols 12\nnrows 8\nxllcorner 0\nyllcorner 0\ncellsize 30\nNODATA_value -9999\n";
    for (int r = 0; r < 8; ++r) {
        for (int c = 0; c < 12; ++c) grid += std::string(c ? " " : "") + (c < 6 ? "4" : r < 3 ? "8" : "2");
        grid += "\n";
    }
    return grid;
}

struct Case {
    const char* name;
    const char* input;  ///< "hill.csv", "cover.asc" (written here) or a path in the source tree
    const char* args;   ///< after `tsf gen INPUT`; MODEL stands for the output folder's model path
    const char* model;  ///< the model's file name
};

// Each case writes a model, its .scad and its sidecar, key and braille files
// (whatever tsf gen writes beside them) into a folder of its own.
const std::vector<Case> kCases = {
    {"tab", "hill.csv", "--cell 6 --height 12 --scad MODEL.scad", "m.stl"},
    {"legend", "hill.csv", "--cell 6 --height 12 --title Hill --units m --scad MODEL.scad", "m.3mf"},
    {"scale", "hill.csv", "--cell 6 --height 12 --scale --scad MODEL.scad", "m.stl"},
    {"classes", "cover.asc", "--categorical --cell 5 --classes 3 --scad MODEL.scad", "m.stl"},
    {"halves", "hill.csv", "--cell 6 --height 12 --mirror --halves", "m.stl"},
    {"tiles", "hill.csv", "--cell 9 --height 12 --bed 70x70 --tile", "m.stl"},
    {"mirror", "hill.csv", "--cell 6 --height 12 --mirror --scad MODEL.scad", "m.3mf"},
    {"gdal", "examples/volcano.vrt", "--cell 2 --height 15 --title Volcano --scad MODEL.scad", "v.stl"},
};

std::string replaceAll(std::string text, const std::string& from, const std::string& to) {
    for (size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size()))
        text.replace(at, from.size(), to);
    return text;
}

/// Runs one case into out/<name>/ and returns "name/file bytes hash" for
/// each file written there, sorted by file name.
std::vector<std::string> runCase(const Case& c, const fs::path& inputs, const fs::path& out) {
    const fs::path dir = out / c.name;
    fs::create_directories(dir);
    const std::string input = fs::exists(inputs / c.input) ? (inputs / c.input).string() : test::sourcePath(c.input);
    const std::string model = (dir / c.model).string();
    const std::string args = replaceAll(c.args, "MODEL", model);
    // stdout and stderr go to the inputs folder: the summary is not an output file.
    const auto r = test::runTsf("gen " + input + " " + args + " -o " + model, inputs);
    EXPECT_EQ(r.exit_code, test::kExitOk) << c.name << ": " << r.out << r.err;
    std::vector<std::string> lines;
    for (const auto& entry : fs::directory_iterator(dir)) {
        const FileStamp s = stampFile(entry.path().string());
        lines.push_back(std::string(c.name) + "/" + entry.path().filename().string() + " " + std::to_string(s.bytes) +
                        " " + toHex(s.hash));
    }
    std::sort(lines.begin(), lines.end());
    EXPECT_FALSE(lines.empty()) << c.name << " wrote nothing";
    return lines;
}

/// Every case's lines, in the order of kCases.
std::vector<std::string> runAll(const fs::path& root) {
    const fs::path inputs = root / "inputs", out = root / "out";
    fs::create_directories(inputs);
    test::writeText(inputs / "hill.csv", test::hillCsv());
    test::writeText(inputs / "cover.asc", coverAsc());
    std::vector<std::string> all;
    for (const Case& c : kCases) {
        const auto lines = runCase(c, inputs, out);
        all.insert(all.end(), lines.begin(), lines.end());
    }
    return all;
}

const char* kGoldenPath = "tests/outputs/golden_outputs.txt";
const char* kGoldenHeader =
    "# Size (bytes) and XXH3-64 of every file tsf gen writes for the models of\n"
    "# tests/outputs/output_identity_test.cpp. Regenerate after an intended change:\n"
    "#   TSF_UPDATE_GOLDEN=1 ctest --test-dir build -R OutputIdentity\n";

std::vector<std::string> readGolden() {
    std::istringstream in(test::readText(test::sourcePath(kGoldenPath)));
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        if (!line.empty() && line[0] != '#') lines.push_back(line);
    return lines;
}

TEST(OutputIdentity, EveryOutputFileMatchesTheGoldenList) {
    const auto lines = runAll(test::scratchDir());
    const char* update = std::getenv("TSF_UPDATE_GOLDEN");
    if (update && std::string(update) == "1") {
        std::string text = kGoldenHeader;
        for (const auto& l : lines) text += l + "\n";
        test::writeText(test::sourcePath(kGoldenPath), text);
        std::cout << "wrote " << test::sourcePath(kGoldenPath) << " (" << lines.size() << " files)\n";
        return;
    }
    const auto golden = readGolden();
    ASSERT_FALSE(golden.empty()) << "no " << kGoldenPath;
    // Line by line, so a failure names the files that changed.
    std::map<std::string, std::string> want, got;
    for (const auto& l : golden) want[l.substr(0, l.find(' '))] = l;
    for (const auto& l : lines) got[l.substr(0, l.find(' '))] = l;
    for (const auto& [file, line] : want) {
        const auto it = got.find(file);
        if (it == got.end())
            ADD_FAILURE() << file << " is no longer written";
        else
            EXPECT_EQ(it->second, line) << file << " changed";
    }
    for (const auto& [file, line] : got)
        if (!want.count(file)) ADD_FAILURE() << file << " is written but not in " << kGoldenPath << ": " << line;
}

// Nothing of the folder a model is written to, nor of the time, ends up in
// its files: the same case in two folders of different names gives the same bytes.
TEST(OutputIdentity, SameBytesInAnotherFolder) {
    const auto root = test::scratchDir();
    const fs::path inputs_a = root / "a" / "inputs", inputs_b = root / "another-folder" / "in";
    for (const auto& in : {inputs_a, inputs_b}) {
        fs::create_directories(in);
        test::writeText(in / "hill.csv", test::hillCsv());
    }
    const Case c = kCases[2];  // the scale: model, .scad, sidecar and key
    const auto a = runCase(c, inputs_a, root / "a" / "out");
    const auto b = runCase(c, inputs_b, root / "another-folder" / "elsewhere");
    EXPECT_EQ(a, b);
}

}  // namespace
}  // namespace tsf
