// Every default model can be oriented by touch: the notch and the handedness
// triangle are found from the written STL alone, by rasterising its top near
// the model's south-west corner (nothing is taken from the Scene or the
// report): a V at least 6 mm deep along the corner's diagonal, and a raised
// right triangle with legs of at least 12.7 x 7.62 mm, right angle
// south-west, the longer leg east. Dense rasters (one pillar per value and
// resampled), the bundled examples, sparse points, a constant field, a field
// with pits at its west edge, tilted and concave models.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "gen/mesh_io/mesh_reader.h"
#include "tests/support/files.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

constexpr double kSampleMm = 0.1;

// The top surface (largest z of any upward triangle) over a window of the
// xy plane, NaN where nothing is; from below: the underside (smallest z of
// any downward triangle), stored negated, so what stands out is larger.
struct TopRaster {
    double x0 = 0, y0 = 0;
    int cols = 0, rows = 0;
    std::vector<double> z;
    double at(int c, int r) const { return z[size_t(r) * size_t(cols) + size_t(c)]; }
    double atMm(double x, double y) const {
        const int c = int(std::lround((x - x0) / kSampleMm)), r = int(std::lround((y - y0) / kSampleMm));
        return c < 0 || r < 0 || c >= cols || r >= rows ? std::nan("") : at(c, r);
    }
};

TopRaster rasteriseTop(const Mesh& m, double x0, double y0, double w, double d, bool from_below) {
    TopRaster t;
    t.x0 = x0;
    t.y0 = y0;
    t.cols = int(w / kSampleMm) + 1;
    t.rows = int(d / kSampleMm) + 1;
    t.z.assign(size_t(t.cols) * size_t(t.rows), std::nan(""));
    for (const auto& tri : m.triangles) {
        const Vec3 &a = m.positions[tri[0]], &b = m.positions[tri[1]], &c = m.positions[tri[2]];
        const double signed2 = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
        const double area2 = from_below ? -signed2 : signed2;
        if (area2 <= 1e-12) continue;  // facing the other way, or vertical
        const int c0 = std::max(0, int(std::ceil((std::min({a.x, b.x, c.x}) - x0) / kSampleMm)));
        const int c1 = std::min(t.cols - 1, int(std::floor((std::max({a.x, b.x, c.x}) - x0) / kSampleMm)));
        const int r0 = std::max(0, int(std::ceil((std::min({a.y, b.y, c.y}) - y0) / kSampleMm)));
        const int r1 = std::min(t.rows - 1, int(std::floor((std::max({a.y, b.y, c.y}) - y0) / kSampleMm)));
        for (int r = r0; r <= r1; ++r)
            for (int col = c0; col <= c1; ++col) {
                const double x = x0 + col * kSampleMm, y = y0 + r * kSampleMm;
                const double sign = from_below ? -1.0 : 1.0;
                const double wa = sign * ((b.x - x) * (c.y - y) - (c.x - x) * (b.y - y));
                const double wb = sign * ((c.x - x) * (a.y - y) - (a.x - x) * (c.y - y));
                const double wc = area2 - wa - wb;
                if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
                const double z = sign * (wa * a.z + wb * b.z + wc * c.z) / area2;
                double& cell = t.z[size_t(r) * size_t(t.cols) + size_t(col)];
                if (std::isnan(cell) || z > cell) cell = z;
            }
    }
    return t;
}

struct Found {
    double notch_depth_mm = 0;
    double leg_x_mm = 0, leg_y_mm = 0;
    double fill = 0;  // the raised region's area / (leg_x * leg_y): 0.5 for a right triangle
    bool right_angle_south_west = false;
};

// Finds the marks near the south-west corner of the model's bounding box,
// on its top or (from_below) its underside.
Found findMarks(const Mesh& m, bool from_below = false) {
    double xmin = std::numeric_limits<double>::max(), ymin = xmin;
    for (const Vec3& p : m.positions) {
        xmin = std::min(xmin, p.x);
        ymin = std::min(ymin, p.y);
    }
    const TopRaster top = rasteriseTop(m, xmin, ymin, 40, 40, from_below);
    Found f;
    // The notch: along the diagonal from the corner, how far until material.
    for (double t = 0; t < 20; t += kSampleMm / 2) {
        const double z = top.atMm(xmin + t / std::sqrt(2.0), ymin + t / std::sqrt(2.0));
        if (!std::isnan(z)) break;
        f.notch_depth_mm = t;
    }
    // The triangle: the samples standing 0.8 mm or more above the most common
    // top height of the window's south-west quarter (the plate it stands on),
    // in the component nearest the corner.
    std::vector<double> zs;
    for (int r = 0; r < top.rows / 2; ++r)
        for (int c = 0; c < top.cols / 2; ++c)
            if (!std::isnan(top.at(c, r))) zs.push_back(std::round(top.at(c, r) * 100) / 100);
    if (zs.empty()) return f;
    std::sort(zs.begin(), zs.end());
    double plate = zs[0];
    size_t best = 0;
    for (size_t a = 0; a < zs.size();) {
        size_t b = a;
        while (b < zs.size() && zs[b] == zs[a]) ++b;
        if (b - a > best) best = b - a, plate = zs[a];
        a = b;
    }
    std::vector<uint8_t> raised(top.z.size(), 0);
    for (size_t n = 0; n < top.z.size(); ++n) raised[n] = !std::isnan(top.z[n]) && top.z[n] >= plate + 0.8 && top.z[n] <= plate + 1.5;
    // Flood from the raised sample nearest the corner.
    int seed = -1;
    double seed_d = 1e9;
    for (int r = 0; r < top.rows; ++r)
        for (int c = 0; c < top.cols; ++c)
            if (raised[size_t(r) * size_t(top.cols) + size_t(c)] && std::hypot(c, r) < seed_d) seed_d = std::hypot(c, r), seed = r * top.cols + c;
    if (seed < 0) return f;
    std::vector<int> stack{seed}, region;
    raised[size_t(seed)] = 2;
    while (!stack.empty()) {
        const int n = stack.back();
        stack.pop_back();
        region.push_back(n);
        const int r = n / top.cols, c = n % top.cols;
        for (const auto& [dc, dr] : {std::pair{1, 0}, {-1, 0}, {0, 1}, {0, -1}}) {
            const int cc = c + dc, rr = r + dr;
            if (cc < 0 || rr < 0 || cc >= top.cols || rr >= top.rows) continue;
            const int q = rr * top.cols + cc;
            if (raised[size_t(q)] == 1) raised[size_t(q)] = 2, stack.push_back(q);
        }
    }
    int c_lo = top.cols, c_hi = -1, r_lo = top.rows, r_hi = -1;
    for (const int n : region) {
        c_lo = std::min(c_lo, n % top.cols), c_hi = std::max(c_hi, n % top.cols);
        r_lo = std::min(r_lo, n / top.cols), r_hi = std::max(r_hi, n / top.cols);
    }
    f.leg_x_mm = (c_hi - c_lo) * kSampleMm;
    f.leg_y_mm = (r_hi - r_lo) * kSampleMm;
    f.fill = double(region.size()) / double((c_hi - c_lo + 1) * (r_hi - r_lo + 1));
    // Right angle south-west: the south row spans the whole width and the
    // west column the whole depth (the region's row widths shrink northwards).
    auto raisedAt = [&](int c, int r) { return raised[size_t(r) * size_t(top.cols) + size_t(c)] == 2; };
    const int south = r_lo + 2, west = c_lo + 2;
    f.right_angle_south_west = raisedAt(c_hi - 3, south) && raisedAt(west, r_hi - 3) && !raisedAt(c_hi - 3, r_hi - 3);
    return f;
}

void expectMarks(const std::string& name, const Found& f) {
    EXPECT_GE(f.notch_depth_mm, 6.0 - 2 * kSampleMm) << name;
    EXPECT_LE(f.notch_depth_mm, 6.0 + 3 * kSampleMm) << name;  // a V, not the whole corner gone
    EXPECT_GE(f.leg_x_mm, 12.7) << name;
    EXPECT_GE(f.leg_y_mm, 7.62) << name;
    EXPECT_GT(f.leg_x_mm, 1.4 * f.leg_y_mm) << name << ": the east leg is the longer";
    EXPECT_NEAR(f.fill, 0.5, 0.06) << name << ": a triangle";
    EXPECT_TRUE(f.right_angle_south_west) << name;
}

void expectOrientable(const std::string& name, const std::string& args) {
    const auto dir = test::scratchDir("tab_" + name);
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + args + " -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << name << "\n" << r.out << r.err;
    const Mesh m = readMesh(model);
    expectMarks(name, findMarks(m));
    // A mirrored model shows them on its underside too, at the same place:
    // turned over, the long leg runs the other way, as the data does.
    if (args.find("--mirror") != std::string::npos) expectMarks(name + " (underside)", findMarks(m, /*from_below=*/true));
    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json", dir);
    EXPECT_EQ(v.exit_code, test::kExitOk) << name << "\n" << v.out << v.err;
}

std::string denseGrid(const std::string& name, int cols, int rows, bool pits) {
    std::string text;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            if (c) text += ",";
            if (pits && c < 2 && r % 5 == 0) continue;  // no data at the west edge
            text += std::to_string(50 + 40 * std::sin(r / 7.0) * std::cos(c / 5.0));
        }
        text += "\n";
    }
    return test::writeScratch(name, text);
}

TEST(OrientationTab, BundledExamplesCarryFullMarks) {
    expectOrientable("volcano", test::sourcePath("examples/volcano.csv"));
    expectOrientable("three_bumps", test::sourcePath("examples/three-bumps.pgm"));
    expectOrientable("airports", test::sourcePath("examples/airports-europe.csv") + " --points x=lon,y=lat");
}

// On an irregular west side the tab follows the outline, so it stands
// against many walls and holds a hand's push at its far corner (on the
// westernmost line alone it touched one pillar: 448 MPa on three-bumps, 37
// MPa on a 10 by 10 grid of 15 mm cells); a mirrored model's tab, on one
// pillar, is made thicker until it holds (254 MPa at 2 mm on the airports).
// The notch stays the model's south-west corner and the model verifies,
// tactile checks included.
TEST(OrientationTab, OnAnIrregularOutlineTheTabFollowsItAndHolds) {
    std::string big;
    for (int r = 0; r < 10; ++r)
        for (int c = 0; c < 10; ++c) big += std::to_string(250 + r + c) + (c == 9 ? "\n" : ",");
    const std::string grid = test::writeScratch("big_cells.csv", big);
    for (const auto& [name, args] : {std::pair<std::string, std::string>{"three_bumps", test::sourcePath("examples/three-bumps.pgm")},
                                     {"big_cells", grid},
                                     {"airports", test::sourcePath("examples/airports-europe.csv") + " --points x=lon,y=lat"},
                                     {"airports_mirrored", test::sourcePath("examples/airports-europe.csv") +
                                                               " --points x=lon,y=lat --bins 40 --mirror"}}) {
        const auto dir = test::scratchDir("outline_tab_" + name);
        const std::string model = (dir / "m.stl").string();
        const auto r = test::runTsf("gen " + args + " -o " + model, dir);
        ASSERT_EQ(r.exit_code, test::kExitOk) << name << "\n" << r.out << r.err;
        EXPECT_EQ(r.out.find("warn      every attachment holds"), std::string::npos) << name << "\n" << r.out;
        expectMarks(name, findMarks(readMesh(model)));
        const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile", dir);
        // The mirrored airports at --bins 40 keep narrow lows a fingertip
        // does not reach (--bins given is kept: LegibleDefaults tests).
        if (name != "airports_mirrored") EXPECT_EQ(v.exit_code, test::kExitOk) << name << "\n" << v.out;
        EXPECT_NE(v.out.find("PASS  every attachment holds a hand's push"), std::string::npos) << name << "\n" << v.out;
    }
}

TEST(OrientationTab, DenseRastersCarryFullMarks) {
    const std::string grid = denseGrid("dense.csv", 120, 120, false);
    expectOrientable("dense_resampled", grid);
    expectOrientable("dense_one_per_value", grid + " --cell 1.5");
    expectOrientable("dense_pits", denseGrid("pits.csv", 60, 60, true) + " --cell 3");
}

TEST(OrientationTab, ConstantTiltedAndConcaveModelsCarryFullMarks) {
    std::string flat;
    for (int r = 0; r < 8; ++r) flat += "5,5,5,5,5,5,5,5\n";
    expectOrientable("constant", test::writeScratch("constant.csv", flat));
    expectOrientable("tilted", test::sourcePath("examples/volcano.csv") + " --tilt gradient");
    expectOrientable("concave", test::sourcePath("examples/airports-europe.csv") + " --points x=lon,y=lat --cull concave");
    expectOrientable("legend_scale", test::sourcePath("examples/airports-europe.csv") +
                                         " --points x=lon,y=lat --bins 40 --title Airports --units airports --scale");
}

TEST(OrientationTab, MirroredModelsCarryThemOnBothFaces) {
    expectOrientable("mirrored_airports", test::sourcePath("examples/airports-europe.csv") + " --points x=lon,y=lat --bins 40 --mirror");
    expectOrientable("mirrored_volcano", test::sourcePath("examples/volcano.csv") + " --mirror --tilt gradient");
    expectOrientable("mirrored_dense", denseGrid("dense_m.csv", 80, 80, false) + " --mirror");
}

// Cut into halves, each half carries its side of the tab with the marks on
// its face away from the cut: the upper half as the top shows them, the
// lower half (printed turned over about the x axis) as the underside does,
// which is the top's layout once its y is turned back.
TEST(OrientationTab, EachHalfCarriesTheMarks) {
    const auto dir = test::scratchDir("tab_halves");
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + test::sourcePath("examples/volcano.csv") + " --mirror --halves -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    expectMarks("upper half", findMarks(readMesh((dir / "m-upper.stl").string())));
    Mesh lower = readMesh((dir / "m-lower.stl").string());
    for (Vec3& p : lower.positions) p.y = -p.y;
    for (auto& t : lower.triangles) std::swap(t[1], t[2]);  // a reflection turns the faces inside out
    expectMarks("lower half", findMarks(lower));
}

// Leaving a mark out leaves it out; --marks-on data keeps the old placement.
TEST(OrientationTab, OptionsChooseTheMarks) {
    const auto dir = test::scratchDir("tab_options");
    const std::string in = test::sourcePath("examples/volcano.csv");
    const auto no_triangle = test::runTsf("gen " + in + " --no-triangle --json -o " + (dir / "a.stl").string(), dir);
    ASSERT_EQ(no_triangle.exit_code, test::kExitOk) << no_triangle.err;
    const Found a = findMarks(readMesh((dir / "a.stl").string()));
    EXPECT_GE(a.notch_depth_mm, 5.8);
    EXPECT_EQ(a.leg_x_mm, 0.0);
    const auto data = test::runTsf("gen " + in + " --marks-on data -o " + (dir / "b.stl").string(), dir);
    ASSERT_EQ(data.exit_code, test::kExitOk) << data.err;
    EXPECT_LT(findMarks(readMesh((dir / "b.stl").string())).notch_depth_mm, 5.0);  // 3 mm cells: a shallow V in the corner pillar
    EXPECT_NE(data.out.find("notch     V"), std::string::npos) << data.out;
    EXPECT_EQ(data.out.find("  tab "), std::string::npos) << data.out;

    // One value with a braille legend: the plate takes the west line's
    // whole height, so the tab stands against the pillar's south-west wall
    // below it, the notch at the model's south-west corner, and holds.
    test::writeText(dir / "one.csv", "5\n");
    const std::string c = (dir / "c.stl").string();
    const auto one = test::runTsf("gen " + (dir / "one.csv").string() + " --title T -o " + c, dir);
    ASSERT_EQ(one.exit_code, test::kExitOk) << one.err;
    EXPECT_NE(one.out.find("  tab "), std::string::npos) << one.out;
    EXPECT_NE(one.out.find("notch     V 6.0 mm deep"), std::string::npos) << one.out;
    EXPECT_NE(one.out.find("at the model's south-west corner"), std::string::npos) << one.out;
    const auto v = test::runTsf("verify " + c + " --scene " + c + ".scene.json --tactile", dir);
    EXPECT_EQ(v.exit_code, test::kExitOk) << v.out;
    EXPECT_NE(v.out.find("PASS  every attachment holds a hand's push"), std::string::npos) << v.out;
}

}  // namespace
}  // namespace tsf
