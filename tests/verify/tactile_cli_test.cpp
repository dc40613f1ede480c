// tsf verify --tactile: the model as a hand reads it (verify/tactile.h).
// A needle, a blade, a pit narrower than a fingertip and a model without
// orientation marks fail; a plain block and the bundled volcano pass.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run.h"
#include "tests/support/verify_report.h"

namespace tsf {
namespace {
namespace fs = std::filesystem;

// The status of check `id` in `tsf verify --json` output ("" when absent).
std::string statusOf(const std::string& json_text, const std::string& id) { return test::checkStatus(json_text, id); }

std::string noteOf(const std::string& json_text, const std::string& id) {
    const nlohmann::json c = test::checkOf(nlohmann::json::parse(json_text, nullptr, false), id);
    return c.is_object() ? c.value("note", "") : "";
}

int64_t countOf(const std::string& json_text, const std::string& id) {
    const nlohmann::json c = test::checkOf(nlohmann::json::parse(json_text, nullptr, false), id);
    return c.is_object() ? c.value("count", int64_t(-1)) : -1;
}

// A closed box [0, w] x [0, d] x [0, h] as OFF text.
std::string boxOff(double w, double d, double h) {
    return "OFF\n8 12 0\n0 0 0\n" + std::to_string(w) + " 0 0\n" + std::to_string(w) + " " + std::to_string(d) + " 0\n0 " +
           std::to_string(d) + " 0\n0 0 " + std::to_string(h) + "\n" + std::to_string(w) + " 0 " + std::to_string(h) + "\n" +
           std::to_string(w) + " " + std::to_string(d) + " " + std::to_string(h) + "\n0 " + std::to_string(d) + " " +
           std::to_string(h) +
           "\n3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";
}

TEST(TactileCli, APlainBlockPasses) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "block.off", boxOff(30, 20, 5));
    const auto r = test::runTsf("verify " + (dir / "block.off").string() + " --tactile --json", dir);
    EXPECT_EQ(r.exit_code, test::kExitOk) << r.out;
    for (const char* id : {"tactile_sharp_points", "tactile_knife_edges", "tactile_finger_reach"})
        EXPECT_EQ(statusOf(r.out, id), "pass") << id << "\n" << r.out;
}

// A 10 mm spike on a 0.5 mm square base: a valid solid, and a prick.
TEST(TactileCli, ANeedleIsASharpPoint) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "needle.off",
                    "OFF\n5 6 0\n0 0 0\n0.5 0 0\n0.5 0.5 0\n0 0.5 0\n0.25 0.25 10\n"
                    "3 0 2 1\n3 0 3 2\n3 0 1 4\n3 1 2 4\n3 2 3 4\n3 3 0 4\n");
    const auto plain = test::runTsf("verify " + (dir / "needle.off").string() + " --no-printability", dir);
    EXPECT_EQ(plain.exit_code, test::kExitOk) << "a valid solid:\n" << plain.out;
    const auto r = test::runTsf("verify " + (dir / "needle.off").string() + " --tactile --json", dir);
    EXPECT_EQ(r.exit_code, test::kExitCheckFailed) << r.out;
    EXPECT_EQ(statusOf(r.out, "tactile_sharp_points"), "fail") << r.out;
    EXPECT_EQ(countOf(r.out, "tactile_sharp_points"), 1) << "the apex, and only it:\n" << r.out;
    const auto text = test::runTsf("verify " + (dir / "needle.off").string() + " --tactile", dir);
    EXPECT_NE(text.out.find("at (0.250, 0.250, 10.000) mm: a point as narrow as a cone of"), std::string::npos) << text.out;

    // The same spike, open at its foot, standing on a 0.5 mm plate: not a
    // closed solid, and its tip is still found.
    test::writeText(dir / "on_plate.off",
                                              "OFF\n13 16 0\n0 0 0\n20 0 0\n20 20 0\n0 20 0\n0 0 0.5\n20 0 0.5\n20 20 0.5\n0 20 0.5\n"
                                              "9.75 9.75 0.5\n10.25 9.75 0.5\n10.25 10.25 0.5\n9.75 10.25 0.5\n10 10 10.5\n"
                                              "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n"
                                              "3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n3 8 9 12\n3 9 10 12\n3 10 11 12\n3 11 8 12\n");
    const auto on_plate = test::runTsf("verify " + (dir / "on_plate.off").string() + " --tactile --json", dir);
    EXPECT_EQ(on_plate.exit_code, test::kExitCheckFailed) << on_plate.out;
    EXPECT_EQ(statusOf(on_plate.out, "tactile_sharp_points"), "fail") << on_plate.out;
}

// A wedge 10 mm tall whose vertical edge is 10 degrees: a blade.
TEST(TactileCli, ABladeIsAKnifeEdge) {
    const auto dir = test::scratchDir();
    // The triangle (0, 0) (20, 0) (20, 20 tan 10 deg) extruded from z = 0 to 10.
    const std::string t = std::to_string(20 * 0.17632698070846498);
    test::writeText(dir / "wedge.off", "OFF\n6 8 0\n0 0 0\n20 0 0\n20 " + t + " 0\n0 0 10\n20 0 10\n20 " + t +
                                           " 10\n3 0 2 1\n3 3 4 5\n3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 2 0 3\n3 2 3 5\n");
    const auto r = test::runTsf("verify " + (dir / "wedge.off").string() + " --tactile --json", dir);
    EXPECT_EQ(r.exit_code, test::kExitCheckFailed) << r.out;
    EXPECT_EQ(statusOf(r.out, "outward_orientation"), "pass") << r.out;
    EXPECT_EQ(statusOf(r.out, "tactile_knife_edges"), "fail") << r.out;
    EXPECT_EQ(countOf(r.out, "tactile_knife_edges"), 1) << "the vertical 10-degree edge:\n" << r.out;
}

// A pillar 3 mm across, 4 mm lower than the six around it: a pit no
// fingertip reaches the bottom of. The same pit 1 mm deep passes.
TEST(TactileCli, APitNarrowerThanAFingertipIsFound) {
    const auto dir = test::scratchDir();
    std::string deep, shallow;
    for (int r = 0; r < 7; ++r) {
        for (int c = 0; c < 7; ++c) {
            deep += std::string(c ? "," : "") + (r == 3 && c == 3 ? "6" : "10");
            shallow += std::string(c ? "," : "") + (r == 3 && c == 3 ? "9" : "10");
        }
        deep += "\n";
        shallow += "\n";
    }
    test::writeText(dir / "deep.csv", deep);
    test::writeText(dir / "shallow.csv", shallow);
    for (const std::string name : {"deep", "shallow"}) {
        const std::string model = (dir / (name + ".stl")).string();
        const auto g = test::runTsf("gen " + (dir / (name + ".csv")).string() + " --cell 3 --height 10 --transfer linear --baseline zero -o " + model, dir);
        ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
        const auto r = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --json", dir);
        // tsf gen's self-check says so as a warning, and writes the model.
        const bool warned = g.out.find("warn      a fingertip reaches the bottom") != std::string::npos;
        EXPECT_EQ(warned, name == "deep") << g.out;
        // The options given are kept; the summary names one that passes, tried.
        if (name == "deep") EXPECT_NE(g.out.find("tried: --transfer log passes every tactile check"), std::string::npos) << g.out;
        if (name == "deep") {
            EXPECT_EQ(r.exit_code, test::kExitCheckFailed) << r.out;
            EXPECT_EQ(statusOf(r.out, "tactile_finger_reach"), "fail") << r.out;
            EXPECT_EQ(countOf(r.out, "tactile_finger_reach"), 1) << r.out;
        } else {
            EXPECT_EQ(statusOf(r.out, "tactile_finger_reach"), "pass") << r.out;
        }
    }
}

// With the sidecar: a model made without marks cannot be oriented by hand.
TEST(TactileCli, AModelWithoutOrientationMarksFailsWithItsScene) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "v.stl").string();
    const auto g = test::runTsf("gen " + test::sourcePath("examples/volcano.csv") + " --no-notch --no-triangle -o " + model, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    const auto r = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --json", dir);
    EXPECT_EQ(r.exit_code, test::kExitCheckFailed) << r.out;
    EXPECT_EQ(statusOf(r.out, "tactile_marks"), "fail") << r.out;
}

// The bundled volcano's default model reads by hand: every tactile check passes.
TEST(TactileCli, TheVolcanosDefaultModelPasses) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "v.stl").string();
    const auto g = test::runTsf("gen " + test::sourcePath("examples/volcano.csv") + " -o " + model, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    const auto r = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --json", dir);
    EXPECT_EQ(r.exit_code, test::kExitOk) << r.out;
    for (const char* id : {"tactile_sharp_points", "tactile_knife_edges", "tactile_finger_reach", "tactile_marks"})
        EXPECT_EQ(statusOf(r.out, id), "pass") << id;
}

// The tactile scale stands a groove away from the pillars (so the hand tells
// it from the data); the groove is too narrow for a fingertip to reach its
// floor, but no value stands there: with the Scene the model passes, and
// the note gives the groove's area apart. Without the Scene every pit counts.
TEST(TactileCli, TheGrooveBesideTheScaleHoldsNoValue) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "v.stl").string();
    const auto g = test::runTsf("gen " + test::sourcePath("examples/volcano.vrt") + " --title Volcano --scale -o " + model, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    const auto with = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --json", dir);
    EXPECT_EQ(with.exit_code, test::kExitOk) << with.out;
    EXPECT_EQ(statusOf(with.out, "tactile_finger_reach"), "pass") << with.out;
    const std::string note = noteOf(with.out, "tactile_finger_reach");
    EXPECT_NE(note.find("the groove beside the pillars: "), std::string::npos) << note;
    const auto without = test::runTsf("verify " + model + " --tactile --json", dir);
    EXPECT_EQ(statusOf(without.out, "tactile_finger_reach"), "fail") << without.out;
}

// A pillar 3 mm across standing 20 mm above its neighbours breaks under a
// hand; 8 mm across it stands. Neighbouring values closer than a layer are
// a warning, not a failure.
TEST(TactileCli, SlenderPillarsFailAndCloseHeightsWarn) {
    const auto dir = test::scratchDir();
    std::string spike;
    for (int r = 0; r < 5; ++r) {
        for (int c = 0; c < 5; ++c) spike += std::string(c ? "," : "") + (r == 2 && c == 2 ? "20" : "0");
        spike += "\n";
    }
    test::writeText(dir / "spike.csv", spike);
    for (const std::string cell : {"3", "8"}) {
        const std::string model = (dir / ("spike" + cell + ".stl")).string();
        // --height given: tsf keeps it (without it, gen lowers the spike until it stands).
        const auto g = test::runTsf("gen " + (dir / "spike.csv").string() + " --cell " + cell + " --height 20 --cull none -o " + model, dir);
        ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
        const auto r = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --json", dir);
        EXPECT_EQ(statusOf(r.out, "tactile_slender_pillars"), cell == "3" ? "fail" : "pass") << cell << "\n" << r.out;
        if (cell == "3") {
            EXPECT_EQ(countOf(r.out, "tactile_slender_pillars"), 1) << r.out;
        }
    }
    // The volcano at 0.001 mm steps: many neighbours less than 0.5 mm apart; a warning.
    const std::string v = (dir / "v.stl").string();
    ASSERT_EQ(test::runTsf("gen " + test::sourcePath("examples/volcano.csv") + " -o " + v, dir).exit_code, test::kExitOk);
    const auto r = test::runTsf("verify " + v + " --scene " + v + ".scene.json --tactile --json", dir);
    EXPECT_EQ(r.exit_code, test::kExitOk) << r.out;
    EXPECT_EQ(statusOf(r.out, "tactile_height_steps"), "warn") << r.out;
    EXPECT_GT(countOf(r.out, "tactile_height_steps"), 0) << r.out;
}

// Braille as it will print: without --layer the dots are 0.6 mm, whole
// layers at 0.2 and 0.3 mm (pass at both). Made for 0.12 mm layers they
// are four, 0.48 mm, and print 0.4 mm at 0.2 mm layers (fail), 0.5 mm at
// 0.1 mm (pass); made with --layer 0.2 they are three, 0.6 mm (pass).
TEST(TactileCli, BrailleDotsAreCheckedAsTheyWillPrint) {
    const auto dir = test::scratchDir();
    const std::string plain = (dir / "plain.stl").string(), fine = (dir / "fine.stl").string(),
                      layered = (dir / "layered.stl").string();
    const std::string field = test::sourcePath("examples/volcano.csv");
    const auto g = test::runTsf("gen " + field + " --title Volcano -o " + plain, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    EXPECT_NE(g.out.find("0.60 mm high"), std::string::npos) << g.out;
    for (const char* layer : {"0.2", "0.3"}) {
        const auto r = test::runTsf("verify " + plain + " --scene " + plain + ".scene.json --tactile --layer " + layer + " --json", dir);
        EXPECT_EQ(statusOf(r.out, "tactile_braille"), "pass") << layer << "\n" << r.out;
    }

    const auto f = test::runTsf("gen " + field + " --title Volcano --layer 0.12 -o " + fine, dir);
    ASSERT_EQ(f.exit_code, test::kExitOk) << f.out << f.err;
    EXPECT_NE(f.out.find("0.48 mm high (4 whole layers of 0.12 mm"), std::string::npos) << f.out;
    const auto at02 = test::runTsf("verify " + fine + " --scene " + fine + ".scene.json --tactile --json", dir);
    EXPECT_EQ(at02.exit_code, test::kExitCheckFailed) << at02.out;
    EXPECT_EQ(statusOf(at02.out, "tactile_braille"), "fail") << at02.out;
    EXPECT_NE(at02.out.find("print 0.40 mm at 0.2 mm layers"), std::string::npos) << at02.out;
    const auto at01 = test::runTsf("verify " + fine + " --scene " + fine + ".scene.json --tactile --layer 0.1 --json", dir);
    EXPECT_EQ(statusOf(at01.out, "tactile_braille"), "pass") << at01.out;

    const auto l = test::runTsf("gen " + field + " --title Volcano --layer 0.2 -o " + layered, dir);
    ASSERT_EQ(l.exit_code, test::kExitOk) << l.out << l.err;
    EXPECT_NE(l.out.find("0.60 mm high (3 whole layers of 0.2 mm"), std::string::npos) << l.out;
    const auto v = test::runTsf("verify " + layered + " --scene " + layered + ".scene.json --tactile --json", dir);
    EXPECT_EQ(v.exit_code, test::kExitOk) << v.out;
    EXPECT_EQ(statusOf(v.out, "tactile_braille"), "pass") << v.out;
}

// Neighbours 0.4 mm apart (two whole 0.2 mm layers) print apart but feel the
// same: a reader compares steps of about 0.5 mm. 1 mm apart they pass.
TEST(TactileCli, StepsUnderHalfAMillimetreFeelTheSame) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "ramp.csv", "1,2,3,4,5\n1,2,3,4,5\n1,2,3,4,5\n1,2,3,4,5\n");
    for (const std::string height : {"2", "5"}) {
        const std::string model = (dir / ("ramp" + height + ".stl")).string();
        const auto g = test::runTsf("gen " + (dir / "ramp.csv").string() + " --cell 6 --baseline zero --layer 0.2 --height " +
                                        height + " -o " + model,
                                    dir);
        ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
        const auto r = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --layer 0.2 --json", dir);
        EXPECT_EQ(statusOf(r.out, "tactile_height_steps"), height == "2" ? "warn" : "pass") << height << "\n" << r.out;
    }
}

// A pit 8 mm deep (at the default 20 mm) beside a step of 1.2 mm: a height
// low enough for the pit would take the step under 0.5 mm, and a log
// transfer would too, so gen
// keeps its model and says why, never passing by flattening the data.
TEST(TactileCli, GenNeverPassesByFlattening) {
    const auto dir = test::scratchDir();
    std::string grid;
    for (int r = 0; r < 7; ++r) {
        for (int c = 0; c < 7; ++c) grid += std::string(c ? "," : "") + (r == 3 && c == 3 ? "6" : r == 0 && c == 6 ? "9.4" : "10");
        grid += "\n";
    }
    test::writeText(dir / "pit.csv", grid);
    const std::string model = (dir / "pit.stl").string();
    const auto g = test::runTsf("gen " + (dir / "pit.csv").string() + " --cell 3 --baseline zero --json -o " + model, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    const nlohmann::json j = nlohmann::json::parse(g.out);
    EXPECT_FALSE(j["legibility"].contains("changed")) << j["legibility"].dump(1);
    EXPECT_NE(j["legibility"]["why"].get<std::string>().find("would flatten"), std::string::npos) << j["legibility"].dump(1);
    EXPECT_EQ(j["legibility"]["fails"].size(), 1u) << j["legibility"].dump(1);
    EXPECT_EQ(j["scene"]["mapping"]["transfer"], "linear");
}

// gen's self-check and tsf verify --tactile run the same checks on the same
// samples: on every tactile check they give the same verdict and the same
// count (gen says "warn" where verify says "fail": gen writes the model).
TEST(TactileCli, GenAndVerifyGiveTheSameVerdicts) {
    const auto dir = test::scratchDir();
    std::string pit, holes;
    for (int r = 0; r < 7; ++r) {
        for (int c = 0; c < 7; ++c) {
            pit += std::string(c ? "," : "") + (r == 3 && c == 3 ? "6" : "10");
            holes += std::string(c ? "," : "") + ((r == 2 && c == 2) || (r == 4 && c == 3) ? "" : std::to_string(20 + r + c));
        }
        pit += "\n";
        holes += "\n";
    }
    test::writeText(dir / "pit.csv", pit);
    test::writeText(dir / "holes.csv", holes);
    const std::string volcano = test::sourcePath("examples/volcano.csv");
    struct Case {
        std::string name, gen, verify;
    };
    const std::vector<Case> cases = {
        {"volcano", volcano, ""},
        {"mirrored", volcano + " --mirror", ""},
        {"titled", volcano + " --title Volcano --units m --layer 0.2", " --layer 0.2"},
        {"scaled", test::sourcePath("examples/volcano.vrt") + " --title Volcano --scale", ""},
        {"pit", (dir / "pit.csv").string() + " --cell 3 --height 10 --transfer linear --baseline zero", ""},
        {"holes", (dir / "holes.csv").string() + " --cell 3", ""},
    };
    for (const Case& k : cases) {
        const std::string model = (dir / (k.name + ".stl")).string();
        const auto g = test::runTsf("gen " + k.gen + " --json -o " + model, dir);
        ASSERT_EQ(g.exit_code, test::kExitOk) << k.name << "\n" << g.out << g.err;
        const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --json" + k.verify, dir);
        const nlohmann::json gj = nlohmann::json::parse(g.out)["verify"];
        int compared = 0;
        for (const auto& c : gj["checks"]) {
            const std::string id = c["id"];
            if (id.rfind("tactile_", 0) != 0) continue;
            const std::string verified = statusOf(v.out, id);
            EXPECT_EQ(c["status"].get<std::string>(), verified == "fail" ? "warn" : verified) << k.name << " " << id;
            EXPECT_EQ(c["count"].get<int64_t>(), countOf(v.out, id)) << k.name << " " << id;
            // The same measures: the note (depths, areas, the sampling), less what gen adds to a warning.
            std::string note = c["note"];
            if (const size_t at = note.find(" (tsf verify --tactile lists the places)"); at != std::string::npos) note.erase(at);
            EXPECT_EQ(note, noteOf(v.out, id)) << k.name << " " << id;
            ++compared;
        }
        EXPECT_GE(compared, 6) << k.name;
        if (k.name == "pit") {
            EXPECT_EQ(statusOf(v.out, "tactile_finger_reach"), "fail") << v.out;
        } else {
            EXPECT_EQ(statusOf(v.out, "tactile_finger_reach"), "pass") << k.name << "\n" << v.out;
        }
    }
}

}  // namespace
}  // namespace tsf
