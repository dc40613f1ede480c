// Scene sidecar: every field round-trips bit for bit; malformed input is an
// InputError that names the JSON path (and line/column for bad JSON); writes
// are atomic.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <filesystem>
#include <random>

#include "gen/model/features/tab/tab_state.h"
#include "gen/util/error.h"
#include "gen/mesh/direct_mesher.h"
#include "gen/model/features/scale.h"
#include "gen/model/scene_json.h"
#include "tests/support/fields.h"
#include "tests/verify/verify_test_support.h"
#include "gen/model/build_scene.h"
#include "gen/model/features/legend/legend.h"

namespace tsf {
namespace {

// Bitwise equality for doubles (NaN == NaN, -0 != +0).
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

void expectSameScene(const Scene& a, const Scene& b) {
    EXPECT_EQ(a.grid.cols, b.grid.cols);
    EXPECT_EQ(a.grid.rows, b.grid.rows);
    EXPECT_TRUE(same(a.pitch_mm, b.pitch_mm));
    EXPECT_TRUE(same(a.z_snap_mm, b.z_snap_mm));
    const SceneParams &p = a.params, &q = b.params;
    EXPECT_TRUE(same(p.pitch_mm, q.pitch_mm));
    EXPECT_TRUE(same(p.fit_width_mm, q.fit_width_mm));
    EXPECT_TRUE(same(p.fit_depth_mm, q.fit_depth_mm));
    EXPECT_TRUE(same(p.max_height_mm, q.max_height_mm));
    EXPECT_TRUE(same(p.base_mm, q.base_mm));
    EXPECT_EQ(p.transfer, q.transfer);
    EXPECT_EQ(p.baseline_mode, q.baseline_mode);
    EXPECT_TRUE(same(p.baseline_value, q.baseline_value));
    EXPECT_EQ(p.value_max.has_value(), q.value_max.has_value());
    if (p.value_max && q.value_max) EXPECT_TRUE(same(*p.value_max, *q.value_max));
    EXPECT_TRUE(same(p.z_snap_mm, q.z_snap_mm));
    EXPECT_EQ(p.cull, q.cull);
    EXPECT_EQ(p.bottom, q.bottom);
    EXPECT_EQ(a.mapping.transfer, b.mapping.transfer);
    EXPECT_TRUE(same(a.mapping.baseline, b.mapping.baseline));
    EXPECT_TRUE(same(a.mapping.value_max, b.mapping.value_max));
    EXPECT_TRUE(same(a.mapping.max_height_mm, b.mapping.max_height_mm));
    EXPECT_EQ(a.floor_units, b.floor_units);
    EXPECT_EQ(a.col, b.col);
    EXPECT_EQ(a.row, b.row);
    ASSERT_EQ(a.value.size(), b.value.size());
    for (size_t k = 0; k < a.value.size(); ++k) EXPECT_TRUE(same(a.value[k], b.value[k])) << k;
    EXPECT_EQ(a.top, b.top);
    EXPECT_EQ(a.bottom, b.bottom);
    EXPECT_EQ(a.kept_index, b.kept_index);
    EXPECT_EQ(a.hull, b.hull);
    EXPECT_EQ(a.cells_with_data, b.cells_with_data);
    EXPECT_EQ(a.cells_nonempty, b.cells_nonempty);
    EXPECT_EQ(a.cells_nodata_kept, b.cells_nodata_kept);
    EXPECT_EQ(a.mirror_thickness_units, b.mirror_thickness_units);
    EXPECT_EQ(a.notes, b.notes);
}

Scene awkwardScene() {
    // Values that do not print exactly in decimal, a set value_max, a
    // log transfer, a mirrored bottom and a cell without data.
    HexField f = vtest::smallField();
    f.values[5] = 1.0 / 3.0;
    f.values[9] = 2.0e-17;
    SceneParams p = vtest::smallFieldParams(Bottom::Mirrored, 0.01);
    p.transfer = Transfer::Log;
    p.value_max = 4.7;
    p.baseline_mode = BaselineMode::Value;
    p.baseline_value = 0.1;
    return buildScene(f, p);
}

TEST(SceneJson, RoundTripsEveryField) {
    for (const Scene& s : {awkwardScene(), vtest::smallModel(Bottom::Flat).scene}) {
        const Scene back = sceneFromJson(sceneToJson(s));
        expectSameScene(s, back);
        // Through text too (the file path).
        expectSameScene(s, sceneFromJson(nlohmann::json::parse(sceneToJson(s).dump())));
    }
}

// Reading j is an InputError whose message starts with `start`.
void expectError(const nlohmann::json& j, const std::string& start) {
    try {
        (void)sceneFromJson(j);
        ADD_FAILURE() << "no error, expected " << start;
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind(start, 0), 0u) << e.what();
    }
}

// A flat scene with a braille legend and a tactile scale.
Scene sceneWithAttachments() {
    SceneParams p = vtest::smallFieldParams(Bottom::Flat, 0.01);
    p.pitch_mm = 8.0;
    p.words.title = "Depth";
    p.words.units = "m";
    p.requests.set(ScaleRequest{});
    return buildScene(vtest::smallField(), p);
}

TEST(SceneJson, TheLegendAndTheScaleAreRecordedAsPlacedAndReadWithoutPlacingThem) {
    const Scene s = sceneWithAttachments();
    ASSERT_TRUE(sceneLegend(s));
    ASSERT_TRUE(sceneScale(s));
    const nlohmann::json j = sceneToJson(s);
    EXPECT_EQ(j["version"], kSceneJsonVersion);
    EXPECT_EQ(j["legend"]["dots"].size(), sceneLegend(s)->layout.dots.size());
    // Every member survives the trip, the placed legend and scale included.
    const Scene back = sceneFromJson(j);
    expectSameScene(s, back);
    EXPECT_EQ(sceneToJson(back), j);
    // A table that does not exist: reading translates nothing, so nothing
    // notices; the dots are the recorded ones.
    nlohmann::json other = j;
    other["legend"]["table"] = "no-such-table.ctb";
    other["legend"]["dots"][0] = {j["legend"]["dots"][0][0].get<double>() + 0.25, j["legend"]["dots"][0][1]};
    const Scene moved = sceneFromJson(other);
    ASSERT_TRUE(sceneLegend(moved));
    EXPECT_EQ(moved.params.words.braille_table, "no-such-table.ctb");
    EXPECT_DOUBLE_EQ(sceneLegend(moved)->layout.dots[0].x_mm, sceneLegend(s)->layout.dots[0].x_mm + 0.25);
}

TEST(SceneJson, AVersion4SidecarWithALegendIsRefusedSayingHowToRemakeIt) {
    nlohmann::json j = sceneToJson(sceneWithAttachments());
    j["version"] = 4;
    j["legend"] = {{"title", "Depth"}, {"units", "m"}, {"table", "en-us-g1.ctb"}};
    try {
        (void)sceneFromJson(j);
        FAIL() << "a version 4 legend was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("legend: this sidecar (version 4) records the braille legend as asked for"),
                  std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("tsf gen"), std::string::npos) << e.what();
    }
    // Without a legend a version 4 sidecar is read, its scale as recorded.
    j["legend"] = nullptr;
    const Scene s = sceneFromJson(j);
    ASSERT_TRUE(sceneScale(s));
    EXPECT_EQ(sceneScale(s)->steps.size(), sceneScale(sceneWithAttachments())->steps.size());
}

TEST(SceneJson, ARecordedLegendOrScaleThatDoesNotFitIsAnInputError) {
    const nlohmann::json good = sceneToJson(sceneWithAttachments());
    auto j = good;
    j["legend"]["dots"][0] = {-50.0, 0.0};
    expectError(j, "legend.dots[0]: the dot does not lie on the legend's plate");
    j = good;
    j["legend"]["reach_row"] = 1000000;
    expectError(j, "legend.reach_row");
    j = good;
    j["legend"]["standard"]["name"] = "my own";
    expectError(j, "legend.standard.name: not a braille standard this tsf knows");
    j = good;
    j["scale"]["contacts"] = {123456};
    expectError(j, "scale.contacts[0]: is not the index of a cell");
    j = good;
    j["scale"]["steps"] = nlohmann::json::array();
    expectError(j, "scale.steps: a scale has at least one step");
}

// Tilted tops (with crossings and fans) beside both orientation marks.
Scene tiltedMarkedScene(Bottom bottom) {
    SceneParams p = vtest::smallFieldParams(bottom, 0.01);
    p.pitch_mm = 9.0;
    p.marks = MarkParams{};
    p.marks.place = MarkPlace::Data;
    p.tilt = TiltSource::Gradient;
    const HexField f = test::fieldFromFunction(14, 12, [](int c, int r) { return c < 7 && r > 5 ? 6.0 : 1.0 + 0.4 * c + 0.1 * r; });
    return buildScene(f, p);
}

TEST(SceneJson, TheMarksFacesAndTheTiltedTopsAreRecordedAsBuiltAndReadAsRecorded) {
    for (const Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        const Scene s = tiltedMarkedScene(bottom);
        ASSERT_FALSE(s.faces.empty());
        ASSERT_FALSE(s.shapes.empty());
        ASSERT_GT(s.shapes.extra.size(), 0u);
        const nlohmann::json j = sceneToJson(s);
        ASSERT_TRUE(j["faces"].is_object());
        const Scene back = sceneFromJson(j);
        EXPECT_EQ(sceneToJson(back), j);
        EXPECT_EQ(back.drawn_by_face, s.drawn_by_face);
        EXPECT_EQ(back.shapes.crossing_top, s.shapes.crossing_top);
        EXPECT_EQ(back.shapes.centre_top_id, s.shapes.centre_top_id);
        EXPECT_EQ(back.shapes.extra_z, s.shapes.extra_z);
        // The Scene read back draws the same solid, vertex for vertex.
        const Mesh a = meshScene(s), b = meshScene(back);
        EXPECT_EQ(a.triangles, b.triangles);
        EXPECT_EQ(a.positions.size(), b.positions.size());
        // Read as recorded, not built again: a read point moved in the file is the one read.
        nlohmann::json moved = j;
        for (auto& f : moved["faces"]["faces"])
            if (!f["read_point"].is_null()) {
                f["read_point"][0] = f["read_point"][0].get<double>() + 0.125;
                const Scene m = sceneFromJson(moved);
                bool found = false;
                for (const PlanarFace& face : m.faces.faces)
                    found = found || (face.read_point && face.read_point->i == f["read_point"][0].get<double>());
                EXPECT_TRUE(found);
                break;
            }
    }
}

// A sidecar's marks are placed on its own grid: a triangle or notch point far
// outside it (an older sidecar builds the marks' faces again from them) and a
// cell narrower than any model has are InputErrors, not an overflow.
TEST(SceneJson, MarksFarOffTheGridAndTinyCellsAreInputErrors) {
    const Scene s = tiltedMarkedScene(Bottom::Flat);
    ASSERT_TRUE(s.marks.triangle.has_value());
    nlohmann::json j = sceneToJson(s);
    j["version"] = 4;  // faces rebuilt from the marks, as a fuzzer found
    j.erase("faces");
    for (const char* key : {"corner", "east", "north"}) {
        auto far = j;
        far["marks"]["triangle"][key][0] = 1e300;
        expectError(far, std::string("marks.triangle.") + key + ": lies far outside the grid");
        far = j;
        far["marks"]["triangle"][key][1] = -4e9;
        expectError(far, std::string("marks.triangle.") + key + ": lies far outside the grid");
    }
    auto tiny = j;
    tiny["pitch_mm"] = 1e-300;
    expectError(tiny, "pitch_mm: expected at least");
}

// The orientation tab (version 6) is recorded as placed and read as recorded:
// the Scene read back meshes to the same solid; a tab that names a cell it
// does not touch, or a corner away from its lattice point, is an InputError.
TEST(SceneJson, TheOrientationTabIsRecordedAsPlacedAndCheckedWhenRead) {
    SceneParams p;
    p.pitch_mm = 5.0;
    p.cull = Cull::None;
    const Scene s = buildScene(test::fieldFromFunction(8, 10, [](int c, int r) { return 1.0 + (c * 3 + r) % 5; }), p);
    ASSERT_TRUE(sceneTab(s) != nullptr);
    const nlohmann::json j = sceneToJson(s);
    EXPECT_GE(j["version"], 6);  // the tab since version 6
    ASSERT_TRUE(j["marks"]["tab"].is_object());
    const Scene back = sceneFromJson(j);
    EXPECT_EQ(sceneToJson(back), j);
    const Mesh a = meshScene(s), b = meshScene(back);
    EXPECT_EQ(a.triangles, b.triangles);
    EXPECT_EQ(a.positions, b.positions);
    auto j2 = j;
    j2["marks"]["tab"]["touched"][0] = {0, 0};  // the east wall of a cell with a neighbour there
    EXPECT_THROW(sceneFromJson(j2), InputError);
    j2 = j;
    for (auto& q : j2["marks"]["tab"]["outline"])
        if (q[2].get<int64_t>() >= 0) {
            q[0] = q[0].get<double>() + 0.5;
            break;
        }
    try {
        sceneFromJson(j2);
        ADD_FAILURE() << "a tab corner moved off its lattice point was read";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("marks.tab"), std::string::npos) << e.what();
    }
}

TEST(SceneJson, RecordedFacesAndFansThatReachOutsideTheSceneAreInputErrors) {
    const nlohmann::json good = sceneToJson(tiltedMarkedScene(Bottom::Flat));
    auto j = good;
    j["faces"]["faces"][0]["rings"][0][0] = 1LL << 40;
    expectError(j, "faces.faces[0].rings[0][0]: is not a planar vertex id");
    j = good;
    j["faces"]["faces"][0]["anchor"] = 999999;
    expectError(j, "faces.faces[0].anchor");
    j = good;
    j["faces"]["faces"][0]["across"][0][0] = {2, 999999};
    expectError(j, "faces.faces[0].across[0][0]: expected [0, -1] (outside), [1, face] or [2, cell]");
    j = good;
    j["faces"]["faces"][0]["triangles"][0] = {0, 1};
    expectError(j, "faces.faces[0].triangles[0]: expected three vertex ids");
    j = good;
    j["shapes"]["first_id"] = 3;
    expectError(j, "shapes.first_id: must follow the lattice's and the faces' ids");
    j = good;
    for (auto& c : j["cells"])
        if (c.contains("fan")) {
            c["fan"]["centre_top"] = -5;
            break;
        }
    expectError(j, "cells[");
}

TEST(SceneJson, FileRoundTripOneCellPerLineAndNoTemporaryLeft) {
    const auto dir = vtest::scratchDir("scene_json_file");
    const Scene s = awkwardScene();
    const auto path = dir / "model.stl.scene.json";
    writeSceneJson(s, path.string());
    expectSameScene(s, readSceneJson(path.string()));
    const std::string text = vtest::readText(path);
    EXPECT_NE(text.find("\"format\": \"tsf-scene\""), std::string::npos);
    EXPECT_NE(text.find("\n    {\"bottom\":"), std::string::npos) << "one cell per line";
    size_t files = 0;
    for (const auto& e : std::filesystem::directory_iterator(dir)) (void)e, ++files;
    EXPECT_EQ(files, 1u);
}

// gen formats the cells while the model is written and hands them over:
// the file is the one writeSceneJson writes formatting them itself.
TEST(SceneJson, CellsFormattedAheadGiveTheSameFile) {
    const auto dir = vtest::scratchDir("scene_json_cells_ahead");
    const Scene s = awkwardScene();
    const SceneModelRecord model{"model.stl", FileStamp{17, 0x0123456789abcdefull, StampHash::Xxh3_64}};
    writeSceneJson(s, (dir / "streamed.json").string(), &model);
    const std::string cells = sceneCellsJson(s);
    writeSceneJson(s, (dir / "ahead.json").string(), &model, &cells);
    const std::string streamed = vtest::readText(dir / "streamed.json");
    EXPECT_EQ(vtest::readText(dir / "ahead.json"), streamed);
    EXPECT_NE(streamed.find("\"cells\": [" + cells), std::string::npos);
}

TEST(SceneJson, TheModelItWasWrittenWithIsRecordedAndAnotherVersionRefused) {
    const auto dir = vtest::scratchDir("scene_json_model");
    const Scene s = awkwardScene();
    vtest::writeText(dir / "model.stl", "the model's bytes");
    const SceneModelRecord written{"model.stl", stampFile((dir / "model.stl").string())};
    EXPECT_EQ(written.stamp.bytes, 17);
    EXPECT_EQ(written.stamp.algorithm, StampHash::Xxh3_64);
    // FNV-1a 64 of "a" is 0xaf63dc4c8601ec8c, XXH3-64 of nothing
    // 0x2d06800538d394c2 (the published test vectors).
    EXPECT_EQ(fnv1a64("a", 1), 0xaf63dc4c8601ec8cull);
    vtest::writeText(dir / "empty.stl", "");
    EXPECT_EQ(stampFile((dir / "empty.stl").string()).hash, 0x2d06800538d394c2ull);
    EXPECT_EQ(stampFile((dir / "empty.stl").string(), StampHash::Fnv1a64).hash, kFnv1a64Basis);
    const auto sidecar = dir / "model.stl.scene.json";
    writeSceneJson(s, sidecar.string(), &written);
    std::optional<SceneModelRecord> read;
    expectSameScene(s, readSceneJson(sidecar.string(), &read));
    ASSERT_TRUE(read.has_value());
    EXPECT_EQ(read->file, "model.stl");
    EXPECT_EQ(read->stamp, written.stamp);
    EXPECT_NO_THROW(checkSceneModelRecord(*read, sidecar.string(), (dir / "model.stl").string()));
    // Another file of another name (an OpenSCAD render of the model): not compared.
    vtest::writeText(dir / "model.openscad.stl", "other bytes");
    EXPECT_NO_THROW(checkSceneModelRecord(*read, sidecar.string(), (dir / "model.openscad.stl").string()));
    // The same name with other bytes (a later run's model): refused, even at the same size.
    vtest::writeText(dir / "model.stl", "the model's bytez");
    try {
        checkSceneModelRecord(*read, sidecar.string(), (dir / "model.stl").string());
        ADD_FAILURE() << "a sidecar of another run was accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("different runs of tsf gen"), std::string::npos) << e.what();
    }
    // A sidecar written before XXH3 records FNV-1a under its own name, and
    // the model is stamped that way to compare.
    vtest::writeText(dir / "model.stl", "the model's bytes");
    const SceneModelRecord older{"model.stl", stampFile((dir / "model.stl").string(), StampHash::Fnv1a64)};
    writeSceneJson(s, sidecar.string(), &older);
    const std::string older_text = vtest::readText(sidecar);
    EXPECT_NE(older_text.find("\"fnv1a64\""), std::string::npos);
    EXPECT_EQ(older_text.find("\"xxh3_64\""), std::string::npos);
    readSceneJson(sidecar.string(), &read);
    ASSERT_TRUE(read.has_value());
    EXPECT_EQ(read->stamp.algorithm, StampHash::Fnv1a64);
    EXPECT_NO_THROW(checkSceneModelRecord(*read, sidecar.string(), (dir / "model.stl").string()));
    vtest::writeText(dir / "model.stl", "the model's bytez");
    EXPECT_THROW(checkSceneModelRecord(*read, sidecar.string(), (dir / "model.stl").string()), InputError);
    // A sidecar without the record (older tsf, or --scad only) reads as before.
    writeSceneJson(s, sidecar.string());
    readSceneJson(sidecar.string(), &read);
    EXPECT_FALSE(read.has_value());
}

TEST(SceneJson, MalformedMembersNameTheirPath) {
    const nlohmann::json good = sceneToJson(vtest::smallModel(Bottom::Flat).scene);
    {
        auto j = good;
        j["cells"][12]["top"] = "high";
        expectError(j, "cells[12].top: expected an integer, found string");
    }
    {
        auto j = good;
        j["cells"][3].erase("bottom");
        expectError(j, "cells[3].bottom: missing");
    }
    {
        auto j = good;
        j["cells"][4]["top"] = j["cells"][4]["bottom"];
        expectError(j, "cells[4].top: must be above bottom");
    }
    {
        auto j = good;
        j["cells"][2]["col"] = 99;
        expectError(j, "cells[2].col: must be between 0 and 6");
    }
    {
        auto j = good;
        std::swap(j["cells"][5], j["cells"][6]);
        expectError(j, "cells[6]: cells must be listed once each");
    }
    {
        auto j = good;
        j["params"]["transfer"] = "cubic";
        expectError(j, "params.transfer: unknown value \"cubic\" (expected one of: linear, sqrt, log)");
    }
    {
        auto j = good;
        j["mapping"]["baseline"] = nullptr;
        expectError(j, "mapping.baseline: expected a number, found null");
    }
    {
        auto j = good;
        j["version"] = kSceneJsonVersion + 1;
        expectError(j, "version: unsupported version " + std::to_string(kSceneJsonVersion + 1));
    }
    {
        auto j = good;
        j["format"] = "something-else";
        expectError(j, "format: expected \"tsf-scene\"");
    }
    {
        auto j = good;
        j["grid"]["cols"] = 100000;
        j["grid"]["rows"] = 100000;
        expectError(j, "grid: a grid of 10000000000 cells is larger");
    }
    {
        auto j = good;
        j["hull"][0] = 7;
        expectError(j, "hull[0]: expected [i, j]");
    }
    expectError(nlohmann::json::array(), "(top level): expected an object");
}

TEST(SceneJson, BadJsonTextHasLineAndColumn) {
    const auto dir = vtest::scratchDir("scene_json_bad");
    const auto path = dir / "bad.scene.json";
    vtest::writeText(path, "{\n  \"format\": \"tsf-scene\",\n  \"version\": 1,\n  \"grid\": {\"cols\": 2,, }\n}\n");
    try {
        readSceneJson(path.string());
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.path(), path.string());
        EXPECT_EQ(e.line(), 4);
        EXPECT_EQ(e.column(), 22);  // the second comma
        EXPECT_NE(std::string(e.what()).find("not valid JSON"), std::string::npos) << e.what();
    }
    // A semantic error in a file names the file and the JSON path.
    vtest::writeText(path, "{\"format\": \"tsf-scene\", \"version\": 1}");
    try {
        readSceneJson(path.string());
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.path(), path.string());
        EXPECT_EQ(e.detail(), "grid: missing");
    }
    EXPECT_THROW(readSceneJson((dir / "absent.json").string()), InputError);
}

// Fuzz: mutated sidecars either read or throw InputError; nothing else.
TEST(SceneJson, MutatedInputReadsOrThrowsInputError) {
    const Scene s = vtest::smallModel(Bottom::Mirrored).scene;
    const std::string text = sceneToJson(s).dump();
    const nlohmann::json tree = sceneToJson(s);
    std::mt19937 rng(2024);
    const std::string alphabet = "{}[]\":,.-+eE0123456789 truenullfasx\n";
    size_t read = 0, rejected = 0;
    auto attempt = [&](const std::string& t) {
        try {
            const Scene back = parseSceneJson(t, "fuzz.json");
            EXPECT_EQ(int64_t(back.kept_index.size()), back.grid.cellCount());
            ++read;
        } catch (const InputError&) {
            ++rejected;
        }
    };
    for (int i = 0; i < 1500; ++i) {
        std::string t = text;
        const int edits = 1 + int(rng() % 4);
        for (int e = 0; e < edits; ++e) {
            const size_t at = rng() % t.size();
            switch (rng() % 4) {
                case 0: t[at] = alphabet[rng() % alphabet.size()]; break;
                case 1: t.erase(at, 1 + rng() % 8); break;
                case 2: t.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
                default: t.resize(at); break;
            }
            if (t.empty()) t = "{";
        }
        attempt(t);
    }
    // Structured: one member of the tree replaced by a value of another type.
    const std::vector<nlohmann::json> odd{nullptr, true, -1, 0, 1e300, -1e300, "x", nlohmann::json::array(),
                                          nlohmann::json::object(), 4294967296LL, -9223372036854775807LL};
    std::vector<nlohmann::json::json_pointer> paths;
    const nlohmann::json flat = tree.flatten();
    for (auto it = flat.begin(); it != flat.end(); ++it) paths.emplace_back(it.key());
    for (const auto& path : paths) {
        for (const auto& v : odd) {
            nlohmann::json j = tree;
            j[path] = v;
            attempt(j.dump());
        }
    }
    EXPECT_GT(read, 0u);
    EXPECT_GT(rejected, 1000u);
}

}  // namespace
}  // namespace tsf
