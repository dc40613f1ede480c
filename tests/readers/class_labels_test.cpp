// Class maps as readers need them: a class ringing the border is named a
// background with its remedy, --class-names names classes from a CSV, and
// --class-groups joins codes into the classes that matter.
#include "gen/readers/class_labels.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "tests/readers/geotiff_test_writer.h"
#include "tests/support/files.h"
#include "tests/support/input_error.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

TEST(ClassLabels, NamesFromACsvWithOrWithoutAHeader) {
    const std::vector<RasterClass> a = parseClassNames("code,name\n41,Deciduous Forest\n11,Open Water\n", "n.csv");
    ASSERT_EQ(a.size(), 2u);
    EXPECT_EQ(a[0].code, 11.0);
    EXPECT_EQ(a[0].name, "Open Water");
    EXPECT_EQ(a[1].name, "Deciduous Forest");
    EXPECT_EQ(parseClassNames("21;Developed, open space\n", "n.csv")[0].name, "Developed, open space");
    EXPECT_INPUT_ERROR_AT(parseClassNames("code,name\n41,Forest\nforty,Forest\n", "n.csv"), 3, 1, "'forty' is not a class code");
    EXPECT_INPUT_ERROR_AT(parseClassNames("41,Forest\n41,Woods\n", "n.csv"), 2, 1, "class 41 is named twice");
    EXPECT_INPUT_ERROR(parseClassNames("41\n", "n.csv"), "class 41 has no name");
    EXPECT_INPUT_ERROR(parseClassNames("code,name\n", "n.csv"), "names no class");
}

TEST(ClassLabels, GroupsJoinRangesOfCodesIntoOneNamedClass) {
    const std::vector<ClassGroup> g = parseClassGroups("21-24=Developed; 41-43=Forest,11=Water");
    ASSERT_EQ(g.size(), 3u);
    EXPECT_EQ(g[0].lo, 21.0);
    EXPECT_EQ(g[0].hi, 24.0);
    EXPECT_EQ(g[2].lo, 11.0);
    EXPECT_EQ(g[2].hi, 11.0);
    EXPECT_EQ(parseClassGroups("-2--1=Ice")[0].hi, -1.0);
    std::vector<double> values = {21, 22, 24, 25, 42, NAN, 11};
    std::vector<RasterClass> classes = {{22, "Developed, low"}, {25, "Barren"}, {42, "Evergreen"}};
    EXPECT_EQ(applyClassGroups(values, classes, g), 3);
    EXPECT_EQ(values[1], 21.0);
    EXPECT_EQ(values[2], 21.0);
    EXPECT_EQ(values[3], 25.0) << "outside every group: unchanged";
    EXPECT_EQ(values[4], 41.0);
    EXPECT_TRUE(std::isnan(values[5]));
    ASSERT_EQ(classes.size(), 4u);  // 11 Water, 21 Developed, 25 Barren, 41 Forest
    EXPECT_EQ(classes[1].name, "Developed");
    EXPECT_EQ(classes[2].name, "Barren");
    EXPECT_INPUT_ERROR(parseClassGroups("21-24"), "has no '='");
    EXPECT_INPUT_ERROR(parseClassGroups("24-21=Developed"), "runs downwards");
    EXPECT_INPUT_ERROR(parseClassGroups("21-24=A;23-30=B"), "overlaps 21-24");
    EXPECT_INPUT_ERROR(parseClassGroups("x-y=A"), "is not a code");
}

// A 40 x 40 land-cover map: class 0 (outside the survey) three pixels round
// the border and in a corner block, inside it developed land (21 to 24, in
// stripes) and forest (41).
test::GeoTiffSpec surveyed() {
    test::GeoTiffSpec s;
    s.cols = s.rows = 40;
    s.epsg = 32633;
    s.pixel_w = s.pixel_h = 30;
    s.byte_band = true;
    s.classes = true;
    for (int r = 0; r < 40; ++r)
        for (int c = 0; c < 40; ++c) {
            const bool outside = r < 3 || c < 3 || r >= 37 || c >= 37 || (r < 15 && c < 15);
            s.values.push_back(float(outside ? 0 : c < 20 ? 21 + (r / 4) % 4 : 41));
        }
    return s;
}

TEST(ClassLabels, ABackgroundIsNamedAndClassesAreNamedAndGroupedFromTheCommandLine) {
    const auto dir = test::scratchDir();
    const std::string path = (dir / "cover.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, surveyed()));
    const auto run = test::runTsf("gen " + path + " --bins 20 -o " + (dir / "a.stl").string() + " --json", dir);
    ASSERT_EQ(run.exit_code, test::kExitOk) << run.out << run.err;
    const nlohmann::json j = nlohmann::json::parse(run.out.substr(run.out.find('{')));
    int backgrounds = 0;
    for (const auto& c : j["classes"])
        if (c["background"].get<bool>()) {
            ++backgrounds;
            EXPECT_EQ(c["code"].get<double>(), 0.0) << c.dump();
        }
    EXPECT_EQ(backgrounds, 1) << j["classes"].dump();
    const std::string key = test::readText(dir / "a.key.txt");
    EXPECT_NE(key.find("Class 0 rings the edge of the map"), std::string::npos) << key;
    const auto text = test::runTsf("gen " + path + " --bins 20 -o " + (dir / "b.stl").string(), dir);
    EXPECT_NE(text.out.find("--nodata 0 leaves it out"), std::string::npos) << text.out;

    // The remedy: no background left, and developed land one named class.
    test::writeText(dir / "names.csv", "code,name\n41,Forest\n");
    const auto named = test::runTsf("gen " + path + " --bins 20 --nodata 0 --class-names " + (dir / "names.csv").string() +
                                        " --class-groups 21-24=Developed -o " + (dir / "c.stl").string() + " --json", dir);
    ASSERT_EQ(named.exit_code, test::kExitOk) << named.out << named.err;
    const nlohmann::json nj = nlohmann::json::parse(named.out.substr(named.out.find('{')));
    ASSERT_EQ(nj["classes"].size(), 2u) << nj["classes"].dump();
    std::set<std::string> names;
    for (const auto& c : nj["classes"]) {
        names.insert(c["name"].get<std::string>());
        EXPECT_FALSE(c["background"].get<bool>()) << c.dump();
    }
    EXPECT_EQ(names, (std::set<std::string>{"Developed", "Forest"}));
    const std::string nkey = test::readText(dir / "c.key.txt");
    EXPECT_NE(nkey.find("class 21 Developed"), std::string::npos) << nkey;

    const auto bad = test::runTsf("gen " + path + " --class-groups 21-24 -o " + (dir / "d.stl").string(), dir);
    EXPECT_EQ(bad.exit_code, test::kExitBadInput) << bad.out << bad.err;
    EXPECT_NE(bad.err.find("--class-groups: '21-24' has no '='"), std::string::npos) << bad.err;
}

}  // namespace
}  // namespace tsf
