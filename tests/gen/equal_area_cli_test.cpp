// Point densities on an equal-area map: lon/lat points projected with PROJ
// (gen/readers/point_projection.h). Points spread uniformly over the sphere
// between 30 and 70 degrees north make a flat density: the pillars of the
// model's southern and northern thirds stand alike (within 8 %), where the
// old equirectangular projection made the north about 40 % lower.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
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
    EXPECT_NE(r.out.find("projected lon/lat with PROJ onto Lambert azimuthal equal-area centred at 50.0"), std::string::npos) << r.out;
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

// Around the world: Equal Earth.
TEST(EqualAreaCli, TheWholeWorldGoesOnEqualEarth) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "world.csv", sphereBand(20000, -180, 180));
    const auto r = test::runTsf("gen " + (dir / "world.csv").string() + " --points x=lon,y=lat --bins 20 -o " +
                                    (dir / "w.stl").string(), dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    EXPECT_NE(r.out.find("onto Equal Earth"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("area distortion at most 0.0 %"), std::string::npos) << r.out;
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

}  // namespace
}  // namespace tsf
