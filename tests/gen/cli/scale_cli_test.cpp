// tsf gen --scale/--scale-step: the staircase in the summary and the JSON
// report, one closed solid in the STL, read back by tsf verify through the
// scene sidecar, and refused with exit 2 where it cannot stand.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "gen/mesh_io/mesh_reader.h"
#include "tests/support/mesh_invariants.h"
#include "tests/support/run.h"
#include "tests/support/verify_report.h"

namespace tsf {
namespace {

const char* kField =
    "0,1,2.5,3,1.5,2\n"
    "1,4,2,2,0.5,1\n"
    "2,3.5,5,4.5,1,4\n"
    "0.5,2,1,3,2,3\n"
    "0.5,2,1,3,2,3\n"
    "0,1,2.5,3,1.5,2\n";

TEST(ScaleCli, StaircaseOfRoundValuesBesideThePillarsReadBackByVerify) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", kField);
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + (dir / "f.csv").string() + " --cell 6 --height 12 --scale --json -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto& scale = j["scene"]["scale"];
    ASSERT_TRUE(scale.is_object()) << j["scene"].dump(2);
    // 0..5 over 12 mm: ten steps of 0.5 rise 1.2 mm each.
    EXPECT_DOUBLE_EQ(scale["step"].get<double>(), 0.5);
    EXPECT_FALSE(scale["step_given"].get<bool>());
    ASSERT_EQ(scale["steps"].size(), 10u);
    EXPECT_DOUBLE_EQ(scale["steps"][9]["value"].get<double>(), 5.0);
    EXPECT_NEAR(scale["steps"][9]["height_above_floor_mm"].get<double>(), 12.0, 1e-9);
    EXPECT_NEAR(scale["steps"][0]["height_above_floor_mm"].get<double>(), 1.2, 1e-9);

    const Mesh m = readMesh(model);
    const test::Invariants inv = test::checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);

    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json --json", dir);
    ASSERT_EQ(v.exit_code, test::kExitOk) << v.out << v.err;
    EXPECT_EQ(test::checkStatus(v.out, "scale_read_back"), "pass") << v.out;

    // A step of 2 is kept as given.
    const auto g = test::runTsf("gen " + (dir / "f.csv").string() + " --cell 6 --height 12 --scale-step 2 -o " +
                                (dir / "g.stl").string(), dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    EXPECT_NE(g.out.find("2 steps every 2 east of the pillars"), std::string::npos) << g.out;
}

TEST(ScaleCli, FittedToTheBedWithTheScale) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", kField);
    const std::string model = (dir / "m.stl").string();
    // A 70 mm bed less 5 mm each side: 60 mm, of which the scale takes 4 + 12.7
    // and the orientation tab 23.
    const auto r = test::runTsf("gen " + (dir / "f.csv").string() + " --bed 70x200 --scale -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const Bounds b = meshBounds(readMesh(model));
    EXPECT_LE(b.max.x - b.min.x, 60.0 + 1e-6);
    EXPECT_GT(b.max.x - b.min.x, 50.0);
}

// A field whose only data is one column: culled cells east of it have their
// centres on the boundary between two steps of the scale, where the ray meets
// the riser's edge. That is the scale, not material outside the kept cells.
TEST(ScaleCli, OneColumnOfDataTakesAScale) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "col.csv", "0,,\n1,,\n2,,\n3,,\n4,,\n");
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + (dir / "col.csv").string() + " --scale -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json", dir);
    EXPECT_EQ(v.exit_code, test::kExitOk) << v.out << v.err;
}

TEST(ScaleCli, RefusedWithExitTwoSayingWhatToChange) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", kField);
    const std::string in = (dir / "f.csv").string(), out = (dir / "m.stl").string();
    const auto mirrored = test::runTsf("gen " + in + " --scale --mirror -o " + out, dir);
    EXPECT_EQ(mirrored.exit_code, test::kExitBadInput) << mirrored.output;
    EXPECT_NE(mirrored.err.find("Leave out --mirror"), std::string::npos) << mirrored.err;
    const auto fine = test::runTsf("gen " + in + " --height 12 --scale-step 0.1 -o " + out, dir);
    EXPECT_EQ(fine.exit_code, test::kExitBadInput) << fine.output;
    EXPECT_NE(fine.err.find("--scale-step 0.5"), std::string::npos) << fine.err;
    const auto negative = test::runTsf("gen " + in + " --scale-step -1 -o " + out, dir);
    EXPECT_EQ(negative.exit_code, test::kExitBadInput) << negative.output;
}

}  // namespace
}  // namespace tsf
