// tsf coupon: the calibration piece is an ordinary verified tsf model whose
// heights are the steps and ridges it announces, in whole layers.
#include <gtest/gtest.h>

#include <string>

#include <nlohmann/json.hpp>

#include "tests/support/run.h"

namespace tsf {
namespace {

TEST(CouponCli, WritesAVerifiedModelOfWholeLayerStepsRidgesMarksAndBraille) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "coupon.stl").string();
    const auto r = test::runTsf("coupon -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    EXPECT_NE(r.out.find("4 plateaus at 0.2 0.6 1 2 mm above the floor"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("  tsf gen "), std::string::npos) << "says how it is made:\n" << r.out;
    EXPECT_NE(r.out.find("steps"), std::string::npos) << r.out;
    EXPECT_TRUE(std::filesystem::exists(model + ".coupon.csv"));

    // Verified as a solid at its heights and as a tactile graphic.
    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --json", dir);
    EXPECT_EQ(v.exit_code, test::kExitOk) << v.out;
    const nlohmann::json j = nlohmann::json::parse(v.out);
    for (const auto& c : j["checks"]) EXPECT_NE(c["status"], "fail") << c.dump();

    // Its field: the four steps on the north rows, ridges of 1, 2 and 3 cells on the south rows.
    const std::string csv = test::readText(model + ".coupon.csv");
    EXPECT_EQ(csv.substr(0, csv.find('\n')), "0.2,0.2,0.2,0.2,0,0.6,0.6,0.6,0.6,0,1,1,1,1,0,2,2,2,2,0");
    EXPECT_NE(csv.find("\n1,0,1,0,1,0"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\n1,1,0,0,1,1,0,0"), std::string::npos) << csv;
    EXPECT_NE(csv.find("\n1,1,1,0,0,0,1,1,1"), std::string::npos) << csv;
}

// At 0.1 mm layers the steps are 0.2, 0.5, 1 and 2 mm and the dots five layers (0.5 mm).
TEST(CouponCli, StepsAndDotsFollowTheLayer) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "c.stl").string();
    const auto r = test::runTsf("coupon --layer 0.1 -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    EXPECT_NE(r.out.find("4 plateaus at 0.2 0.5 1 2 mm"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("0.50 mm high (5 whole layers of 0.1 mm"), std::string::npos) << r.out;
    const auto missing = test::runTsf("coupon", dir);
    EXPECT_EQ(missing.exit_code, test::kExitBadInput) << missing.out;
}

}  // namespace
}  // namespace tsf
