// A mirrored model stands on z = 0 and the heights tsf states are the mesh's:
// a field of 7000 to 22200 on the default baseline (0) used to float its
// lowest underside 6.3 mm above the bed while the summary gave the model's
// height from z = 0.
#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

#include <nlohmann/json.hpp>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_reader.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

std::string highBand() {
    std::ostringstream csv;
    for (int r = 0; r < 8; ++r) {
        for (int c = 0; c < 10; ++c) csv << (c ? "," : "") << 7000 + 200 * ((r * 7 + c * 3) % 91);
        csv << "\n";
    }
    return csv.str();
}

TEST(MirrorFloor, AMirroredModelStandsOnTheBedAndStatesTheMeshsHeight) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "band.csv", highBand());
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + (dir / "band.csv").string() + " --mirror --json -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out.substr(r.out.find('{')));
    const Mesh mesh = readMesh(model);
    const Bounds b = meshBounds(mesh);
    EXPECT_EQ(b.min.z, 0.0) << "the lowest underside is the bed";
    EXPECT_NEAR(j["scene"]["size_mm"][2].get<double>(), b.max.z, 1e-4) << "the stated height is the mesh's";
    // Values 7000 to 22200: value 0 (the baseline) lies 20 mm x 7000 / 22200 below the bed.
    EXPECT_NEAR(j["scene"]["floor_mm"].get<double>(), -20.0 * 7000 / 22200, 0.01) << j["scene"].dump();
    const std::string key = test::readText(dir / "m.key.txt");
    EXPECT_NE(key.find("The lowest pillar stands on the table"), std::string::npos) << key;

    // The sidecar and the model agree, every pillar read back from the mesh at
    // its value (the read-back counts heights from the floor below the bed).
    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json --json", dir);
    EXPECT_EQ(v.exit_code, test::kExitOk) << v.out << v.err;
    const nlohmann::json vj = nlohmann::json::parse(v.out.substr(v.out.find('{')));
    EXPECT_EQ(vj.dump().find("\"ok\":false"), std::string::npos) << vj.dump();
}

// Tilted tops mirror into the underside; once their corners are known the
// model comes down to its lowest corner, and still reads back.
TEST(MirrorFloor, ATiltedMirroredModelStandsOnItsLowestCorner) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "band.csv", highBand());
    const std::string model = (dir / "t.stl").string();
    const auto r = test::runTsf("gen " + (dir / "band.csv").string() + " --mirror --tilt gradient --json -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out.substr(r.out.find('{')));
    EXPECT_GT(j["scene"]["tilt"]["cells_tilted"].get<int>(), 0) << j["scene"]["tilt"].dump();
    const Bounds b = meshBounds(readMesh(model));
    EXPECT_EQ(b.min.z, 0.0);
    EXPECT_NEAR(j["scene"]["size_mm"][2].get<double>(), b.max.z, 1e-4);
    EXPECT_LT(j["scene"]["floor_mm"].get<double>(), 0.0);
    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json", dir);
    EXPECT_EQ(v.exit_code, test::kExitOk) << v.out << v.err;
}

}  // namespace
}  // namespace tsf
