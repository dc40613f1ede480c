// Point densities on an equal-area map: lon/lat points projected with PROJ
// (gen/readers/point_projection.h). Points spread uniformly over the sphere
// between 30 and 70 degrees north make a flat density: the pillars of the
// model's southern and northern thirds stand alike (within 8 %), where the
// old equirectangular projection made the north about 40 % lower.
#include <gtest/gtest.h>


#include <algorithm>
#include <cmath>
#include <random>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "tests/support/run.h"

namespace tsf {
namespace {

// Medians of the values of the kept cells with data in the model's northern
// and southern thirds of rows (from the scene sidecar).
std::pair<double, double> northSouthMedians(const std::string& sidecar) {
    const nlohmann::json j = nlohmann::json::parse(test::readText(sidecar));
    std::vector<std::pair<int, double>> cells;
    for (const auto& c : j["cells"])
        if (!c["value"].is_null() && c["value"].get<double>() > 0) cells.push_back({c["row"].get<int>(), c["value"].get<double>()});
    int lo = 1 << 30, hi = -1;
    for (const auto& [r, v] : cells) lo = std::min(lo, r), hi = std::max(hi, r);
    const double span = hi - lo + 1;
    std::vector<double> north, south;
    for (const auto& [r, v] : cells) {
        if (r < lo + span / 3) north.push_back(v);
        if (r >= lo + 2 * span / 3) south.push_back(v);
    }
    auto median = [](std::vector<double> v) {
        std::sort(v.begin(), v.end());
        return v.empty() ? 0.0 : v[v.size() / 2];
    };
    return {median(north), median(south)};
}

std::string sphereBand(int n, double lon_lo, double lon_hi) {
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> lon(lon_lo, lon_hi), z(std::sin(30 * M_PI / 180), std::sin(70 * M_PI / 180));
    std::ostringstream csv;
    csv.precision(8);
    csv << "lon,lat\n";
    for (int k = 0; k < n; ++k) csv << lon(rng) << "," << std::asin(z(rng)) * 180 / M_PI << "\n";
    return csv.str();
}

TEST(EqualAreaCli, UniformPointsOnTheSphereMakeAFlatDensity) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "band.csv", sphereBand(60000, -20, 40));
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + (dir / "band.csv").string() + " --points x=lon,y=lat --bins 20 -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    EXPECT_NE(r.out.find("projected lon/lat with PROJ onto Lambert azimuthal equal-area centred at 48."), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("area distortion at most 0.0 %"), std::string::npos) << r.out;
    const auto [north, south] = northSouthMedians(model + ".scene.json");
    EXPECT_LT(std::fabs(north - south) / std::max(north, south), 0.08) << "north " << north << ", south " << south;

    // The old projection, asked for: the north far lower, and the summary says it is no density.
    const auto e = test::runTsf("gen " + (dir / "band.csv").string() + " --points x=lon,y=lat --bins 20 --project equirect -o " + model, dir);
    ASSERT_EQ(e.exit_code, test::kExitOk) << e.out << e.err;
    EXPECT_NE(e.out.find("not a density"), std::string::npos) << e.out;
    const auto [en, es] = northSouthMedians(model + ".scene.json");
    EXPECT_GT((es - en) / es, 0.25) << "north " << en << ", south " << es;
}

// Around the world: Equal Earth. A ring round the north (30 to 70 N at every
// longitude) is no world: its spherical mean is the pole, no point is more
// than 60 degrees from it (the mean of 20 000 random points: within a
// quarter of a degree of the pole), and a polar equal-area map keeps it whole.
TEST(EqualAreaCli, TheWholeWorldGoesOnEqualEarth) {
    const auto dir = test::scratchDir();
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> lon(-180, 180), z(-0.9, 0.9);
    std::ostringstream world;
    world << "lon,lat\n";
    for (int k = 0; k < 20000; ++k) world << lon(rng) << "," << std::asin(z(rng)) * 180 / M_PI << "\n";
    test::writeText(dir / "world.csv", world.str());
    const auto r = test::runTsf("gen " + (dir / "world.csv").string() + " --points x=lon,y=lat --bins 20 -o " +
                                    (dir / "w.stl").string(), dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    EXPECT_NE(r.out.find("onto Equal Earth"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("area distortion at most 0.0 %"), std::string::npos) << r.out;

    test::writeText(dir / "ring.csv", sphereBand(20000, -180, 180));
    const auto ring = test::runTsf("gen " + (dir / "ring.csv").string() + " --points x=lon,y=lat --bins 20 -o " +
                                       (dir / "r.stl").string(), dir);
    ASSERT_EQ(ring.exit_code, test::kExitOk) << ring.out << ring.err;
    EXPECT_NE(ring.out.find("Lambert azimuthal equal-area centred at 89.8"), std::string::npos) << ring.out;
}

// x, y columns in Web Mercator (an export): --crs brings them to lon/lat
// first, and the model is the one the lon/lat columns make.
TEST(EqualAreaCli, ProjectedColumnsAreReprojectedWithCrs) {
    const auto dir = test::scratchDir();
    std::ostringstream ll, merc;
    ll << "lon,lat\n";
    merc << "x,y\n";
    merc.precision(12);
    for (int k = 0; k < 400; ++k) {
        const double lon = -5 + (k * 37) % 300 / 10.0, lat = 40 + (k * 53) % 250 / 10.0;
        ll << lon << "," << lat << "\n";
        const double x = 6378137.0 * lon * M_PI / 180, y = 6378137.0 * std::log(std::tan(M_PI / 4 + lat * M_PI / 360));
        merc << x << "," << y << "\n";
    }
    test::writeText(dir / "ll.csv", ll.str());
    test::writeText(dir / "merc.csv", merc.str());
    const auto a = test::runTsf("gen " + (dir / "ll.csv").string() + " --points x=lon,y=lat --bins 12 --json -o " + (dir / "a.stl").string(), dir);
    const auto b = test::runTsf("gen " + (dir / "merc.csv").string() + " --points x=x,y=y --crs EPSG:3857 --bins 12 --json -o " +
                                    (dir / "b.stl").string(), dir);
    ASSERT_EQ(a.exit_code, test::kExitOk) << a.out << a.err;
    ASSERT_EQ(b.exit_code, test::kExitOk) << b.out << b.err;
    const auto ja = nlohmann::json::parse(test::readText((dir / "a.stl.scene.json").string()));
    const auto jb = nlohmann::json::parse(test::readText((dir / "b.stl.scene.json").string()));
    EXPECT_EQ(ja["cells"], jb["cells"]) << "the same points make the same model";

    // Any PROJ definition; an unknown one is bad input naming it.
    const auto d = test::runTsf("gen " + (dir / "ll.csv").string() + " --points x=lon,y=lat --project EPSG:3035 -o " +
                                    (dir / "d.stl").string(), dir);
    EXPECT_EQ(d.exit_code, test::kExitOk) << d.out << d.err;
    EXPECT_NE(d.out.find("ETRS89-extended / LAEA Europe"), std::string::npos) << d.out;
    const auto bad = test::runTsf("gen " + (dir / "ll.csv").string() + " --points x=lon,y=lat --project EPSG:99999999 -o " +
                                      (dir / "e.stl").string(), dir);
    EXPECT_EQ(bad.exit_code, test::kExitBadInput) << bad.out << bad.err;
    EXPECT_NE(bad.err.find("EPSG:99999999"), std::string::npos) << bad.err;
}

// The columns of the grid that hold a pillar above the floor (from the sidecar).
std::vector<int> occupiedColumns(const std::string& sidecar, int* cols, int* nonempty) {
    const nlohmann::json j = nlohmann::json::parse(test::readText(sidecar));
    *cols = j["grid"]["cols"].get<int>();
    std::vector<int> seen(size_t(*cols), 0);
    *nonempty = 0;
    for (const auto& c : j["cells"])
        if (!c["value"].is_null() && c["value"].get<double>() > 0) {
            seen[size_t(c["col"].get<int>())] = 1;
            ++*nonempty;
        }
    return seen;
}

// A cluster across the antimeridian (Fiji, longitudes 178 to 180 and -180 to
// -178) stays one cluster: centred on the points' spherical mean, not split
// to both ends of a 358-degree strip with every column between them empty.
TEST(EqualAreaCli, AClusterAcrossTheAntimeridianStaysOneCluster) {
    const auto dir = test::scratchDir();
    std::ostringstream csv;
    csv << "lon,lat\n";
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> d_lon(-2, 2), lat(-18, -16);
    for (int k = 0; k < 200; ++k) {
        double lon = 180 + d_lon(rng);
        if (lon > 180) lon -= 360;
        csv << lon << "," << lat(rng) << "\n";
    }
    test::writeText(dir / "fiji.csv", csv.str());
    const std::string model = (dir / "f.stl").string();
    const auto r = test::runTsf("gen " + (dir / "fiji.csv").string() + " --points x=lon,y=lat --bins 6 -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    EXPECT_NE(r.out.find("Lambert azimuthal equal-area centred at 17.0"), std::string::npos) << r.out;
    // The summary wraps long lines for a screen reader: read it as one line.
    const std::string said = std::regex_replace(r.out, std::regex(R"(\n\s+)"), " ");
    EXPECT_TRUE(said.find(", 179.9") != std::string::npos || said.find(", 180.0") != std::string::npos) << r.out;
    int cols = 0, nonempty = 0;
    const std::vector<int> seen = occupiedColumns(model + ".scene.json", &cols, &nonempty);
    EXPECT_LE(cols, 7) << "a 4 x 2 degree cluster, 6 hexagons across its longer side";
    for (int c = 0; c < cols; ++c) EXPECT_TRUE(seen[size_t(c)]) << "column " << c << " of " << cols << " is empty";
}

// Four rows that are all the North Pole, at four longitudes: one point on
// the globe, one hexagon of 4.
TEST(EqualAreaCli, PointsAtAPoleAreOnePoint) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "pole.csv", "lon,lat\n0,90\n90,90\n180,90\n-90,90\n");
    const std::string model = (dir / "p.stl").string();
    const auto r = test::runTsf("gen " + (dir / "pole.csv").string() + " --points x=lon,y=lat -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const nlohmann::json j = nlohmann::json::parse(test::readText(model + ".scene.json"));
    int pillars = 0;
    double value = 0;
    for (const auto& c : j["cells"])
        if (!c["value"].is_null() && c["value"].get<double>() > 0) ++pillars, value = c["value"].get<double>();
    EXPECT_EQ(pillars, 1) << r.out;
    EXPECT_EQ(value, 4.0);
}

// Points on two sides of the globe (more than a hemisphere from their mean)
// keep a world map, and the summary says so.
TEST(EqualAreaCli, PointsSpanningMoreThanAHemisphereKeepAWorldMapAndSaySo) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "two.csv", "lon,lat\n10,50\n12,48\n-150,-40\n-148,-42\n100,0\n");
    const auto r = test::runTsf("gen " + (dir / "two.csv").string() + " --points x=lon,y=lat --bins 10 -o " +
                                    (dir / "t.stl").string(), dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    EXPECT_NE(r.out.find("Equal Earth"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("more than a hemisphere"), std::string::npos) << r.out;
}

// A latitude off the globe is refused, naming the value and the column.
TEST(EqualAreaCli, ALatitudeOffTheGlobeIsRefusedNamingIt) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "bad.csv", "lon,lat\n10,50\n12,435\n");
    const auto r = test::runTsf("gen " + (dir / "bad.csv").string() + " --points x=lon,y=lat --project equal-area -o " +
                                    (dir / "b.stl").string(), dir);
    EXPECT_EQ(r.exit_code, test::kExitBadInput) << r.out << r.err;
    EXPECT_NE(r.err.find("point 2: lat 435 is not a latitude"), std::string::npos) << r.err;
}

// A density needs its ground: the summary and the key give the ground the
// model covers and the area of one hexagon, and the hexagons tile that
// ground (cols x rows hexagons cover about its width x depth).
TEST(EqualAreaCli, ADensityGivesItsGroundAndTheAreaOfAHexagon) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "band.csv", sphereBand(5000, -20, 40));
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + (dir / "band.csv").string() + " --points x=lon,y=lat --bins 30 --json -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const nlohmann::json j = nlohmann::json::parse(r.out.substr(r.out.find('{')));
    ASSERT_TRUE(j["ground"].is_object()) << j.dump();
    const double area = j["ground"]["hexagon_area_km2"].get<double>();
    const nlohmann::json side = nlohmann::json::parse(test::readText(model + ".scene.json"));
    const double cells = side["grid"]["cols"].get<double>() * side["grid"]["rows"].get<double>();
    const double ground_km2 = j["ground"]["width_m"].get<double>() * j["ground"]["depth_m"].get<double>() / 1e6;
    EXPECT_NEAR(cells * area / ground_km2, 1.0, 0.1) << area << " km^2 a hexagon, " << cells << " hexagons";
    // 60 degrees of longitude at 30 to 70 north (some 4500 km) across 30
    // hexagons of about 150 to 190 km: tens of thousands of square kilometres.
    EXPECT_GT(area, 15000);
    EXPECT_LT(area, 40000);
    const std::string key = test::readText(dir / "m.key.txt");
    EXPECT_NE(key.find("Each hexagon covers about"), std::string::npos) << key;
    EXPECT_NE(key.find("square kilometres"), std::string::npos) << key;
}

}  // namespace
}  // namespace tsf
