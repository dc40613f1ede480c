// The fingertip's reach (verify/finger_reach.h) on sampled tops made here:
// fixed cases (a pit, the foot of a wall, a plain), and metamorphic ones that
// hold for any top because physics says so: a smaller fingertip leaves no
// deeper or larger region unreached; raising a wall beside a pit or deepening
// the pit never makes it shallower or smaller.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <tuple>
#include <random>
#include <vector>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "tests/support/fields.h"
#include "verify/finger_reach.h"
#include "verify/tactile.h"

namespace tsf {
namespace {

constexpr double kStep = 0.5;  // mm, as tsf verify samples

// A top of blocks: cells `cell` samples square, each at its height (mm).
struct Blocks {
    int cols = 0, rows = 0, cell = 6;  // 6 samples: 3 mm blocks
    std::vector<double> z;             // cols * rows
    double& at(int c, int r) { return z[size_t(r) * size_t(cols) + size_t(c)]; }
    TopHeightField top() const {
        TopHeightField h;
        h.step = kStep;
        h.nx = cols * cell;
        h.ny = rows * cell;
        h.z.resize(size_t(h.nx) * size_t(h.ny));
        for (int j = 0; j < h.ny; ++j)
            for (int i = 0; i < h.nx; ++i) h.z[size_t(j) * size_t(h.nx) + size_t(i)] = z[size_t(j / cell) * size_t(cols) + size_t(i / cell)];
        return h;
    }
};

Blocks plateau(int cols, int rows, double height) {
    Blocks b;
    b.cols = cols;
    b.rows = rows;
    b.z.assign(size_t(cols) * size_t(rows), height);
    return b;
}

// Random blocks 0-20 mm: pits, walls and valleys of every width.
Blocks randomBlocks(unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> height(0.0, 20.0);
    Blocks b = plateau(14, 12, 0);
    for (double& z : b.z) z = std::round(height(rng) * 5) / 5;  // 0.2 mm layers
    return b;
}

FingerReachResult reach(const Blocks& b, std::vector<double> radii = {kAdultFingertipRadiusMm, kChildFingertipRadiusMm}) {
    return fingerReach(b.top(), -2.0, radii);
}

// The ball's closing written the plain way, offset by offset over the whole
// disc and sample by sample, against which the closing verify uses is
// checked bit for bit.
std::vector<double> closedByBallPlainly(const TopHeightField& h, double r, double table) {
    const int n = int(std::ceil(r / h.step));
    const auto height = [&](int i, int j) {
        if (i < 0 || j < 0 || i >= h.nx || j >= h.ny) return table;
        const double z = h.at(i, j);
        return std::isfinite(z) ? z : table;
    };
    const auto inDisc = [&](int di, int dj) {
        return (di * h.step) * (di * h.step) + (dj * h.step) * (dj * h.step) <= r * r;
    };
    const auto rise = [&](int di, int dj) {
        return std::sqrt(r * r - ((di * h.step) * (di * h.step) + (dj * h.step) * (dj * h.step)));
    };
    const auto centre = [&](int i, int j) {  // the lowest the ball's centre over (i, j) goes
        if (i < 0 || j < 0 || i >= h.nx || j >= h.ny) return table + r;
        double c = -std::numeric_limits<double>::infinity();
        for (int dj = -n; dj <= n; ++dj)
            for (int di = -n; di <= n; ++di)
                if (inDisc(di, dj)) c = std::max(c, height(i + di, j + dj) + rise(di, dj));
        return c;
    };
    std::vector<double> centres(h.z.size());
    for (int j = 0; j < h.ny; ++j)
        for (int i = 0; i < h.nx; ++i) centres[size_t(j) * size_t(h.nx) + size_t(i)] = centre(i, j);
    const auto centreAt = [&](int i, int j) {
        return i < 0 || j < 0 || i >= h.nx || j >= h.ny ? table + r : centres[size_t(j) * size_t(h.nx) + size_t(i)];
    };
    std::vector<double> out(h.z.size());
    for (int j = 0; j < h.ny; ++j)
        for (int i = 0; i < h.nx; ++i) {
            double low = std::numeric_limits<double>::infinity();
            for (int dj = -n; dj <= n; ++dj)
                for (int di = -n; di <= n; ++di)
                    if (inDisc(di, dj)) low = std::min(low, centreAt(i + di, j + dj) - rise(di, dj));
            out[size_t(j) * size_t(h.nx) + size_t(i)] = low;
        }
    return out;
}

TEST(FingerReach, TheBallsClosingIsThePlainOneBitForBit) {
    // Random tops (some samples with nothing over them), odd sizes smaller
    // and larger than the ball, steps that do and do not divide the radius.
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> height(0.0, 20.0);
    int compared = 0;
    for (const auto& [nx, ny, step, r] : {std::tuple{37, 23, 0.5, 8.0}, {9, 41, 0.5, 5.5}, {30, 30, 0.37, 3.1},
                                          {5, 3, 0.5, 8.0}, {64, 1, 0.25, 2.0}}) {
        TopHeightField h;
        h.step = step;
        h.nx = nx;
        h.ny = ny;
        h.z.resize(size_t(nx) * size_t(ny));
        for (double& z : h.z) z = rng() % 9 == 0 ? -std::numeric_limits<double>::infinity() : height(rng);
        const std::vector<double> fast = closedByBall(h, r, -2.0), plain = closedByBallPlainly(h, r, -2.0);
        ASSERT_EQ(fast.size(), plain.size());
        for (size_t s = 0; s < plain.size(); ++s) {
            ASSERT_EQ(fast[s], plain[s]) << "sample " << s << " of " << nx << " x " << ny << ", r " << r;
            ++compared;
        }
    }
    EXPECT_EQ(compared, 37 * 23 + 9 * 41 + 30 * 30 + 5 * 3 + 64);
}

TEST(FingerReach, APlateauHasNoPlace) {
    const FingerReachResult r = reach(plateau(8, 8, 10));
    ASSERT_EQ(r.fingers.size(), 2u);
    EXPECT_EQ(r.fingers[0].places, 0);
    EXPECT_EQ(r.fingers[0].area_mm2, 0);
}

// A 3 mm block 4 mm below the eight around it: one place, the pit's floor,
// reached about w^2 / (8 r) = 0.14 mm down by an adult's fingertip.
TEST(FingerReach, ANarrowPitIsOnePlaceOfItsDepth) {
    Blocks b = plateau(9, 9, 10);
    b.at(4, 4) = 6;
    const FingerReachResult r = reach(b);
    EXPECT_EQ(r.fingers[0].places, 1);
    EXPECT_NEAR(r.fingers[0].deepest_mm, 4.0 - 0.14, 0.2);
    EXPECT_NEAR(r.fingers[0].area_mm2, 9.0, 3.0) << "the pit's floor, 3 x 3 mm";
    EXPECT_EQ(r.fingers[0].worst.size(), 1u) << "listed once";
    // 1 mm deep: the pressing finger reaches it.
    b.at(4, 4) = 9;
    EXPECT_EQ(reach(b).fingers[0].places, 0);
}

// A tall block on a plain leaves a strip at its foot the ball cannot touch;
// the plain continues from the strip to where the ball reaches it: read.
TEST(FingerReach, TheFootOfAWallIsRead) {
    Blocks b = plateau(12, 12, 0);
    for (int r = 4; r < 8; ++r)
        for (int c = 4; c < 8; ++c) b.at(c, r) = 20;
    const FingerReachResult r = reach(b);
    EXPECT_EQ(r.fingers[0].places, 0);
    EXPECT_EQ(r.fingers[1].places, 0);
}

// A samples' mask of no value (a no-data pit): never a place, counted apart.
TEST(FingerReach, APitWithoutDataIsNoPlace) {
    Blocks b = plateau(9, 9, 20);
    b.at(4, 4) = 0;
    const TopHeightField top = b.top();
    std::vector<uint8_t> no_value(top.z.size(), 0);
    for (size_t s = 0; s < top.z.size(); ++s) no_value[s] = top.z[s] == 0;
    const FingerReachResult r = fingerReach(top, -2.0, {kAdultFingertipRadiusMm}, no_value);
    EXPECT_EQ(r.fingers[0].places, 0);
    EXPECT_GT(r.fingers[0].no_value_area_mm2, 5.0);
    EXPECT_EQ(fingerReach(top, -2.0, {kAdultFingertipRadiusMm}).fingers[0].places, 1) << "with data it is a place";
}

// Shrink the finger: every smaller fingertip leaves at most the area and
// depth the larger one left, on any top.
TEST(FingerReach, ASmallerFingertipNeverLeavesMoreUnreached) {
    const std::vector<double> radii = {9.0, 8.0, 7.0, 6.0, 5.5, 4.5, 3.0};
    int64_t any_places = 0;
    for (unsigned seed = 1; seed <= 12; ++seed) {
        const FingerReachResult r = reach(randomBlocks(seed), radii);
        ASSERT_EQ(r.fingers.size(), radii.size());
        any_places += r.fingers[0].places;
        for (size_t f = 1; f < radii.size(); ++f) {
            EXPECT_LE(r.fingers[f].area_mm2, r.fingers[f - 1].area_mm2 + 1e-9) << "seed " << seed << " radius " << radii[f];
            EXPECT_LE(r.fingers[f].deepest_mm, r.fingers[f - 1].deepest_mm + 1e-9) << "seed " << seed << " radius " << radii[f];
        }
    }
    EXPECT_GT(any_places, 0) << "the tops must have places for the test to mean anything";
}

// A pit among walls of any height: raising a wall, or deepening the pit,
// never leaves the pit shallower or smaller (the walls stand at one height,
// so the pit is the only place).
TEST(FingerReach, RaisingAWallOrDeepeningAPitNeverHelps) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> wall(4.0, 20.0), rise(0.2, 6.0), deeper(0.2, 4.0);
    int checked = 0;
    for (int trial = 0; trial < 20; ++trial) {
        Blocks b = plateau(9, 9, wall(rng));
        const int w = 1 + trial % 2;  // a pit of one or two blocks
        for (int c = 4; c < 4 + w; ++c) b.at(c, 4) = 1.0;
        const FingerReach before = reach(b).fingers[0];
        Blocks raised = b;
        raised.at(trial % 3 == 0 ? 3 : 4, trial % 3 == 2 ? 3 : 5) += rise(rng);  // a wall beside the pit
        const FingerReach after_wall = reach(raised).fingers[0];
        Blocks deep = b;
        const double d = deeper(rng);
        for (int c = 4; c < 4 + w; ++c) deep.at(c, 4) -= d;
        const FingerReach after_pit = reach(deep).fingers[0];
        EXPECT_GE(after_wall.deepest_mm, before.deepest_mm - 1e-9) << "trial " << trial;
        EXPECT_GE(after_wall.area_mm2, before.area_mm2 - 1e-9) << "trial " << trial;
        EXPECT_GE(after_pit.deepest_mm, before.deepest_mm + d - 1e-6) << "trial " << trial << ": the ball rests on the walls";
        EXPECT_GE(after_pit.area_mm2, before.area_mm2 - 1e-9) << "trial " << trial;
        checked += before.places > 0;
    }
    EXPECT_GT(checked, 10);
}

// Cells `cell_mm` across, a value of 20 standing 20 mm above a zero floor:
// a value is its height in millimetres.
SceneParams pillarParams(double cell_mm) {
    SceneParams p = test::smallParams(Bottom::Flat, Cull::None);
    p.pitch_mm = cell_mm;
    p.max_height_mm = 20;
    p.baseline_mode = BaselineMode::Zero;
    p.value_max = 20;
    return p;
}

// Pillars of a tenth of a millimetre hold a few ten-thousandths of a
// millimetre free: the note and each offender say so in figures a reader
// can use, not "stands 0.0 mm above ...: more than 0.0 mm breaks".
TEST(TactileSlender, TinyPillarsAreDescribedInSignificantFigures) {
    const SceneParams p = pillarParams(0.15);
    const Scene s = buildScene(test::fieldFromFunction(5, 5, [](int c, int r) { return c == 2 && r == 2 ? 0.02 : 0.0; }), p);
    for (const Check& c : checkTactile(meshScene(s), &s, TactileOptions{}).checks) {
        if (c.id != "tactile_slender_pillars") continue;
        EXPECT_EQ(c.status, CheckStatus::Fail) << c.note;
        EXPECT_EQ(c.note.find("0.0 mm"), std::string::npos) << c.note;
        EXPECT_NE(c.note.find("up to 0.0007 mm free"), std::string::npos) << c.note;
        ASSERT_FALSE(c.worst.empty());
        EXPECT_NE(c.worst[0].detail.find("stands 0.02 mm above its neighbours"), std::string::npos) << c.worst[0].detail;
        return;
    }
    ADD_FAILURE() << "no slender-pillar check";
}

// The slender-pillar check on built models: raising the spike never makes
// it stand stronger, and a thinner pillar never stands stronger (a failure
// at w mm cells stays one at thinner cells).
TEST(TactileMonotone, SlenderPillarsAreMonotoneInHeightAndWidth) {
    auto verdict = [](double spike, double cell) {
        const SceneParams p = pillarParams(cell);
        const Scene s = buildScene(test::fieldFromFunction(5, 5, [&](int c, int r) { return c == 2 && r == 2 ? spike : 0.0; }), p);
        for (const Check& c : checkTactile(meshScene(s), &s, TactileOptions{}).checks)
            if (c.id == "tactile_slender_pillars") return c.status == CheckStatus::Fail;
        ADD_FAILURE() << "no slender-pillar check";
        return false;
    };
    bool failed_taller = false;
    for (double spike : {2.0, 4.0, 6.0, 10.0, 20.0}) {
        const bool fails = verdict(spike, 3.0);
        EXPECT_TRUE(fails || !failed_taller) << spike << " mm passes after a lower spike failed";
        failed_taller = failed_taller || fails;
    }
    EXPECT_TRUE(failed_taller) << "a 20 mm spike 3 mm across breaks";
    bool failed_wider = false;
    for (double cell : {8.0, 6.0, 5.0, 4.0, 3.0}) {
        const bool fails = verdict(12.0, cell);
        EXPECT_TRUE(fails || !failed_wider) << cell << " mm cells pass after wider ones failed";
        failed_wider = failed_wider || fails;
    }
    EXPECT_FALSE(verdict(12.0, 8.0)) << "12 mm free, 8 mm across: stands";
    EXPECT_TRUE(failed_wider) << "12 mm free, 3 mm across: breaks";
}

// What a search over settings asks of each model it tries: the two checks a
// setting can fix, each exactly as the whole tactile check gives it (status,
// count, note, offenders), failing here, where a pit one cell wide sits 20
// mm deep beside a spike 12 mm above its neighbours at 3 mm cells.
TEST(TactileLegibility, TheChecksASettingCanFixAreTheTactileChecksOwn) {
    const SceneParams p = pillarParams(3);
    const Scene s = buildScene(test::fieldFromFunction(9, 9, [](int c, int r) {
                                   return c == 2 && r == 2 ? 0.0 : c == 6 && r == 6 ? 20.0 : 8.0;
                               }),
                               p);
    const Mesh m = meshScene(s);
    TactileOptions o;
    o.max_offenders = 3;
    const TactileResult whole = checkTactile(m, &s, o), fixable = checkLegibility(m, s, o);
    std::vector<const Check*> expected;
    for (const Check& c : whole.checks)
        if (c.id == "tactile_finger_reach" || c.id == "tactile_slender_pillars") expected.push_back(&c);
    ASSERT_EQ(expected.size(), 2u);
    ASSERT_EQ(fixable.checks.size(), 2u);
    for (size_t k = 0; k < 2; ++k) {
        const Check &a = *expected[k], &b = fixable.checks[k];
        EXPECT_EQ(a.id, b.id);
        EXPECT_EQ(a.status, CheckStatus::Fail) << a.id << ": " << a.note;
        EXPECT_EQ(a.status, b.status) << a.id;
        EXPECT_EQ(a.count, b.count) << a.id;
        EXPECT_EQ(a.note, b.note) << a.id;
        ASSERT_EQ(a.worst.size(), b.worst.size()) << a.id;
        for (size_t w = 0; w < a.worst.size(); ++w) {
            EXPECT_EQ(a.worst[w].detail, b.worst[w].detail) << a.id;
            EXPECT_EQ(a.worst[w].amount, b.worst[w].amount) << a.id;
        }
    }
}

}  // namespace
}  // namespace tsf
