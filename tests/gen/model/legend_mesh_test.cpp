// The legend plate: closed, 2-manifold, outward, one piece, no
// self-intersection, and its volume the plate's plus one low-poly dome per
// dot, computed here from the dome's own shape (octagonal frusta).
#include <gtest/gtest.h>

#include <cmath>

#include "gen/model/features/legend/legend_mesh.h"
#include "tests/support/mesh_invariants.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {

// Volume (mm^3) of one dome: octagons of circumradius r_k at heights z_k
// (base r at 0, rings on the sphere, the apex a point), stacked frusta.
double domeVolume(const BrailleStandard& s) {
    const double r = s.dot_base_mm / 2, hd = s.dot_height_mm;
    const double R = (r * r + hd * hd) / (2 * hd), theta_max = std::asin(r / R);
    std::vector<double> radius{r}, z{0};
    for (int ring = 1; ring <= kDomeRings; ++ring) {
        const double theta = theta_max * (1.0 - double(ring) / (kDomeRings + 1));
        radius.push_back(R * std::sin(theta));
        z.push_back(hd - R + R * std::cos(theta));
    }
    radius.push_back(0);
    z.push_back(hd);
    const auto area = [](double rc) { return 2 * std::sqrt(2.0) * rc * rc; };  // regular octagon
    double v = 0;
    for (size_t k = 0; k + 1 < radius.size(); ++k) {
        const double a = area(radius[k]), b = area(radius[k + 1]);
        v += (z[k + 1] - z[k]) / 3 * (a + b + std::sqrt(a * b));
    }
    return v;
}

TEST(LegendMesh, PlateWithDomesIsOneClosedSolidOfTheExpectedVolume) {
    LegendParams p;
    p.lines = {"Airports of Europe", "0 to 27 airports"};
    const LegendLayout l = layoutLegend(p);
    ASSERT_GT(l.dots.size(), 30u);
    const double plate_mm = 2.0;
    const Mesh m = meshLegendPlate(l, plate_mm);

    const test::Invariants inv = test::checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    EXPECT_EQ(inv.euler, 2);
    const double expected = l.width_mm * l.depth_mm * plate_mm + double(l.dots.size()) * domeVolume(l.standard);
    EXPECT_NEAR(inv.volume, expected, 1e-3 * expected);

    // Every dot stands dot_height_mm above the plate, nothing higher.
    const Bounds b = meshBounds(m);
    EXPECT_DOUBLE_EQ(b.max.z, plate_mm + l.standard.dot_height_mm);
    EXPECT_DOUBLE_EQ(b.max.x, l.width_mm);
    EXPECT_DOUBLE_EQ(b.max.y, l.depth_mm);

    VerifyOptions vo;
    vo.name = "legend";
    vo.printability = false;  // dots are meant to be finer than pillars
    const VerifyReport r = verifyModel(m, nullptr, vo);
    EXPECT_TRUE(r.passed()) << formatReport(r);
}

TEST(LegendMesh, NoDotsNoMesh) {
    EXPECT_TRUE(meshLegendPlate(LegendLayout{}, 2.0).triangles.empty());
}

}  // namespace
}  // namespace tsf
