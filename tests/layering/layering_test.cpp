// The one-way layering of docs/design.md, checked on the source tree: every
// #include goes to the same layer or an earlier one, and only the
// application (app/) sees CLI11 or the application's own headers.
//
//   base      gen/util/: errors, files, text scanning
//   field     gen/field/: rasters, the hex lattice and the values on it
//   readers   gen/readers/: every input format -> Raster or HexField
//   geometry  gen/geometry/: the Mesh type and exact-geometry helpers
//   model     gen/model/: the Scene, its features, its sidecar
//   mesh      gen/mesh/: the direct mesher, parts, halves, the preview picture
//   mesh_io   gen/mesh_io/: STL, OFF, OBJ, 3MF read and written
//   scad      gen/scad/: the OpenSCAD emitter
//   key       gen/key/: the model's key in text and braille (beside scad)
//   verify    verify/: the self-check of a mesh, and against a Scene
//   runners   runners/: external tools (OpenSCAD engines, PrusaSlicer)
//   pipeline  pipeline/: library entry points (a verified model from a Scene)
//   haptics   haptics/ (beside verify and runners, after gen)
//   app       app/: main, exit codes, every subcommand
#include <gtest/gtest.h>

#include "tests/layering/source_files.h"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace tsf {
namespace {

namespace fs = std::filesystem;

enum class Layer { Base, Field, Readers, Geometry, Model, Mesh, MeshIo, Scad, Key, Verify, Runners, Pipeline, Haptics, App, Tests, Unknown };

const char* name(Layer l) {
    switch (l) {
        case Layer::Base: return "base (gen/util)";
        case Layer::Field: return "field (gen/field)";
        case Layer::Readers: return "readers (gen/readers)";
        case Layer::Geometry: return "geometry (gen/geometry)";
        case Layer::Model: return "model (gen/model)";
        case Layer::Mesh: return "mesh (gen/mesh)";
        case Layer::MeshIo: return "mesh files (gen/mesh_io)";
        case Layer::Scad: return "scad (gen/scad)";
        case Layer::Key: return "key (gen/key)";
        case Layer::Verify: return "verify";
        case Layer::Runners: return "runners";
        case Layer::Pipeline: return "pipeline";
        case Layer::Haptics: return "haptics";
        case Layer::App: return "app";
        case Layer::Tests: return "tests and bench";
        default: return "unknown";
    }
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.rfind(prefix, 0) == 0; }

// The layer of a path relative to the source tree ("gen/readers/pgm_reader.h").
Layer layerOf(const std::string& path) {
    static const std::vector<std::pair<std::string, Layer>> prefixes = {
        {"gen/util/", Layer::Base},        {"gen/field/", Layer::Field}, {"gen/readers/", Layer::Readers},
        {"gen/geometry/", Layer::Geometry}, {"gen/model/", Layer::Model}, {"gen/mesh/", Layer::Mesh},
        {"gen/mesh_io/", Layer::MeshIo},   {"gen/scad/", Layer::Scad},   {"gen/key/", Layer::Key}, {"verify/", Layer::Verify},
        {"runners/", Layer::Runners},      {"pipeline/", Layer::Pipeline}, {"haptics/", Layer::Haptics},
        {"app/", Layer::App},
        {"tests/", Layer::Tests},          {"bench/", Layer::Tests},
    };
    for (const auto& [prefix, layer] : prefixes)
        if (startsWith(path, prefix)) return layer;
    return Layer::Unknown;
}

// What each layer may include besides itself.
const std::map<Layer, std::set<Layer>> kMayInclude = [] {
    using L = Layer;
    const std::set<L> gen = {L::Base, L::Field, L::Readers, L::Geometry, L::Model, L::Mesh, L::MeshIo, L::Scad, L::Key};
    std::set<L> all_libraries = gen;
    all_libraries.insert({L::Verify, L::Runners, L::Pipeline, L::Haptics});
    return std::map<L, std::set<L>>{
        {L::Base, {}},
        {L::Field, {L::Base}},
        {L::Readers, {L::Base, L::Field}},
        {L::Geometry, {L::Base}},
        {L::Model, {L::Base, L::Field, L::Geometry}},
        {L::Mesh, {L::Base, L::Field, L::Geometry, L::Model}},
        {L::MeshIo, {L::Base, L::Geometry}},
        {L::Scad, {L::Base, L::Field, L::Geometry, L::Model, L::Mesh, L::MeshIo}},
        {L::Key, {L::Base, L::Field, L::Geometry, L::Model}},
        {L::Verify, gen},
        {L::Runners, [&] { std::set<L> s = gen; s.insert(L::Verify); return s; }()},
        {L::Pipeline, [&] { std::set<L> s = gen; s.insert({L::Verify, L::Haptics}); return s; }()},
        {L::Haptics, gen},
        {L::App, all_libraries},
        {L::Tests, all_libraries},  // tests run the application as a process, never include it
    };
}();

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
    for (const std::string& rel : test::sourceFiles(root, {"gen", "verify", "runners", "pipeline", "haptics", "app", "tests", "bench"})) {
        std::ifstream in(root / rel);
        std::string text;
        int line = 0;
        while (std::getline(in, text)) {
            ++line;
            std::smatch m;
            if (std::regex_search(text, m, directive)) out.push_back({rel, line, m[2].str(), m[1].str() == "<"});
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
    // The commands live in app/ only; a cli/ folder next to a library
    // would be a second application folder.
    const fs::path root(TSF_SOURCE_DIR);
    for (const char* top : {"gen", "verify", "runners", "pipeline", "haptics", "app"})
        for (const auto& entry : fs::recursive_directory_iterator(root / top))
            EXPECT_FALSE(entry.is_directory() && entry.path().filename() == "cli") << entry.path();
}

// A module is a header and its source (x.h + x.cpp, or either alone), named
// by its path without the extension ("gen/model/scene").
std::string moduleOf(const std::string& path) {
    const size_t dot = path.rfind('.');
    return dot == std::string::npos ? path : path.substr(0, dot);
}

bool isLibraryPath(const std::string& path) {
    const Layer l = layerOf(path);
    return l != Layer::Tests && l != Layer::Unknown;
}

TEST(Layering, NoIncludeCycleBetweenModules) {
    // Edges module -> module from every quoted include of the libraries and
    // the application; a cycle means two modules cannot be understood, tested
    // or moved apart (Tarjan's strongly connected components).
    std::map<std::string, std::set<std::string>> edges;
    const std::vector<Include> all = includes();
    std::set<std::string> modules;
    for (const Include& inc : all)
        if (isLibraryPath(inc.file)) modules.insert(moduleOf(inc.file));
    for (const Include& inc : all) {
        if (inc.angle || !isLibraryPath(inc.file)) continue;
        const std::string from = moduleOf(inc.file), to = moduleOf(inc.target);
        if (from != to && modules.count(to)) edges[from].insert(to);
    }
    ASSERT_GT(edges.size(), 100u);
    std::map<std::string, int> index, low;
    std::vector<std::string> stack;
    std::set<std::string> on_stack;
    int next = 0;
    std::vector<std::vector<std::string>> cycles;
    std::function<void(const std::string&)> visit = [&](const std::string& v) {
        index[v] = low[v] = next++;
        stack.push_back(v);
        on_stack.insert(v);
        for (const std::string& w : edges[v]) {
            if (!index.count(w)) {
                visit(w);
                low[v] = std::min(low[v], low[w]);
            } else if (on_stack.count(w)) {
                low[v] = std::min(low[v], index[w]);
            }
        }
        if (low[v] != index[v]) return;
        std::vector<std::string> component;
        std::string w;
        do {
            w = stack.back();
            stack.pop_back();
            on_stack.erase(w);
            component.push_back(w);
        } while (w != v);
        if (component.size() > 1) cycles.push_back(component);
    };
    for (const std::string& m : modules)
        if (!index.count(m)) visit(m);
    for (const auto& cycle : cycles) {
        std::string text;
        for (const std::string& m : cycle) text += " " + m;
        ADD_FAILURE() << "modules include each other:" << text;
    }
}

// The modules of each folder under the given top-level folders, by folder
// (a subfolder is a folder of its own).
std::map<std::string, std::set<std::string>> modulesPerFolder(std::initializer_list<const char*> tops) {
    const fs::path root(TSF_SOURCE_DIR);
    std::map<std::string, std::set<std::string>> per_folder;
    for (const std::string& rel : test::sourceFiles(root, tops))
        per_folder[fs::path(rel).parent_path().string()].insert(moduleOf(rel));
    return per_folder;
}

// A folder of more than two dozen modules side by side no longer shows the
// flow; split it into subfolders that do.
constexpr size_t kMaxModulesPerFolder = 24;

TEST(Layering, NoFolderHoldsMoreThan24Modules) {
    const auto per_folder = modulesPerFolder(test::kProjectTops);
    ASSERT_GT(per_folder.size(), 10u);
    for (const auto& [folder, mods] : per_folder) EXPECT_LE(mods.size(), kMaxModulesPerFolder) << folder;
}

TEST(Layering, NoTestFolderHoldsMoreThan24Modules) {
    // The tests are read as the code is: a test folder is split by what its
    // tests test (tests/gen/model, tests/gen/cli, ...), one binary still.
    const auto per_folder = modulesPerFolder({"tests", "bench"});
    ASSERT_GT(per_folder.size(), 10u) << "the tests were not found at " << TSF_SOURCE_DIR;
    for (const auto& [folder, mods] : per_folder) EXPECT_LE(mods.size(), kMaxModulesPerFolder) << folder;
}

}  // namespace
}  // namespace tsf
