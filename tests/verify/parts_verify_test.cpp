// verifyParts: each part alone and the assembly. Parts that touch (a face,
// part of a face) pass; a planted overlap and a planted hole fail, each in
// its own check, with the overlap's volume computed here from the boxes.
#include <gtest/gtest.h>

#include "tests/support/meshes.h"
#include "verify/verify_parts.h"

namespace tsf {
namespace {

VerifyOptions quiet() {
    VerifyOptions vo;
    vo.printability = false;
    return vo;
}

const Check& check(const VerifyReport& r, const std::string& id) {
    const Check* c = r.find(id);
    EXPECT_NE(c, nullptr) << id;
    static const Check none;
    return c ? *c : none;
}

// A 20 x 10 x 5 mm base with a 4 x 4 x 1 mm block standing on part of its
// top and two 1 mm cubes (one part of two pieces) on it elsewhere.
std::vector<MeshPart> touchingParts() {
    return {{"pillars", test::box({0, 0, 0}, {20, 10, 5})},
            {"marks", test::box({2, 2, 5}, {6, 6, 6})},
            {"legend", test::append(test::cube(1, {10, 2, 5}), test::cube(1, {14, 2, 5}))}};
}

TEST(PartsVerify, PartsThatTouchPassAndALaterPartMayBeSeveralPieces) {
    const PartsVerifyReport r = verifyParts(touchingParts(), nullptr, quiet());
    EXPECT_TRUE(r.passed()) << formatPartsReport(r);
    ASSERT_EQ(r.parts.size(), 3u);
    EXPECT_EQ(r.parts[2].report.mesh.component_count, 2u);
    EXPECT_EQ(check(r.assembly, "parts_overlap").status, CheckStatus::Pass);
    EXPECT_NEAR(r.assembly.mesh.volume_mm3, 20 * 10 * 5 + 16 + 2, 1e-9);
    const nlohmann::json j = toJson(r);
    EXPECT_EQ(j["format"], "tsf-verify-parts-report");
    EXPECT_EQ(j["parts"][1]["name"], "marks");
    EXPECT_EQ(j["passed"], true);
    // For people: a section per part, then the assembly.
    const std::string text = formatPartsReport(r);
    EXPECT_NE(text.find("part 2 of 3: marks"), std::string::npos) << text;
    EXPECT_NE(text.find("parts touch, never overlap"), std::string::npos) << text;
}

TEST(PartsVerify, APlantedOverlapFailsWithItsVolume) {
    std::vector<MeshPart> parts = touchingParts();
    parts[1].mesh = test::box({2, 2, 4.5}, {6, 6, 5.5});  // sunk 0.5 mm into the base
    const PartsVerifyReport r = verifyParts(parts, nullptr, quiet());
    EXPECT_FALSE(r.passed());
    for (const PartReport& p : r.parts) EXPECT_TRUE(p.report.passed()) << p.name;  // each part alone is fine
    const Check& c = check(r.assembly, "parts_overlap");
    EXPECT_EQ(c.status, CheckStatus::Fail);
    ASSERT_EQ(c.count, 1);
    EXPECT_NEAR(c.worst[0].amount, 4 * 4 * 0.5, 1e-9);
    EXPECT_NEAR(c.worst[0].at_mm.z, 4.75, 1e-9);
    EXPECT_NE(c.worst[0].detail.find("pillars and marks"), std::string::npos) << c.worst[0].detail;
}

TEST(PartsVerify, APlantedHoleInOnePartFailsThatPart) {
    std::vector<MeshPart> parts = touchingParts();
    parts[1].mesh.triangles.pop_back();
    const PartsVerifyReport r = verifyParts(parts, nullptr, quiet());
    EXPECT_FALSE(r.passed());
    EXPECT_TRUE(r.parts[0].report.passed());
    EXPECT_EQ(check(r.parts[1].report, "closed").status, CheckStatus::Fail);
    // The overlap test needs closed parts: skipped, naming the part.
    const Check& c = check(r.assembly, "parts_overlap");
    EXPECT_EQ(c.status, CheckStatus::Skipped);
    EXPECT_NE(c.note.find("marks"), std::string::npos) << c.note;
}

TEST(PartsVerify, TheFirstPartMustBeOnePiece) {
    std::vector<MeshPart> parts = touchingParts();
    parts[0].mesh = test::append(parts[0].mesh, test::cube(1, {30, 0, 0}));
    const PartsVerifyReport r = verifyParts(parts, nullptr, quiet());
    EXPECT_FALSE(r.passed());
    EXPECT_EQ(check(r.parts[0].report, "single_piece").status, CheckStatus::Fail);
}

}  // namespace
}  // namespace tsf
