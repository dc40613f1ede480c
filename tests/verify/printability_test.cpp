// Printability warnings measured on boxes whose thicknesses are known.
#include <cmath>

#include <gtest/gtest.h>

#include "tests/verify/verify_test_support.h"
#include "verify/printability.h"
#include "verify/column_grid.h"

namespace tsf {
namespace {

PrintabilityResult run(const Mesh& m, PrintabilityOptions o = {}, bool closed = true) {
    const ColumnGrid caster(m);
    return checkPrintability(m, closed, caster, o);
}

const Check& findCheck(const PrintabilityResult& r, const std::string& id) {
    for (const Check& c : r.checks)
        if (c.id == id) return c;
    ADD_FAILURE() << "no check " << id;
    return r.checks.front();
}

TEST(Printability, ThinWallIsWarnedWithItsThickness) {
    const PrintabilityResult r = run(vtest::box({0, 0, 0}, {0.25, 10, 5}));
    EXPECT_DOUBLE_EQ(r.figures.min_wall_mm, 0.25);
    const Check& c = findCheck(r, "wall_thickness");
    EXPECT_EQ(c.status, CheckStatus::Warn);
    EXPECT_EQ(c.count, 2);  // the two large faces, one region each
    EXPECT_DOUBLE_EQ(c.worst.at(0).amount, 0.25);
    EXPECT_DOUBLE_EQ(r.figures.min_slab_mm, 5.0);
    EXPECT_EQ(findCheck(r, "base_thickness").status, CheckStatus::Pass);
}

TEST(Printability, NarrowGapBetweenTwoBlocksIsWarned) {
    const Mesh m = vtest::append(vtest::box({0, 0, 0}, {5, 5, 5}), vtest::box({5.3, 0, 0}, {10, 5, 5}));
    const PrintabilityResult r = run(m);
    EXPECT_NEAR(r.figures.min_gap_mm, 0.3, 1e-12);
    const Check& c = findCheck(r, "gap_width");
    EXPECT_EQ(c.status, CheckStatus::Warn);
    EXPECT_EQ(c.count, 2);  // each facing wall sees the other
    EXPECT_NEAR(c.worst.at(0).at_mm.x, 5.15, 0.16);
}

// Five slabs under the nozzle and one over it, far apart, not in order of
// width (binary fractions at whole millimetres: each slab's two faces
// measure it exactly alike): the count is every wall face under the limit,
// the offenders the thinnest few in order (a slab's two faces, a tie, by
// triangle index), the figure the thinnest of all.
TEST(Printability, OffendersAreTheThinnestInOrderAndTheCountIsEveryOne) {
    const double widths[] = {0.375, 0.3125, 0.5, 0.25, 0.28125, 0.125};
    Mesh m;
    for (int i = 0; i < 6; ++i) m = vtest::append(std::move(m), vtest::box({16.0 * i, 0, 0}, {16.0 * i + widths[i], 10, 5}));
    PrintabilityOptions o;
    o.max_offenders = 3;
    const PrintabilityResult r = run(m, o);
    const Check& c = findCheck(r, "wall_thickness");
    EXPECT_EQ(c.count, 10);  // two faces each of the five slabs under 0.4 mm
    ASSERT_EQ(c.worst.size(), 3u);
    EXPECT_EQ(c.worst[0].amount, 0.125);
    EXPECT_EQ(c.worst[1].amount, 0.125);
    EXPECT_EQ(c.worst[2].amount, 0.25);
    // The 0.1 mm slab's two faces, the lower triangle index first.
    auto triangleOf = [](const Offender& off) {
        const size_t at = off.detail.find("(triangle ");
        return at == std::string::npos ? -1L : std::stol(off.detail.substr(at + 10));
    };
    EXPECT_LT(triangleOf(c.worst[0]), triangleOf(c.worst[1])) << c.worst[0].detail << " / " << c.worst[1].detail;
    EXPECT_NEAR(c.worst[0].at_mm.x, 80.0625, 0.07);
    EXPECT_NEAR(c.worst[1].at_mm.x, 80.0625, 0.07);
    EXPECT_NEAR(c.worst[2].at_mm.x, 48.125, 0.13);
    EXPECT_EQ(r.figures.min_wall_mm, 0.125);
    EXPECT_EQ(c.note, "thinnest 0.125 mm over 24 samples; limit 0.400 mm");  // four walls a slab
}

/// A 10 mm deep block whose top falls from z = 6 at x = 0 (the rim) at
/// `slope_deg` toward +x, `length` long: under the rim the material is a
/// wedge, layer / tan(slope) wide one layer down.
Mesh wedge(double slope_deg, double length) {
    Mesh m = vtest::box({0, 0, 0}, {length, 10, 6});
    const double low = 6 - length * std::tan(slope_deg * M_PI / 180);
    m.positions[5].z = m.positions[6].z = low;
    return m;
}

// The wedge under a tilted top's rim is measured a layer below the rim (its
// last layer is that layer's rounding): at 20 degrees it is 0.55 mm wide
// there and passes; at 40 degrees 0.24 mm and is warned with that width.
TEST(Printability, AWedgeUnderARimIsMeasuredALayerDown) {
    PrintabilityOptions o;
    o.layer_mm = 0.2;
    EXPECT_EQ(findCheck(run(wedge(20, 10), o), "wall_thickness").status, CheckStatus::Pass);
    const PrintabilityResult r = run(wedge(40, 5), o);
    const Check& steep = findCheck(r, "wall_thickness");
    EXPECT_EQ(steep.status, CheckStatus::Warn);
    EXPECT_NEAR(steep.worst.at(0).amount, 0.2 / std::tan(40 * M_PI / 180), 0.002);  // to the probes, 1 um beside the wall
    // A thin slab is thin all the way: still found, at its full thinness.
    const PrintabilityResult slab = run(vtest::box({0, 0, 0}, {0.25, 10, 0.5}), o);
    ASSERT_FALSE(findCheck(slab, "wall_thickness").worst.empty());
    EXPECT_DOUBLE_EQ(findCheck(slab, "wall_thickness").worst.at(0).amount, 0.25);
}

// A wall shorter than a layer is one layer's step, not a wall a printer
// draws: a 0.15 mm thin plate 0.1 mm tall is not measured at 0.2 mm layers.
TEST(Printability, AWallShorterThanALayerIsNotMeasured) {
    PrintabilityOptions o;
    o.layer_mm = 0.2;
    const PrintabilityResult r = run(vtest::box({0, 0, 0}, {0.15, 10, 0.1}), o);
    EXPECT_EQ(findCheck(r, "wall_thickness").status, CheckStatus::Pass);
    o.layer_mm = 0.05;
    EXPECT_EQ(findCheck(run(vtest::box({0, 0, 0}, {0.15, 10, 0.1}), o), "wall_thickness").status, CheckStatus::Warn);
}

TEST(Printability, ThinBaseIsWarnedAgainstTwoLayers) {
    PrintabilityOptions o;
    o.layer_mm = 0.2;
    const PrintabilityResult r = run(vtest::box({0, 0, 0}, {20, 20, 0.3}), o);
    EXPECT_DOUBLE_EQ(r.figures.min_slab_mm, 0.3);
    EXPECT_EQ(findCheck(r, "base_thickness").status, CheckStatus::Warn);
    o.layer_mm = 0.15;
    EXPECT_EQ(findCheck(run(vtest::box({0, 0, 0}, {20, 20, 0.3}), o), "base_thickness").status, CheckStatus::Pass);
}

TEST(Printability, StrictTurnsWarningsIntoFailures) {
    PrintabilityOptions o;
    o.fail_on_warnings = true;
    EXPECT_EQ(findCheck(run(vtest::box({0, 0, 0}, {0.25, 10, 5}), o), "wall_thickness").status, CheckStatus::Fail);
}

TEST(Printability, BedFitAsIsTurnedOrNot) {
    const Mesh m = vtest::box({0, 0, 0}, {230, 200, 10});
    PrintabilityOptions o;
    EXPECT_EQ(findCheck(run(m, o), "fits_bed").status, CheckStatus::Skipped);
    o.bed_mm = Vec3{250, 210, 200};
    PrintabilityResult r = run(m, o);
    EXPECT_EQ(findCheck(r, "fits_bed").status, CheckStatus::Pass);
    EXPECT_TRUE(r.figures.fits_bed);
    o.bed_mm = Vec3{210, 240, 200};
    r = run(m, o);
    EXPECT_EQ(findCheck(r, "fits_bed").status, CheckStatus::Pass);
    EXPECT_TRUE(r.figures.fits_bed_rotated);
    o.bed_mm = Vec3{220, 220, 250};
    r = run(m, o);
    EXPECT_EQ(findCheck(r, "fits_bed").status, CheckStatus::Warn);
    o.bed_mm = Vec3{250, 250, 5};
    EXPECT_EQ(findCheck(run(m, o), "fits_bed").status, CheckStatus::Warn);  // too tall
}

// Material is looked for ten nozzle widths into the solid when no face
// slopes; walls all wider than that are measured to their far side, so the
// thinnest wall is still a figure, not "none".
TEST(Printability, WallsWiderThanTheSearchAreMeasuredToTheirFarSide) {
    // 6 mm thick, 20 mm long: no face slopes, 4 mm of search.
    const PrintabilityResult r = run(vtest::box({0, 0, 0}, {6, 20, 5}));
    EXPECT_DOUBLE_EQ(r.figures.min_wall_mm, 6.0);
    EXPECT_EQ(findCheck(r, "wall_thickness").status, CheckStatus::Pass);
    // Two boxes side by side: a 1 mm wall found within the search, a 6 mm
    // one beyond it; the thinnest is 1 mm and both walls are sampled.
    const Mesh two = test::append(vtest::box({0, 0, 0}, {1, 20, 5}), vtest::box({3, 0, 0}, {9, 20, 5}));
    const PrintabilityResult r2 = run(two);
    EXPECT_DOUBLE_EQ(r2.figures.min_wall_mm, 1.0);
    EXPECT_NE(findCheck(r2, "wall_thickness").note.find("over 8 samples"), std::string::npos)
        << findCheck(r2, "wall_thickness").note;
}

TEST(Printability, TsfModelHasPitchWideWallsAndGaps) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    PrintabilityOptions o;
    o.nozzle_mm = 0.6;  // gaps are looked for up to 10 nozzle widths: 6 mm > the 5 mm pitch
    const PrintabilityResult r = run(m.mesh, o);
    // A ray across one hexagon, flat to flat, is one pitch long.
    EXPECT_NEAR(r.figures.min_wall_mm, m.scene.pitch_mm, 1e-3);
    EXPECT_NEAR(r.figures.min_gap_mm, m.scene.pitch_mm, 1e-3);
    // The thinnest vertical slab is the base under the lowest kept cell.
    int64_t lowest = m.scene.top[0];
    for (int64_t t : m.scene.top) lowest = std::min(lowest, t);
    EXPECT_NEAR(r.figures.min_slab_mm, m.scene.zMm(lowest), 1e-9);
    for (const Check& c : r.checks) EXPECT_NE(c.status, CheckStatus::Warn) << c.id;
}

TEST(Printability, OpenMeshSkipsTheRayChecks) {
    Mesh m = vtest::box({0, 0, 0}, {0.25, 10, 5});
    m.triangles.pop_back();
    const PrintabilityResult r = run(m, {}, /*closed=*/false);
    EXPECT_EQ(findCheck(r, "wall_thickness").status, CheckStatus::Skipped);
    EXPECT_TRUE(std::isnan(r.figures.min_wall_mm));
}

}  // namespace
}  // namespace tsf
