// Default raster placement (one pillar per value when it fits) and map
// projection of lon/lat points.
#include <gtest/gtest.h>

#include <cmath>

#include "gen/util/error.h"
#include "gen/readers/point_projection.h"
#include "gen/field/resample.h"

namespace tsf {
namespace {

Raster grid(int cols, int rows) {
    Raster r;
    r.cols = cols;
    r.rows = rows;
    r.source = "grid";
    for (int k = 0; k < cols * rows; ++k) r.values.push_back(double(k));
    return r;
}

TEST(PlaceRaster, SmallGridIsOnePillarPerValue) {
    for (int n : {1, 4, 16, 40}) {
        const Raster r = grid(n, n);
        const HexField f = placeRaster(r, {});
        EXPECT_TRUE(f.one_to_one) << n;
        EXPECT_EQ(f.grid.cols, n);
        EXPECT_EQ(f.grid.rows, n);
        EXPECT_EQ(f.values, r.values);  // every value as read, none averaged or repeated
        EXPECT_NE(f.how.find("one pillar per value"), std::string::npos);
    }
}

TEST(PlaceRaster, LargeGridIsResampledToTactileCellsAndSaysWhy) {
    const Raster r = grid(300, 200);
    const HexField f = placeRaster(r, {});
    EXPECT_FALSE(f.one_to_one);
    EXPECT_LT(f.grid.cols, 300);
    // The default box (150 x 150 mm) at >= 3 mm cells.
    const double pitch = std::min(150.0 / gridWidth(f.grid, 1.0), 150.0 / gridDepth(f.grid, 1.0, 1.0));
    EXPECT_GE(pitch, kMinTactileCellMm);
    EXPECT_NE(f.how.find("resampled because"), std::string::npos);
}

TEST(PlaceRaster, GivenCellKeepsOneToOneAndBinsAlwaysResample) {
    RasterPlacement pl;
    pl.pitch_mm = 1.0;
    EXPECT_TRUE(placeRaster(grid(300, 200), pl).one_to_one);
    RasterPlacement bins;
    bins.hex_cols = 3;
    const HexField f = placeRaster(grid(4, 4), bins);
    EXPECT_FALSE(f.one_to_one);
    EXPECT_EQ(f.grid.cols, 3);
}

PointTable lonLat() {
    PointTable p;
    p.x = {0.0, 10.0, 20.0};
    p.y = {40.0, 50.0, 60.0};
    p.x_name = "lon";
    p.y_name = "lat";
    p.source = "points";
    return p;
}

// (The equal-area default goes through PROJ in the GDAL module: tested
// end to end in tests/gen/cli/equal_area_cli_test.cpp.)
TEST(Projection, EquirectProjectsAboutTheMeanLatitudeAndStatesItsDistortion) {
    PointTable p = lonLat();
    EXPECT_TRUE(looksLikeLonLat(p));
    const std::string how = projectPoints(p, {Projection::Equirect, ""});
    EXPECT_NE(how.find("equirectangular"), std::string::npos);
    // cos(40) / cos(60) - 1 = 53.2 % on a sphere (the WGS84 ellipsoid's own
    // area moves it by under 1 %): the spread of map area per ground area.
    const size_t at = how.find("area distortion at most ");
    ASSERT_NE(at, std::string::npos) << how;
    const double pct = std::stod(how.substr(at + 24));
    EXPECT_NEAR(pct, 100 * (std::cos(40 * M_PI / 180) / std::cos(60 * M_PI / 180) - 1), 1.0) << how;
    const double k = std::cos(50.0 * M_PI / 180.0);
    EXPECT_NEAR(p.x[1], 10.0 * k, 1e-12);
    EXPECT_EQ(p.y[1], 50.0);
}

TEST(Projection, OtherColumnsAreLeftAloneUnlessAsked) {
    PointTable p = lonLat();
    p.x_name = "x";
    p.y_name = "y";
    EXPECT_EQ(projectPoints(p, {Projection::Auto, ""}), "");
    EXPECT_EQ(p.x[1], 10.0);
    EXPECT_NE(projectPoints(p, {Projection::Equirect, ""}), "");
    PointTable q = lonLat();
    EXPECT_EQ(projectPoints(q, {Projection::None, ""}), "");
    PointTable far = lonLat();
    far.y[0] = 95;  // not a latitude
    EXPECT_FALSE(looksLikeLonLat(far));
    EXPECT_THROW(projectPoints(far, {Projection::Equirect, ""}), InputError);
    EXPECT_EQ(parseProjection("EPSG:3035").kind, Projection::Definition);
    EXPECT_EQ(parseProjection("equal-area").kind, Projection::EqualArea);
    EXPECT_THROW(parseProjection(""), InputError);
}

}  // namespace
}  // namespace tsf
