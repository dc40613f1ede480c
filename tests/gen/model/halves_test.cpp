// Support-free halves of a mirrored model (gen/model/features/halves.h, gen/mesh/halves_mesh.h):
// the pin layout is scalene and clear of the edge and the marks, the cut
// lies in a slab every pillar crosses, each half is a closed solid that
// prints without overhang, and the pieces hold the material they should.
#include <gtest/gtest.h>

#include <cmath>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/features/halves.h"
#include "gen/mesh/halves_mesh.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "tests/support/input_error.h"
#include "tests/support/mesh_invariants.h"
#include "verify/overhang.h"

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A smooth hill, 12 x 10 cells of 6 mm, with the orientation marks on (or
// off); `raster_rows`: its rows a pitch apart, as a raster's (true aspect).
Scene hillWithHalves(bool marks = true, bool raster_rows = false) {
    HexField f = test::fieldFromFunction(12, 10, [](int c, int r) {
        return 1.0 + std::sin(c * 0.5) + std::cos(r * 0.6);
    });
    f.rows_a_pitch_apart = raster_rows;
    SceneParams p = test::smallParams(Bottom::Mirrored);
    if (marks) p.marks = MarkParams{};
    p.marks.place = MarkPlace::Data;  // the pin holes keep clear of marks in the data; the tab is outside the cells
    p.pitch_mm = 6.0;
    p.halves = true;
    return buildScene(f, p);
}

TEST(PinLayout, ChiralOnlyForAScaleneTriangle) {
    EXPECT_TRUE(isChiralLayout({{0, 0}, {30, 0}, {10, 20}}, 0.4));
    EXPECT_FALSE(isChiralLayout({{0, 0}, {30, 0}, {15, 20}}, 0.4));   // isosceles: a reflection maps it
    EXPECT_FALSE(isChiralLayout({{0, 0}, {30, 0}, {15, 25.98}}, 0.4));  // equilateral: rotations map it
    EXPECT_FALSE(isChiralLayout({{0, 0}, {30, 0}, {15.3, 20}}, 0.4));   // isosceles within the pins' play
    EXPECT_FALSE(isChiralLayout({{0, 0}, {10, 0}, {25, 0.1}}, 0.4));    // on one line
    EXPECT_FALSE(isChiralLayout({{0, 0}, {30, 0}}, 0.4));               // two pins: a half turn swaps them
}

TEST(PinLayout, ScaleneClearOfTheEdgeAndTheMarks) {
    const Scene s = hillWithHalves();
    ASSERT_TRUE(s.halves);
    ASSERT_TRUE(s.marks.notch || s.marks.triangle);
    const SceneHalves& h = *s.halves;
    ASSERT_EQ(h.hole_centres.size(), size_t(kPinCount));
    const auto centres = holeCentresMm(s);
    EXPECT_TRUE(isChiralLayout(centres, kPinLayoutMinSideDifferenceMm / 2));
    // Independently of the placement: every cell that is not kept, or that a
    // mark draws, lies farther from each hole than the hole's radius plus the
    // edge margin plus its own inradius (so the disc never enters it).
    const double keep_clear = h.pins.hole_vertex_radius_mm + kHoleEdgeMarginMm + s.pitch_mm / 2;
    for (const auto& [x, y] : centres)
        for (int32_t r = -2; r < s.grid.rows + 2; ++r)
            for (int32_t c = -2; c < s.grid.cols + 2; ++c) {
                const int32_t k = s.keptAt(c, r);
                if (k >= 0 && (s.drawn_by_face.empty() || !s.drawn_by_face[size_t(k)])) continue;
                const Vec3 p = s.point(hexCentre(s.grid, c, r), 0);
                EXPECT_GT(std::hypot(p.x - x, p.y - y), keep_clear) << "cell " << c << "," << r;
            }
}

// Every pillar crosses the cut; every pillar a hole reaches into has room
// for it on both sides of the cut (the hole, its cone and a roof), checked
// from the hole's centre and the cells' own spans; and the slab grew no more
// than the full pin slab (the pins sit in material that is there anyway).
TEST(Halves, EveryPillarCrossesTheCutAndTheHolesHaveRoomWhereTheyAre) {
    const Scene s = hillWithHalves();
    const SceneHalves& h = *s.halves;
    const int64_t roof = int64_t(std::ceil(kHoleRoofMm / s.z_snap_mm));
    const auto centres = holeCentresMm(s);
    const double reaches = h.pins.hole_vertex_radius_mm + s.pitch_mm / kSqrt3;  // the disc can touch the hexagon
    size_t reached = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        EXPECT_LT(s.bottom[k], h.split_units);
        EXPECT_GT(s.top[k], h.split_units);
        const Vec3 p = s.point(hexCentre(s.grid, s.col[k], s.row[k]), 0);
        bool near = false;
        for (const auto& [x, y] : centres) near = near || std::hypot(p.x - x, p.y - y) <= reaches;
        if (!near) continue;
        ++reached;
        EXPECT_LE(s.bottom[k] + h.hole_apex_units + roof, h.split_units) << "cell " << k;
        EXPECT_GE(s.top[k] - h.hole_apex_units - roof, h.split_units) << "cell " << k;
    }
    EXPECT_GE(reached, size_t(kPinCount));
    EXPECT_LE(h.thickness_grown_units, halvesSlabUnits(s.z_snap_mm));
    EXPECT_NEAR(s.zMm(h.hole_depth_units), kHoleDepthMm, s.z_snap_mm);
    EXPECT_GE(s.zMm(h.hole_apex_units - h.hole_depth_units), h.pins.hole_vertex_radius_mm);  // cone steeper than 45 deg
    EXPECT_NEAR(h.pins.hole_radius_mm - h.pins.pin_radius_mm, kPinClearanceMm, 1e-12);
}

// The slab every pillar crosses grows only as much as three pillars need for
// the pins, at least the orientation tab's room (twice the base) - never the
// full pin slab under every pillar when less will do. On a ramp the pillars
// of middle height reach far to both sides of the cut: the slab stays the
// tab's room. Where every pillar but one is
// low, the cut (above the high one's bottom) leaves the low ones no room
// above it: only the full slab will do.
TEST(Halves, TheSlabGrowsOnlyAsMuchAsThePinsNeed) {
    SceneParams p = test::smallParams(Bottom::Mirrored, Cull::None);
    p.max_height_mm = 20;
    p.pitch_mm = 6.0;
    p.halves = true;
    const Scene ramp = buildScene(test::fieldFromFunction(16, 14, [](int c, int) { return double(c); }), p);
    ASSERT_TRUE(ramp.halves);
    const int64_t tab_room = 2 * int64_t(std::llround(p.base_mm / ramp.z_snap_mm));
    EXPECT_EQ(ramp.halves->slab_top_units - ramp.halves->slab_bottom_units, tab_room);
    EXPECT_LT(tab_room, halvesSlabUnits(ramp.z_snap_mm));
    const Scene spike =
        buildScene(test::fieldFromFunction(16, 14, [](int c, int r) { return c == 15 && r == 13 ? 10.0 : 1.0; }), p);
    ASSERT_TRUE(spike.halves);
    EXPECT_GE(spike.halves->slab_top_units - spike.halves->slab_bottom_units,
              halvesSlabUnits(spike.z_snap_mm) - int64_t(std::ceil(kHalvesSlabSearchMm / spike.z_snap_mm)));
}

// Volume of one hole from its radius alone: a regular 16-gon of circumradius
// R, prism to the depth, cone to the tip.
double holeVolume(const Scene& s) {
    const SceneHalves& h = *s.halves;
    const double area = kHoleSides / 2.0 * h.pins.hole_vertex_radius_mm * h.pins.hole_vertex_radius_mm *
                        std::sin(2 * kPi / kHoleSides);
    return area * (s.zMm(h.hole_depth_units) + s.zMm(h.hole_apex_units - h.hole_depth_units) / 3);
}

TEST(Halves, EachHalfIsAClosedSolidWithoutOverhangAndTheirMaterialAddsUp) {
    const Scene s = hillWithHalves(false);  // plain hexagonal pillars: their volume follows from the Scene
    const Mesh upper = meshHalf(s, HalfKind::Upper), lower = meshHalf(s, HalfKind::Lower);
    for (const Mesh* m : {&upper, &lower}) {
        const test::Invariants inv = test::checkInvariants(*m);
        EXPECT_TRUE(inv.closedManifold());
        EXPECT_EQ(inv.duplicate_positions, 0u);
        EXPECT_GT(signedVolume(*m), 0);
        EXPECT_EQ(measureOverhang(*m).area_mm2, 0.0);
        EXPECT_NEAR(meshBounds(*m).min.z, 0.0, 1e-12);  // the cut face on the bed
    }
    // Upper + lower = the pillars (from the Scene alone) less six holes.
    const double expected = test::sceneVolume(s) - 2 * kPinCount * holeVolume(s);
    EXPECT_NEAR(signedVolume(upper) + signedVolume(lower), expected, 1e-4 * expected);
    // The whole mirrored model in one piece overhangs; its halves do not.
    EXPECT_GT(measureOverhang(meshScene(s)).area_mm2, 0.0);
}

// On a lattice stretched north-south (true aspect) the holes stay round in
// mm, and the halves are still closed, without overhang, and add up.
TEST(Halves, HolesStayRoundOnAStretchedLattice) {
    const Scene s = hillWithHalves(false, true);
    ASSERT_EQ(s.y_scale, kRowsAPitchApart);
    ASSERT_TRUE(s.halves);
    for (size_t h = 0; h < s.halves->hole_centres.size(); ++h) {
        const Vec3 c = s.point(s.halves->hole_centres[h], 0);
        for (const PlanarPoint& q : holeRing(s, h)) {
            const Vec3 p = s.point(q, 0);
            EXPECT_NEAR(std::hypot(p.x - c.x, p.y - c.y), s.halves->pins.hole_vertex_radius_mm, 2e-3);
        }
    }
    const Mesh upper = meshHalf(s, HalfKind::Upper), lower = meshHalf(s, HalfKind::Lower);
    for (const Mesh* m : {&upper, &lower}) {
        EXPECT_TRUE(test::checkInvariants(*m).closedManifold());
        EXPECT_EQ(measureOverhang(*m).area_mm2, 0.0);
    }
    const double expected = test::sceneVolume(s) - 2 * kPinCount * holeVolume(s);
    EXPECT_NEAR(signedVolume(upper) + signedVolume(lower), expected, 1e-4 * expected);
}

TEST(Halves, PinsAreClosedPrismsThatFitTheHoles) {
    const PinGeometry g = pinGeometry();
    const Mesh pins = pinsMesh(g);
    const test::Invariants inv = test::checkInvariants(pins);
    EXPECT_TRUE(inv.closedManifold());
    const double area = kHoleSides / 2.0 * g.pin_radius_mm * g.pin_radius_mm * std::sin(2 * kPi / kHoleSides);
    // Corners on the 1 um grid move the area by up to 1e-3 of it.
    EXPECT_NEAR(signedVolume(pins), kPinCount * area * g.pin_length_mm, 1e-3 * signedVolume(pins));
    EXPECT_EQ(measureOverhang(pins).area_mm2, 0.0);
    EXPECT_LT(g.pin_length_mm, 2 * kHoleDepthMm);  // shorter than the two holes it joins
}

TEST(Halves, RefusedWhereTheyCannotBeMade) {
    const HexField f = test::fieldFromFunction(12, 10, [](int c, int) { return double(c); });
    SceneParams flat = test::smallParams(Bottom::Flat);
    flat.halves = true;
    EXPECT_INPUT_ERROR(buildScene(f, flat), "Add --mirror");
    SceneParams tilt = test::smallParams(Bottom::Mirrored);
    tilt.halves = true;
    tilt.tilt = TiltSource::Gradient;
    EXPECT_INPUT_ERROR(buildScene(f, tilt), "--tilt");
    // 3 x 3 cells of 5 mm: no room for three holes clear of the edge.
    const HexField tiny = test::fieldFromFunction(3, 3, [](int c, int r) { return double(c + r); });
    SceneParams small = test::smallParams(Bottom::Mirrored);
    small.halves = true;
    EXPECT_INPUT_ERROR(buildScene(tiny, small), "no room");
    // Cells narrower than a hole.
    SceneParams narrow = small;
    narrow.pitch_mm = 1.5;
    EXPECT_INPUT_ERROR(buildScene(test::fieldFromFunction(40, 40, [](int c, int) { return double(c); }), narrow),
                       "too small for the");
}

}  // namespace
}  // namespace tsf
