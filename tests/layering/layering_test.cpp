// The one-way layering of docs/design.md, checked on the source tree: every
// #include goes to the same layer or an earlier one, and only the
// application (gen/app/) sees CLI11 or the application's own headers.
//
//   base      gen/util/, gen/error.h
//   gen       the rest of gen/: field readers, lattice, Scene, mesher, mesh
//             files, OpenSCAD emitter
//   verify    verify/ except verify/render/
//   render    verify/render/: OpenSCAD engines, their output judged by the verifier
//   slicer    verify/slicer/: PrusaSlicer run on a model (uses render's process runner)
//   haptics   haptics/ (beside verify and render, after gen)
//   app       gen/app/: main, exit codes, every subcommand
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace tsf {
namespace {

namespace fs = std::filesystem;

enum class Layer { Base, Gen, Verify, Render, Slicer, Haptics, App, Tests, Unknown };

const char* name(Layer l) {
    switch (l) {
        case Layer::Base: return "base (gen/util, gen/error.h)";
        case Layer::Gen: return "gen";
        case Layer::Verify: return "verify";
        case Layer::Render: return "render (verify/render)";
        case Layer::Slicer: return "slicer (verify/slicer)";
        case Layer::Haptics: return "haptics";
        case Layer::App: return "app (gen/app)";
        case Layer::Tests: return "tests and bench";
        default: return "unknown";
    }
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The layer of a path relative to the source tree ("gen/io/pgm_reader.h").
Layer layerOf(const std::string& path) {
    if (startsWith(path, "gen/util/") || path == "gen/error.h" || path == "gen/error.cpp") return Layer::Base;
    if (startsWith(path, "gen/app/")) return Layer::App;
    if (startsWith(path, "gen/")) return Layer::Gen;
    if (startsWith(path, "verify/render/")) return Layer::Render;
    if (startsWith(path, "verify/slicer/")) return Layer::Slicer;
    if (startsWith(path, "verify/")) return Layer::Verify;
    if (startsWith(path, "haptics/")) return Layer::Haptics;
    if (startsWith(path, "tests/") || startsWith(path, "bench/")) return Layer::Tests;
    return Layer::Unknown;
}

// What each layer may include besides itself.
const std::map<Layer, std::set<Layer>> kMayInclude = {
    {Layer::Base, {}},
    {Layer::Gen, {Layer::Base}},
    {Layer::Verify, {Layer::Base, Layer::Gen}},
    {Layer::Render, {Layer::Base, Layer::Gen, Layer::Verify}},
    {Layer::Slicer, {Layer::Base, Layer::Gen, Layer::Verify, Layer::Render}},
    {Layer::Haptics, {Layer::Base, Layer::Gen}},
    {Layer::App, {Layer::Base, Layer::Gen, Layer::Verify, Layer::Render, Layer::Slicer, Layer::Haptics}},
    {Layer::Tests, {Layer::Base, Layer::Gen, Layer::Verify, Layer::Render, Layer::Slicer, Layer::Haptics}},
};

struct Include {
    std::string file;  ///< the including file, relative to the source tree
    int line;
    std::string target;  ///< as written
    bool angle;          ///< <...> rather than "..."
};

std::vector<Include> includes() {
    const fs::path root(TSF_SOURCE_DIR);
    const std::regex directive(R"(^\s*#\s*include\s*([<"])([^>"]+)[>"])");
    std::vector<Include> out;
    for (const char* top : {"gen", "verify", "haptics", "tests", "bench"}) {
        for (const auto& entry : fs::recursive_directory_iterator(root / top)) {
            const std::string rel = fs::relative(entry.path(), root).string();
            if (rel.find("node_modules") != std::string::npos) continue;
            const std::string ext = entry.path().extension().string();
            if (!entry.is_regular_file() || (ext != ".h" && ext != ".cpp")) continue;
            std::ifstream in(entry.path());
            std::string text;
            int line = 0;
            while (std::getline(in, text)) {
                ++line;
                std::smatch m;
                if (std::regex_search(text, m, directive)) out.push_back({rel, line, m[2].str(), m[1].str() == "<"});
            }
        }
    }
    return out;
}

TEST(Layering, EveryIncludeGoesToTheSameOrAnEarlierLayer) {
    const std::vector<Include> all = includes();
    ASSERT_GT(all.size(), 500u) << "the source tree was not found at " << TSF_SOURCE_DIR;
    size_t checked = 0;
    for (const Include& inc : all) {
        if (inc.angle) continue;
        const Layer to = layerOf(inc.target);
        if (to == Layer::Unknown) continue;  // a header beside the file (tests' own fixtures)
        const Layer from = layerOf(inc.file);
        ++checked;
        const bool ok = from == to || kMayInclude.at(from).count(to) > 0;
        EXPECT_TRUE(ok) << inc.file << ":" << inc.line << ": " << name(from) << " includes " << inc.target << " ("
                        << name(to) << ")";
    }
    EXPECT_GT(checked, 300u);
}

TEST(Layering, OnlyTheApplicationSeesCli11) {
    for (const Include& inc : includes()) {
        if (!inc.angle || !startsWith(inc.target, "CLI/")) continue;
        EXPECT_EQ(layerOf(inc.file), Layer::App) << inc.file << ":" << inc.line << " includes <" << inc.target << ">";
    }
}

TEST(Layering, NoFolderIsNamedCli) {
    // The commands live in gen/app only; a cli/ folder next to a library
    // would be a second application folder.
    const fs::path root(TSF_SOURCE_DIR);
    for (const char* top : {"gen", "verify", "haptics"})
        for (const auto& entry : fs::recursive_directory_iterator(root / top))
            EXPECT_FALSE(entry.is_directory() && entry.path().filename() == "cli") << entry.path();
}

}  // namespace
}  // namespace tsf
