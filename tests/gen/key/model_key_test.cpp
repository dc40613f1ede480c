// The model's key (gen/key/): its sentences from the Scene, Braille ASCII
// checked against liblouis' own en-us-brf.dis, the BRF page layout, and tsf
// gen writing both files beside every model.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "gen/key/braille_ready_file.h"
#include "gen/key/model_key.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene_scale.h"
#include "gen/model/features/braille.h"
#include "tests/support/fields.h"
#include "tests/support/files.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// The key as its text file says it (no-break spaces written as spaces).
std::string joined(const std::vector<std::string>& paragraphs) { return modelKeyText(paragraphs); }

// Every six-dot cell's character is the one liblouis' US Braille ASCII
// display table gives (parsed here from the table file itself).
TEST(BrailleReadyFile, BrailleAsciiIsLiblouisUsBrf) {
    const std::string path = "/usr/share/liblouis/tables/en-us-brf.dis";
    std::ifstream in(path);
    ASSERT_TRUE(in) << path << " (Debian liblouis-data)";
    std::map<int, char> table;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::string op, ch, dots;
        if (!(words >> op >> ch >> dots) || op != "display") continue;
        const char c = ch == "\\s" ? ' ' : ch == "\\\\" ? '\\' : ch[0];
        int cell = 0;
        if (dots != "0")
            for (char d : dots) cell |= 1 << (d - '1');
        table[cell] = c;
    }
    ASSERT_EQ(table.size(), 64u);
    for (int cell = 0; cell < 64; ++cell) EXPECT_EQ(brailleAsciiOf(uint8_t(cell)), table[cell]) << "cell " << cell;
    EXPECT_EQ(brailleAsciiOf(0xC1), 'A');  // dots 7 and 8 have no character
}

// The layout: 40 cells a line, 25 lines a page, CR LF, a form feed after
// each page; paragraphs indented two cells (not the title); words whole
// unless longer than a line; and reading the cells back gives the
// translation, word for word.
TEST(BrailleReadyFile, PagesOfFortyByTwentyFiveWithWholeWords) {
    std::vector<std::string> paragraphs = {"A title"};
    for (int k = 0; k < 12; ++k)
        paragraphs.push_back("Paragraph " + std::to_string(k) +
                             " says what a reader needs to know about the model, at some length, so that it wraps.");
    paragraphs.push_back(std::string(95, 'x'));  // one word longer than two lines
    const std::string brf = brailleReadyFile(paragraphs, kDefaultBrailleTable);
    std::vector<std::vector<std::string>> pages(1);
    std::string line;
    for (size_t i = 0; i < brf.size(); ++i) {
        const char c = brf[i];
        if (c == '\f') {
            ASSERT_TRUE(line.empty());
            pages.emplace_back();
        } else if (c == '\r') {
            ASSERT_EQ(brf.at(i + 1), '\n') << "lines end CR LF";
            pages.back().push_back(line);
            line.clear();
            ++i;
        } else {
            ASSERT_TRUE(c >= 0x20 && c <= 0x5F) << "Braille ASCII only: " << int(c);
            line += c;
        }
    }
    ASSERT_TRUE(line.empty());
    ASSERT_TRUE(pages.back().empty()) << "the file ends with a form feed";
    pages.pop_back();
    ASSERT_GE(pages.size(), 2u);
    for (size_t p = 0; p < pages.size(); ++p) {
        if (p + 1 < pages.size()) EXPECT_EQ(pages[p].size(), size_t(kBrfLinesPerPage));
        EXPECT_LE(pages[p].size(), size_t(kBrfLinesPerPage));
        for (const std::string& l : pages[p]) EXPECT_LE(l.size(), size_t(kBrfCellsPerLine)) << l;
    }
    EXPECT_NE(pages[0][0].substr(0, 2), "  ") << "the title is not indented";
    EXPECT_EQ(pages[0][1].substr(0, 2), "  ") << "a paragraph is";
    // The words, read back, are the translation's.
    std::string flat;
    for (const auto& page : pages)
        for (const std::string& l : page) flat += l + " ";
    std::string expected;
    for (const std::string& p : paragraphs) {
        for (uint8_t c : translateToBraille(p, kDefaultBrailleTable)) expected += brailleAsciiOf(c);
        expected += " ";
    }
    auto words = [](const std::string& s) {
        std::vector<std::string> out;
        std::istringstream in(s);
        for (std::string w; in >> w;) out.push_back(w);
        return out;
    };
    std::vector<std::string> got = words(flat), want = words(expected);
    // The long word was split across lines: join its pieces back.
    ASSERT_GE(got.size(), 3u);
    while (got.size() > want.size()) {
        got[got.size() - 2] += got.back();
        got.pop_back();
    }
    EXPECT_EQ(got, want);
}

// A number and its unit, joined by a no-break space, are never split
// between lines, wherever the line ends fall; a plain space may split them.
TEST(BrailleReadyFile, ANumberStaysOnTheLineOfItsUnit) {
    auto ascii = [](const std::string& text) {
        std::string out;
        for (uint8_t c : translateToBraille(text, kDefaultBrailleTable)) out += brailleAsciiOf(c);
        return out;
    };
    const std::string number = ascii("537.3"), unit = ascii("millimetres");
    int split_plain = 0;
    for (int shift = 0; shift < 40; ++shift) {
        std::string lead;
        for (int k = 0; k < shift; ++k) lead += "x ";
        for (const bool glued : {true, false}) {
            const std::string brf = brailleReadyFile(
                {"T", lead + "537.3" + (glued ? "\u00A0" : " ") + "millimetres end"}, kDefaultBrailleTable);
            std::istringstream lines(brf);
            for (std::string line; std::getline(lines, line);) {
                if (line.find(number) == std::string::npos) continue;
                const bool together = line.find(unit) != std::string::npos;
                if (glued) EXPECT_TRUE(together) << "shift " << shift << ": " << line;
                else split_plain += !together;
            }
        }
    }
    EXPECT_GT(split_plain, 0) << "some shift puts the unit on the next line when nothing joins them";
}

// The sentences come from the Scene: the title, the range in the units
// spelled out, the heights, the pits and where they are, the orientation
// and how to turn the model, the braille lines and their code, the scale's
// steps, the size; the processing comes last, after its heading.
TEST(ModelKey, SaysWhatAReaderNeedsFromTheScene) {
    HexField f = test::fieldFromFunction(14, 14, [](int c, int r) { return r < 3 ? 0.0 : 1.0 + (c + r) % 5; });
    f.values[size_t(f.grid.index(7, 8))] = NAN;
    SceneParams p = test::smallParams();
    p.marks = MarkParams{};  // notch and triangle
    p.pitch_mm = 6.0;
    p.words.title = "Rain";
    p.words.units = "mm";
    p.requests.set(ScaleRequest{1.0});
    const Scene s = buildScene(f, p);
    ModelKeyFacts facts{"rain.csv", "one value per hexagon", "9.9"};
    const std::vector<std::string> key = modelKeyParagraphs(s, facts);
    const std::string all = joined(key);
    EXPECT_EQ(key.front(), "Rain");
    EXPECT_TRUE(has(all, "\nWhat it shows: the values of the file rain.csv, in millimetres.\n")) << all;
    EXPECT_TRUE(has(all, "The pillars' values go from 1 to 5 millimetres.")) << all;  // the rows of 0 are culled
    EXPECT_TRUE(has(all, "The floor is 0 millimetres; a pillar 10 millimetres high is 5 millimetres.")) << all;
    EXPECT_TRUE(has(all, "each millimetre of height is 0.5 millimetres")) << all;
    EXPECT_TRUE(has(all, "1 cell has no data, in the centre: each is a pit")) << all;
    EXPECT_TRUE(has(all, "Turn the model so the notch is at your near left: north is then away from you")) << all;
    EXPECT_TRUE(has(all, "longer leg running east")) << all;
    EXPECT_TRUE(has(all, "Braille on the plate north of the pillars, in Unified English Braille, uncontracted, reads: "
                         "\"Rain\".")) << all;
    EXPECT_TRUE(has(all, "A tactile scale stands east of the pillars")) << all;
    EXPECT_TRUE(has(all, "on a flat base 2 millimetres thick")) << all;
    const size_t made = all.find("\nHow this model was made\n\nOne value per hexagon.\n");
    ASSERT_NE(made, std::string::npos) << all;
    EXPECT_TRUE(has(all.substr(made), "Made by tsf 9.9 from the file rain.csv.")) << all;
    EXPECT_EQ(all.find("tsf 9.9"), all.find("tsf 9.9", made)) << "the version only in the last section";
    for (const std::string& para : key) EXPECT_EQ(para.find('\n'), std::string::npos);
    const std::string text = modelKeyText(key);
    EXPECT_TRUE(isTsfModelKey(text));
    EXPECT_FALSE(isTsfModelKey("my own notes\n"));

    // A mirrored model says what its underside shows; no marks, says so.
    SceneParams m = test::smallParams(Bottom::Mirrored);
    const std::string mirrored = joined(modelKeyParagraphs(buildScene(f, m), facts));
    EXPECT_TRUE(has(mirrored, "The underside mirrors the top")) << mirrored;
    EXPECT_TRUE(has(mirrored, "made without orientation marks")) << mirrored;
}

// tsf gen writes MODEL.key.txt and MODEL.key.brf beside the model (named
// after it without its extension), lists them, replaces its own on the next
// run and refuses a file of the user's; --no-key leaves them out.
TEST(ModelKeyCli, EveryModelHasItsTextAndBrailleKeys) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "volcano.stl").string();
    const std::string args = "gen " + test::sourcePath("examples/volcano.csv") + " --title Volcano --json -o " + model;
    for (int run = 0; run < 2; ++run) {  // the second run replaces the first's keys
        const test::RunResult r = test::runTsf(args, dir);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const auto j = nlohmann::json::parse(r.out);
        std::vector<std::string> outputs;
        for (const auto& o : j["outputs"]) outputs.push_back(o["path"]);
        EXPECT_NE(std::find(outputs.begin(), outputs.end(), (dir / "volcano.key.txt").string()), outputs.end());
        EXPECT_NE(std::find(outputs.begin(), outputs.end(), (dir / "volcano.key.brf").string()), outputs.end());
    }
    const std::string text = test::readText(dir / "volcano.key.txt");
    EXPECT_TRUE(isTsfModelKey(text));
    EXPECT_TRUE(has(text, "\nVolcano\n")) << text;
    EXPECT_TRUE(has(text, "from the file volcano.csv")) << text;
    EXPECT_TRUE(has(text, "What it shows: the values of the file volcano.csv.")) << text;
    EXPECT_FALSE(has(text, dir.string())) << "no folder of the user's";
    const std::string brf = test::readText(dir / "volcano.key.brf");
    EXPECT_EQ(brf.substr(0, 9), ",VOLCANO\r");
    EXPECT_EQ(brf.back(), '\f');

    // --no-key: none.
    const std::string other = (dir / "plain.stl").string();
    ASSERT_EQ(test::runTsf("gen " + test::sourcePath("examples/volcano.csv") + " --no-key -o " + other, dir).exit_code, 0);
    EXPECT_FALSE(std::filesystem::exists(dir / "plain.key.txt"));
    EXPECT_FALSE(std::filesystem::exists(dir / "plain.key.brf"));

    // A file of the user's where the key would go: refused, untouched.
    test::writeText(dir / "mine.key.txt", "my notes\n");
    const test::RunResult refused = test::runTsf("gen " + test::sourcePath("examples/volcano.csv") + " -o " +
                                                     (dir / "mine.stl").string(),
                                                 dir);
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_TRUE(has(refused.err, "was not written by tsf")) << refused.err;
    EXPECT_EQ(test::readText(dir / "mine.key.txt"), "my notes\n");
    EXPECT_FALSE(std::filesystem::exists(dir / "mine.stl"));
}

}  // namespace
}  // namespace tsf
