// One feature, one contract (gen/model/feature.h): a feature in the registry
// is named in its own files, the registry and the command line that asks
// for it, and nowhere else in the libraries or the application. Everything
// else reaches it through the contract (the lists of attachments, records
// and facts, buildScene, the key, the tiles). Comments and string literals
// are not names: a message may say "--scale", a comment may point to a file.
#include <gtest/gtest.h>

#include "tests/layering/source_files.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

namespace tsf {
namespace {

namespace fs = std::filesystem;

struct MigratedFeature {
    const char* name;
    /// Its identifiers and the paths of its headers. (The scale's
    /// ScaleLevel is left out: tsf::haptics has a ScaleLevel of its own.)
    std::regex names;
    /// Files that may name it: its own, the registry's, the command line's;
    /// each with why.
    std::set<std::string> allowed;
};

const std::vector<MigratedFeature>& migrated() {
    static const std::vector<MigratedFeature> list = {
        {"orientation tab",
         std::regex(R"(\b(OrientationTab|sceneTab|TileTabRequest|placeTab|tabTopAt|tabAreaMm2|meshTabBody|tabBoxMm|)"
                    R"(tabClaim|tabAttachment|tabProbes|checkTabInScene|checkTab|tabRecord|readTabRecord|tabFactsJson|)"
                    R"(tabFactsLines|tabWidthMm|tabScadPiece|tabFeature|kTab\w+)\b|features/tab/|scad_tab\.h)"),
         {
             // Its own files.
             "gen/model/features/tab/orientation_tab.h", "gen/model/features/tab/orientation_tab.cpp",
             "gen/model/features/tab/orientation_tab_record.h", "gen/model/features/tab/orientation_tab_record.cpp",
             "gen/model/features/tab/tab_feature.h", "gen/model/features/tab/tab_feature.cpp",
             "gen/model/features/tab/tab_scad.cpp", "gen/model/features/tab/tab_state.h",
             // The registry.
             "gen/model/feature_registry.cpp",
         }},
        {"scale",
         std::regex(R"(\b(SceneScale|ScaleStep|ScaleRequest|scaleLevels|chooseScaleStep|placeScale|sceneScale|scaleTopAt|)"
                    R"(meshScaleBody|scaleBoxMm|scaleAttachment|checkScale|scaleProbes|scaleRecord|readScaleRecord|)"
                    R"(scaleFactsJson|scaleFactsLines|scaleKeyParagraph|scaleFeature|scaleScadPiece|kScale\w+)\b|)"
                    R"(features/scale(_record|_feature)?\.h|scene_scale\.h|\b(params|p)\.scale\b)"),
         {
             // Its own files.
             "gen/model/features/scale.h", "gen/model/features/scale.cpp", "gen/model/features/scale_record.h",
             "gen/model/features/scale_record.cpp", "gen/model/features/scale_feature.h",
             "gen/model/features/scale_feature.cpp", "gen/model/features/scale_scad.cpp", "gen/model/scene_scale.h",
             // The registry.
             "gen/model/feature_registry.cpp",
             // The command line: --scale and --scale-step fill in its request.
             "app/gen_options.cpp",
         }},
        {"ruler",
         std::regex(R"(\b(SceneRuler|RulerTooth|RulerRequest|sceneRuler|placeRuler|meshRulerBody|rulerAttachment|)"
                    R"(rulerBoxMm|rulerTopAt|rulerProbes|checkRuler|rulerRecord|readRulerRecord|rulerFactsJson|)"
                    R"(rulerFactsLines|rulerKeyParagraph|rulerScadPiece|rulerFeature|kRuler\w+)\b|features/ruler/)"),
         {
             // Its own files.
             "gen/model/features/ruler/ruler.h", "gen/model/features/ruler/ruler.cpp",
             "gen/model/features/ruler/ruler_record.cpp", "gen/model/features/ruler/ruler_feature.h",
             "gen/model/features/ruler/ruler_feature.cpp",
             // The registry.
             "gen/model/feature_registry.cpp",
             // The command line: --ruler fills in its request.
             "app/gen_options.cpp",
         }},
        // A tile of a model cut into tiles: its state, its requests, its
        // layout and its code. The tiles' outputs (their files, their
        // check as an assembly, the summary's tiles) are the tiles' own.
        {"tile",
         std::regex(R"(\b(SceneTile|TilePlace|TileRequest|TiledWholeRequest|TileLayout|planTiles|tileParams|placeTileCode|)"
                    R"(sceneTile|keepTileShare|tileKeepsLevel|tileBottomHoles|tileGivenMarks|tileFeature|kTileCode\w+|kMaxTileCount|)"
                    R"(kToothMm)\b|features/tiles\.h|features/tile_(feature|code)\.h|scene_tiles\.h)"),
         {
             // Its own files.
             "gen/model/features/tiles.h", "gen/model/features/tiles.cpp", "gen/model/features/tile_feature.h",
             "gen/model/features/tile_feature.cpp", "gen/model/features/tile_code.h", "gen/model/features/tile_code.cpp",
             "gen/model/scene_tiles.h",
             // The registry.
             "gen/model/feature_registry.cpp",
             // Its outputs: the tiles made and verified as an assembly, their
             // files and their lines in the summary.
             "pipeline/verified_tiles.h", "pipeline/verified_tiles.cpp", "verify/tiles_check.h", "verify/tiles_check.cpp",
             "app/tiles_output.h", "app/tiles_output.cpp", "app/gen_run/bed_tiles.cpp",
         }},
        {"legend",
         std::regex(R"(\b(SceneLegend|sceneLegend|placeLegend|LegendParams|LegendLayout|LegendDot|layoutLegend|)"
                    R"(legendRangeText|PlateOutline|PlateSpec|legendPlateOutline|legendEastOnLattice|meshPlateBody|)"
                    R"(meshLegendPlate|meshLegendDots|legendPlateMesh|legendDotsMesh|legendAttachment|legendProbes|)"
                    R"(legendBoxMm|legendClaim|legendTopAt|legendScadPiece|legendRecord|readLegendRecord|legendFactsJson|)"
                    R"(legendFactsLines|legendBraille|legendFeature|kMinMirroredPlateMm)\b|features/legend/|\b(params|p)\.legend\b)"),
         {
             // Its own files.
             "gen/model/features/legend/legend.h", "gen/model/features/legend/legend.cpp",
             "gen/model/features/legend/legend_scene.h", "gen/model/features/legend/legend_scene.cpp",
             "gen/model/features/legend/legend_plate.h", "gen/model/features/legend/legend_plate.cpp",
             "gen/model/features/legend/legend_mesh.h", "gen/model/features/legend/legend_mesh.cpp",
             "gen/model/features/legend/legend_join.h", "gen/model/features/legend/legend_join.cpp",
             "gen/model/features/legend/legend_record.h", "gen/model/features/legend/legend_record.cpp",
             "gen/model/features/legend/legend_scad.cpp", "gen/model/features/legend/legend_feature.h",
             "gen/model/features/legend/legend_feature.cpp",
             // The registry.
             "gen/model/feature_registry.cpp",
         }},
        {"class textures",
         std::regex(R"(\b(SceneTextures|ClassTexture|ClassTextureRequest|Texture|textureName|textureNamed|textureFeel|)"
                    R"(sceneTextures|classTexturesApply|decideClassTextures|classTextureMapping|classTextureLegendLines|)"
                    R"(classTexture|classTextureShapes|frameClassTextures|classTexturesRecord|readClassTexturesRecord|)"
                    R"(classTexturesFactsJson|classTexturesFactsLines|classTexturesFeature|kTexture\w+|)"
                    R"(kMinFeltTextureReliefMm|class_textures)\b|\.textures\b|features/class_textures|scene_textures\.h)"),
         {
             // Its own files.
             "gen/model/features/class_textures.h", "gen/model/features/class_textures.cpp",
             "gen/model/features/class_textures_record.h", "gen/model/features/class_textures_record.cpp",
             "gen/model/features/class_textures_feature.h", "gen/model/features/class_textures_feature.cpp",
             "gen/model/scene_textures.h",
             // The registry.
             "gen/model/feature_registry.cpp",
             // The command line: --classes fills in its request.
             "app/gen_options.cpp",
         }},
    };
    return list;
}

/// The text without comments and string and character literals (each
/// replaced by a space; newlines kept).
std::string codeOnly(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        if (text.compare(i, 2, "//") == 0) {
            while (i < text.size() && text[i] != '\n') ++i;
        } else if (text.compare(i, 2, "/*") == 0) {
            const size_t end = text.find("*/", i + 2);
            i = end == std::string::npos ? text.size() : end + 2;
            out += ' ';
        } else if (text.compare(i, 2, "R\"") == 0) {
            const size_t open = text.find('(', i);
            const std::string close = ")" + text.substr(i + 2, open - i - 2) + "\"";
            const size_t end = text.find(close, open);
            i = end == std::string::npos ? text.size() : end + close.size();
            out += ' ';
        } else if (text[i] == '"' || text[i] == '\'') {
            const char q = text[i++];
            while (i < text.size() && text[i] != q && text[i] != '\n') i += text[i] == '\\' ? 2 : 1;
            ++i;
            out += ' ';
        } else {
            out += text[i++];
        }
    }
    return out;
}

TEST(FeatureNames, CodeOnlyDropsCommentsAndLiterals) {
    EXPECT_EQ(codeOnly("a // placeScale\nb \"placeScale\" c"), "a \nb   c");
    EXPECT_EQ(codeOnly("x /* sceneScale */ y 'q'"), "x   y  ");
}

TEST(FeatureNames, AFeatureOfTheRegistryIsNamedOnlyInItsOwnFilesTheRegistryAndTheCommandLine) {
    const fs::path root(TSF_SOURCE_DIR);
    size_t files = 0;
    for (const std::string& rel : test::sourceFiles(root, test::kProjectTops)) {
        ++files;
        std::ifstream in(root / rel);
        std::stringstream text;
        text << in.rdbuf();
        // Includes are names too: keep the include lines' paths.
        std::string code = codeOnly(text.str());
        std::istringstream lines(text.str());
        for (std::string line; std::getline(lines, line);)
            if (line.rfind("#include", 0) == 0) code += "\n" + line;
        for (const MigratedFeature& f : migrated()) {
            if (f.allowed.count(rel)) continue;
            std::smatch m;
            EXPECT_FALSE(std::regex_search(code, m, f.names))
                << rel << " names the " << f.name << " (" << m.str() << ") outside its own files and the registry";
        }
    }
    EXPECT_GT(files, 300u) << "the source tree was not found at " << TSF_SOURCE_DIR;
}

TEST(FeatureNames, EveryAllowedFileExists) {
    // A file that was moved or renamed must leave the list, not stay as a
    // blind spot.
    for (const MigratedFeature& f : migrated())
        for (const std::string& rel : f.allowed)
            EXPECT_TRUE(fs::exists(fs::path(TSF_SOURCE_DIR) / rel)) << rel;
}

}  // namespace
}  // namespace tsf
