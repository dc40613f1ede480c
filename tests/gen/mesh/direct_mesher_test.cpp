#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <map>
#include <random>
#include <set>
#include <tuple>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "tests/support/mesh_invariants.h"

namespace tsf {
namespace {
using test::checkInvariants;
using test::fieldFromFunction;
using test::fieldFromRows;
using test::kNaN;
using test::sceneVolume;
using test::smallParams;


// Twice the signed area of the triangle (a, b, p) seen from above.
double cross2(const Vec3& a, const Vec3& b, const Vec3& p) { return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x); }

// Every kept cell's top can be read back: a level triangle at its top height
// covers its centre (merged tops leave interior corners out, so the corners
// themselves need not be vertices); mirrored, its six bottom corners exist.
void expectCellHeightsPresent(const Scene& s, const Mesh& m) {
    std::set<std::tuple<double, double, double>> pts;
    for (const Vec3& p : m.positions) pts.insert({p.x, p.y, p.z});
    std::multimap<double, std::array<Vec3, 3>> level;  // z -> horizontal triangles
    for (const auto& t : m.triangles) {
        const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
        if (a.z == b.z && b.z == c.z) level.insert({a.z, {a, b, c}});
    }
    for (size_t k = 0; k < s.keptCount(); ++k) {
        const Vec3 centre = s.point(hexCentre(s.grid, s.col[k], s.row[k]), s.top[k]);
        bool covered = false;
        for (auto [at, end] = level.equal_range(centre.z); at != end && !covered; ++at) {
            const auto& [a, b, c] = at->second;
            const double tol = -1e-9 * s.pitch_mm * s.pitch_mm;
            const double u = cross2(a, b, centre), v = cross2(b, c, centre), w = cross2(c, a, centre);
            covered = (u >= tol && v >= tol && w >= tol) || (u <= -tol && v <= -tol && w <= -tol);
        }
        ASSERT_TRUE(covered) << "no top at cell " << s.col[k] << "," << s.row[k];
        if (s.params.bottom == Bottom::Mirrored)
            for (int e = 0; e < 6; ++e) {
                const Vec3 bot = s.point(hexCorner(s.grid, s.col[k], s.row[k], e), s.bottom[k]);
                ASSERT_TRUE(pts.count({bot.x, bot.y, bot.z}));
            }
    }
}

// The longest edge (mm) of the triangles all of whose vertices are at height z (mm).
double longestLevelEdge(const Mesh& m, double z, size_t& faces) {
    double longest = 0;
    faces = 0;
    for (const auto& t : m.triangles) {
        if (m.positions[t[0]].z != z || m.positions[t[1]].z != z || m.positions[t[2]].z != z) continue;
        ++faces;
        for (int i = 0; i < 3; ++i) {
            const Vec3 &a = m.positions[t[size_t(i)]], &b = m.positions[t[size_t((i + 1) % 3)]];
            longest = std::max(longest, std::hypot(a.x - b.x, a.y - b.y));
        }
    }
    return longest;
}

void expectSolid(const HexField& field, const SceneParams& params, const char* what) {
    SCOPED_TRACE(std::string(what) + " " + toString(params.bottom) + " cull=" + toString(params.cull));
    const Scene s = buildScene(field, params);
    const Mesh m = meshScene(s);
    const auto inv = checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.euler, 2) << inv.describe();
    EXPECT_EQ(inv.components, 1u) << inv.describe();
    const double expected = sceneVolume(s);
    EXPECT_NEAR(inv.volume, expected, 1e-9 * expected) << inv.describe();
    expectCellHeightsPresent(s, m);
}

void expectSolidAllModes(const HexField& field, const char* what) {
    for (Bottom b : {Bottom::Flat, Bottom::Mirrored})
        for (Cull c : {Cull::Hull, Cull::None}) expectSolid(field, smallParams(b, c), what);
}

TEST(DirectMesher, SingleCellIsAHexagonalPrism) {
    const Scene s = buildScene(fieldFromRows({{1}}), smallParams());
    const Mesh m = meshScene(s);
    // 12 corners; top 4 triangles, bottom 4, six walls of 2.
    EXPECT_EQ(m.vertexCount(), 12u);
    EXPECT_EQ(m.triangleCount(), 20u);
    expectSolidAllModes(fieldFromRows({{1}}), "1x1");
}

TEST(DirectMesher, EqualNeighboursGetNoWallBetweenThem) {
    // Two equal cells side by side: the shared edge carries no wall, so the
    // solid is one 10-sided prism: 10 top vertices... plus the bottom rim.
    const Scene s = buildScene(fieldFromRows({{3, 3}}), smallParams(Bottom::Flat, Cull::None));
    const Mesh m = meshScene(s);
    EXPECT_EQ(m.vertexCount(), 20u);
    // Tops 2x4, bottom polygon of 10 vertices -> 8, outer walls 10 x 2.
    EXPECT_EQ(m.triangleCount(), 8u + 8u + 20u);
}

TEST(DirectMesher, StepBetweenNeighboursIsOneWallSplitAtEveryCornerHeight) {
    const Scene s = buildScene(fieldFromRows({{1, 2}}), smallParams(Bottom::Flat, Cull::None));
    const auto inv = checkInvariants(meshScene(s));
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.euler, 2);
}

TEST(DirectMesher, FlatBottomIsSparseAndWellShaped) {
    const Scene s = buildScene(fieldFromFunction(30, 26, [](int c, int r) { return (c * 7 + r * 3) % 5; }),
                               smallParams(Bottom::Flat, Cull::None));
    const Mesh m = meshScene(s);
    size_t bottom_vertices = 0, bottom_faces = 0;
    for (const Vec3& p : m.positions) bottom_vertices += p.z == 0.0;
    const double longest = longestLevelEdge(m, 0.0, bottom_faces);
    // A polygon with n boundary vertices needs n - 2 triangles; interior
    // vertices add two each, and there are some: more than n - 2.
    EXPECT_GT(bottom_faces, bottom_vertices - 2);
    EXPECT_LT(bottom_vertices, size_t(2 * 30 * 26 / 4));  // far fewer than the 2 * 30 * 26 lattice vertices
    // No triangle spans the model (30 pitches wide): a few cells at most.
    EXPECT_LE(longest, 6.0 * s.pitch_mm);
    EXPECT_GT(longest, 0.0);
}

TEST(DirectMesher, EqualHeightTopsMergeWithoutLongTriangles) {
    // A 20 x 20 plateau with a raised 3-cell island and a no-data hole: one
    // merged top around them.
    const HexField f = fieldFromFunction(20, 20, [](int c, int r) {
        if (r == 9 && c >= 8 && c <= 10) return 4.0;
        if (r == 14 && c == 5) return kNaN;
        return (c + r) == 0 ? 0.0 : 2.0;  // one lower corner cell so the plateau is not the floor
    });
    for (Bottom b : {Bottom::Flat, Bottom::Mirrored}) {
        const Scene s = buildScene(f, smallParams(b, Cull::None));
        expectSolid(f, smallParams(b, Cull::None), "plateau");
        const Mesh m = meshScene(s);
        const int32_t k = s.keptAt(0, 10);
        ASSERT_GE(k, 0);
        size_t plateau_faces = 0;
        const double longest = longestLevelEdge(m, s.zMm(s.top[size_t(k)]), plateau_faces);
        // About 396 cells of 4 triangles each unmerged; merged: the boundary
        // plus two per kept sparse vertex.
        EXPECT_LT(plateau_faces, size_t(396 * 4 / 2));
        EXPECT_LE(longest, 6.0 * s.pitch_mm);
    }
}

TEST(DirectMesher, ExtremeFields) {
    expectSolidAllModes(fieldFromRows({{0}}), "1x1 zero");
    expectSolidAllModes(fieldFromRows({{0, 0, 0}, {0, 5, 0}, {0, 0, 0}}), "one non-zero cell");
    expectSolidAllModes(fieldFromFunction(6, 5, [](int, int) { return 0.0; }), "all zero");
    expectSolidAllModes(fieldFromFunction(6, 5, [](int, int) { return 42.0; }), "constant");
    expectSolidAllModes(fieldFromFunction(8, 7, [](int c, int r) { return 1.0 + 1e-12 * ((c + r) % 3); }), "1e-12 steps");
    expectSolidAllModes(fieldFromFunction(8, 7, [](int c, int r) { return 1e9 * ((c * r) % 4); }), "1e9 values");
    expectSolidAllModes(fieldFromFunction(9, 8, [](int c, int r) { return double((c + r) % 2); }), "checkerboard");
    expectSolidAllModes(fieldFromFunction(9, 8, [](int c, int r) { return (c + 2 * r) % 3 == 0 ? kNaN : double(c); }),
                        "NaN holes");
    expectSolidAllModes(fieldFromFunction(9, 8, [](int c, int r) { return c == r ? 1.0 : 0.0; }), "diagonal line");
    expectSolidAllModes(fieldFromFunction(9, 8, [](int c, int r) { return r == 3 && c % 3 == 0 ? 2.0 : 0.0; }),
                        "collinear row");
    expectSolidAllModes(fieldFromFunction(9, 8, [](int c, int r) { return c == 4 && r % 3 == 0 ? 2.0 : 0.0; }),
                        "collinear column");
    expectSolidAllModes(fieldFromFunction(9, 8, [](int c, int r) { return (c == 1 && r == 1) || (c == 4 && r == 6) ? 1.0 : 0.0; }),
                        "knight's move pair");
    expectSolidAllModes(fieldFromFunction(7, 6, [](int c, int r) { return c - 3.0 + r; }), "negative values");
    expectSolidAllModes(fieldFromFunction(1, 9, [](int, int r) { return double(r); }), "single column");
    expectSolidAllModes(fieldFromFunction(9, 1, [](int c, int) { return double(c); }), "single row");
}

TEST(DirectMesher, RandomFieldsAreAlwaysSolid) {
    std::mt19937 rng(1234);
    std::uniform_real_distribution<double> u(0, 1);
    for (int trial = 0; trial < 40; ++trial) {
        const int cols = 1 + int(u(rng) * 12), rows = 1 + int(u(rng) * 12);
        const double sparsity = u(rng);
        HexField f = fieldFromFunction(cols, rows, [&](int, int) {
            const double x = u(rng);
            if (x < sparsity * 0.3) return kNaN;
            if (x < sparsity) return 0.0;
            return std::floor(u(rng) * 5);  // few distinct levels: many equal neighbours
        });
        bool any = false;
        for (double v : f.values) any |= !std::isnan(v);
        if (!any) continue;
        SceneParams p = smallParams(u(rng) < 0.5 ? Bottom::Flat : Bottom::Mirrored, u(rng) < 0.5 ? Cull::Hull : Cull::None);
        p.transfer = trial % 3 == 0 ? Transfer::Sqrt : Transfer::Linear;
        expectSolid(f, p, ("random " + std::to_string(trial)).c_str());
    }
}

TEST(DirectMesher, ThousandByThousandGridIsSolid) {
    const HexField f = fieldFromFunction(1000, 1000, [](int c, int r) {
        return std::sin(c * 0.05) * std::cos(r * 0.03) + 1.0;
    });
    SceneParams p = smallParams(Bottom::Flat, Cull::None);
    p.pitch_mm = 0.2;
    const Scene s = buildScene(f, p);
    const Mesh m = meshScene(s);
    const auto inv = checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.euler, 2);
    EXPECT_EQ(inv.components, 1u);
    EXPECT_NEAR(inv.volume, sceneVolume(s), 1e-8 * inv.volume);
}

}  // namespace
}  // namespace tsf
