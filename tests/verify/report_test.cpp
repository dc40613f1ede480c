// The report as people and programs see it: text lines with statuses and
// millimetre coordinates, JSON with every figure and null for NaN.
#include <gtest/gtest.h>

#include <set>

#include "tests/verify/verify_test_support.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {

TEST(Report, FailingReportNamesCheckPlaceAndVerdict) {
    Mesh m = vtest::box({0, 0, 0}, {10, 20, 30});
    std::swap(m.triangles[7][1], m.triangles[7][2]);  // flip one triangle of the +x face
    VerifyOptions o;
    o.name = "box.stl";
    o.read_notes = {"stl-binary, 12 triangles"};
    const VerifyReport r = verifyModel(m, nullptr, o);
    ASSERT_FALSE(r.passed());
    const std::string text = formatReport(r);
    EXPECT_NE(text.find("model: box.stl"), std::string::npos) << text;
    EXPECT_NE(text.find("read: stl-binary, 12 triangles"), std::string::npos);
    EXPECT_NE(text.find("size 10.000 x 20.000 x 30.000 mm"), std::string::npos) << text;
    EXPECT_NE(text.find("FAIL  neighbouring triangles consistently oriented: 3"), std::string::npos) << text;
    // Triangle 7 is {1, 5, 6} after the flip: (10,0,0), (10,0,30), (10,20,30); centroid (10, 6.667, 20).
    EXPECT_NE(text.find("at (10.000, 6.667, 20.000) mm: triangle 7"), std::string::npos) << text;
    EXPECT_NE(text.find("volume n/a"), std::string::npos) << text;
    EXPECT_NE(text.find("result: FAIL"), std::string::npos) << text;
}

TEST(Report, JsonCarriesEveryFigure) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    VerifyOptions o;
    o.bed_mm = Vec3{220, 220, 250};
    o.reference = &m.mesh;
    o.reference_name = "itself";
    const VerifyReport r = verifyModel(m.mesh, &m.scene, o);
    const nlohmann::json j = toJson(r);
    EXPECT_EQ(j["format"], "tsf-verify-report");
    EXPECT_EQ(j["version"], 1);
    EXPECT_EQ(j["passed"], true);
    EXPECT_EQ(j["mesh"]["triangles"], m.mesh.triangleCount());
    EXPECT_EQ(j["mesh"]["components"], 1);
    EXPECT_TRUE(j["mesh"]["volume_mm3"].is_number());
    EXPECT_EQ(j["readback"]["cells_checked"], m.scene.keptCount());
    EXPECT_TRUE(j["readback"]["worst"].is_array());
    EXPECT_EQ(j["agreement"]["reference"], "itself");
    EXPECT_EQ(j["printability"]["fits_bed"], true);
    std::set<std::string> ids;
    for (const auto& c : j["checks"]) {
        ids.insert(c["id"].get<std::string>());
        EXPECT_TRUE(c["time_ms"].is_number());
        EXPECT_TRUE(c["status"] == "pass" || c["status"] == "skipped") << c.dump();
    }
    for (const char* id : {"valid_input", "closed", "manifold_edges", "manifold_vertices", "consistent_orientation",
                           "single_piece", "distinct_vertices", "degenerate_faces", "self_intersections",
                           "outward_orientation", "values_read_back", "outside_cells_empty", "reference_distance",
                           "reference_volume", "wall_thickness", "gap_width", "base_thickness", "fits_bed"})
        EXPECT_TRUE(ids.count(id)) << id;
    EXPECT_GE(j["stages"].size(), 5u);
    EXPECT_GT(j["total_ms"].get<double>(), 0.0);
}

TEST(Report, NaNBecomesNull) {
    Mesh open = vtest::box({0, 0, 0}, {1, 1, 1});
    open.triangles.pop_back();
    const nlohmann::json j = toJson(verifyModel(open, nullptr, {}));
    EXPECT_TRUE(j["mesh"]["volume_mm3"].is_null());
    EXPECT_TRUE(j["printability"]["min_wall_mm"].is_null());
    EXPECT_EQ(j["passed"], false);
    // The whole document survives a dump/parse round trip (no NaN literals).
    EXPECT_NO_THROW(nlohmann::json::parse(j.dump()));
}

}  // namespace
}  // namespace tsf
