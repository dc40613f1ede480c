// The OpenSCAD library itself: every public module and function is
// documented, every documented example renders in the real OpenSCAD (and
// echo examples print what their doc block says), the library adds no
// variables, and numbers survive the trip from C++ text into OpenSCAD.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <random>
#include <regex>

#include "gen/field/hex_grid.h"
#include "gen/scad/scad_library.h"
#include "scad_test_support.h"

namespace tsf {
namespace {
namespace fs = std::filesystem;
using namespace test;

struct DocExample {
    std::string file;
    int line = 0;           ///< 1-based line of "// Example"
    bool echo = false;      ///< "Example(echo):" - compare printed ECHO lines
    std::string code;
    std::vector<std::string> expected_echo;
};

std::vector<std::string> libraryParts() {
    std::vector<std::string> parts;
    for (const std::string& name : scadLibraryFiles(scadLibraryDir()))
        if (name != kScadLibraryEntry) parts.push_back(name);
    return parts;
}

std::vector<DocExample> docExamples() {
    std::vector<DocExample> out;
    for (const std::string& name : libraryParts()) {
        const std::vector<std::string> lines = splitLines(readText(scadLibraryDir() + "/" + name));
        for (size_t i = 0; i < lines.size(); ++i) {
            if (lines[i].rfind("// Example", 0) != 0) continue;
            DocExample ex;
            ex.file = name;
            ex.line = int(i + 1);
            ex.echo = lines[i].rfind("// Example(echo):", 0) == 0;
            for (size_t j = i + 1; j < lines.size() && lines[j].rfind("//   ", 0) == 0; ++j) {
                const std::string body = lines[j].substr(5);
                if (body.rfind("// ECHO: ", 0) == 0) ex.expected_echo.push_back(body.substr(3));
                else ex.code += body + "\n";
            }
            out.push_back(ex);
        }
    }
    return out;
}

TEST(ScadLibrary, EveryPublicModuleAndFunctionHasADocBlock) {
    const std::regex definition(R"(^(module|function) ([a-z][a-z0-9_]*)\s*\()");
    int public_names = 0;
    for (const std::string& name : libraryParts()) {
        const std::vector<std::string> lines = splitLines(readText(scadLibraryDir() + "/" + name));
        for (size_t i = 0; i < lines.size(); ++i) {
            std::smatch m;
            if (!std::regex_search(lines[i], m, definition)) continue;
            ++public_names;
            const std::string kind = m[1] == "module" ? "Module" : "Function";
            // The comment block right above the definition.
            size_t start = i;
            while (start > 0 && lines[start - 1].rfind("//", 0) == 0) --start;
            std::string block;
            for (size_t j = start; j < i; ++j) block += lines[j] + "\n";
            SCOPED_TRACE(name + ": " + m[2].str());
            EXPECT_NE(block.find("// " + kind + ": " + m[2].str() + "()"), std::string::npos);
            EXPECT_NE(block.find("// Usage:"), std::string::npos);
            EXPECT_NE(block.find("// Description:"), std::string::npos);
            EXPECT_NE(block.find("// Arguments:"), std::string::npos);
            EXPECT_NE(block.find("// Example"), std::string::npos);
        }
    }
    EXPECT_GE(public_names, 14);  // every public name of tsf.scad's list is found
}

// A library read with use<> or pasted after [Hidden] must not bring
// variables along (they would show up in, or clash with, the user's file).
TEST(ScadLibrary, DefinesNoTopLevelVariables) {
    const std::regex assignment(R"(^\$?[A-Za-z_][A-Za-z0-9_]*\s*=)");
    for (const std::string& name : scadLibraryFiles(scadLibraryDir())) {
        const std::vector<std::string> lines = splitLines(readText(scadLibraryDir() + "/" + name));
        for (size_t i = 0; i < lines.size(); ++i)
            EXPECT_FALSE(std::regex_search(lines[i], assignment)) << name << ":" << i + 1 << ": " << lines[i];
    }
}

TEST(ScadLibrary, EveryDocExampleRendersAndEchoesWhatItSays) {
    const std::vector<DocExample> examples = docExamples();
    ASSERT_GE(examples.size(), 15u);
    const std::string dir = scratchDir("doc_examples");
    int n = 0;
    for (const DocExample& ex : examples) {
        SCOPED_TRACE(ex.file + ":" + std::to_string(ex.line));
        const std::string scad = dir + "/example" + std::to_string(++n) + ".scad";
        writeText(scad, "use <" + scadLibraryDir() + "/tsf.scad>\n" + ex.code);
        ScadRenderRequest rq;
        rq.scad_path = scad;
        rq.timeout_s = 60;
        if (ex.echo) {
            // An echo example draws nothing; a cube gives OpenSCAD something to export.
            writeText(scad, readText(scad) + "cube(1);\n");
        }
        rq.output_path = dir + "/example" + std::to_string(n) + ".stl";
        const ScadRenderResult r = renderScad(openscad(), rq);
        ASSERT_TRUE(r.ok()) << errorText(r);
        EXPECT_TRUE(r.warnings().empty()) << formatScadMessage(r.warnings().front());
        if (ex.echo) {
            std::vector<std::string> echoed;
            for (const ScadMessage& m : r.messages)
                if (m.kind == ScadMessage::Kind::Echo) echoed.push_back("ECHO: " + m.text);
            ASSERT_FALSE(ex.expected_echo.empty()) << "an echo example must say what it prints";
            EXPECT_EQ(echoed, ex.expected_echo);
        }
    }
}

// The emitter writes doubles as the shortest text that reads back exactly
// (std::to_chars); OpenSCAD must read that text back to the same double, or
// heights and corners would differ from the direct mesher's. Each number is
// compared in OpenSCAD with mantissa * 2^exponent, which is exact.
TEST(ScadLibrary, OpenScadReadsShortestDecimalsExactly) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::string scad = "ok = [\n";
    const int kCount = 400;
    for (int k = 0; k < kCount; ++k) {
        double v = 0;
        switch (k % 4) {
            case 0: v = unit(rng) * 1000; break;
            case 1: v = std::round(unit(rng) * 1e5) / 1e3; break;   // a typical data value
            case 2: v = 150.0 / (3 + unit(rng) * 200); break;          // a fitted pitch
            default: v = std::ldexp(unit(rng), int(unit(rng) * 80) - 40); break;
        }
        int exponent = 0;
        const double mantissa = std::frexp(v, &exponent);
        const int64_t m53 = int64_t(std::ldexp(mantissa, 53));
        ASSERT_EQ(std::ldexp(double(m53), exponent - 53), v);
        char text[64];
        const auto res = std::to_chars(text, text + sizeof text, v);
        scad += "  " + std::string(text, res.ptr) + " == " + std::to_string(m53) + " * pow(2, " +
                std::to_string(exponent - 53) + "),\n";
    }
    scad += "  true];\nbad = [for (i = [0:len(ok) - 1]) if (!ok[i]) i];\necho(bad = bad);\ncube(1);\n";
    const std::string dir = scratchDir("number_roundtrip");
    writeText(dir + "/numbers.scad", scad);
    const ScadRenderResult r = renderStl(dir + "/numbers.scad", dir + "/numbers.stl");
    ASSERT_TRUE(r.ok()) << errorText(r);
    std::string echoed;
    for (const ScadMessage& m : r.messages)
        if (m.kind == ScadMessage::Kind::Echo) echoed = m.text;
    EXPECT_EQ(echoed, "bad = []");
}

TEST(ScadLibrary, SqrtOfThreeIsTheLatticeConstant) {
    // The library computes y = j * cell / (2 * sqrt(3)); tsf uses kSqrt3.
    EXPECT_EQ(std::sqrt(3.0), kSqrt3);
}

}  // namespace
}  // namespace tsf
