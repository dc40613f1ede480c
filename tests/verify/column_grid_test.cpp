// ColumnGrid: the same first hit as the tree for every kind of ray (straight
// down through every lattice point, along the walls, at random), and every
// pair of triangles that touch or cross among its candidate pairs, once.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "tests/support/fields.h"
#include "tests/verify/verify_test_support.h"
#include "verify/column_grid.h"
#include "verify/triangle_bvh.h"

namespace tsf {
namespace {

// The grid and the tree answer a ray alike: both hit or both miss, at the
// same distance, on the same triangle (ties go to the lower index in both).
void expectSameHit(const ColumnGrid& grid, const TriangleBvh& tree, const Vec3& o, const Vec3& d, int64_t skip,
                   double max_mm, const std::string& what) {
    const auto a = grid.firstHit(o, d, skip, max_mm);
    const auto b = tree.firstHit(o, d, skip, max_mm);
    ASSERT_EQ(bool(a), bool(b)) << what << " from (" << o.x << ", " << o.y << ", " << o.z << ") along (" << d.x << ", "
                                << d.y << ", " << d.z << ")";
    if (!a) return;
    EXPECT_EQ(a->distance_mm, b->distance_mm) << what;
    EXPECT_EQ(a->triangle, b->triangle) << what;
    EXPECT_EQ(a->point_mm, b->point_mm) << what;
}

class ColumnGridRays : public ::testing::TestWithParam<Bottom> {};

TEST_P(ColumnGridRays, SameFirstHitsAsTheTree) {
    const vtest::Model m = vtest::smallModel(GetParam());
    const Scene& s = m.scene;
    const Bounds b = meshBounds(m.mesh);
    const TriangleBvh tree(m.mesh);
    for (const double per_column : {1.0, ColumnGrid::kTrianglesPerColumn, 50.0}) {
        const ColumnGrid grid(m.mesh, per_column);
        ASSERT_EQ(grid.triangleCount(), m.mesh.triangles.size());
        // Straight down and up through every centre and corner: on the
        // diagonals of the tops, along the walls' edges.
        size_t hits = 0;
        for (size_t k = 0; k < s.keptCount(); ++k) {
            for (const Vec3& p : vtest::cellCentreAndCorners(s, k)) {
                expectSameHit(grid, tree, {p.x, p.y, b.max.z + 5}, {0, 0, -1}, -1, INFINITY, "down");
                expectSameHit(grid, tree, {p.x, p.y, b.min.z - 5}, {0, 0, 1}, -1, INFINITY, "up");
                hits += bool(grid.firstHit({p.x, p.y, b.max.z + 5}, {0, 0, -1}));
            }
        }
        EXPECT_EQ(hits, 7 * s.keptCount());
        // From every triangle's centroid along and against its normal, and
        // horizontally: the printability's rays, through the solid.
        for (uint32_t t = 0; t < m.mesh.triangles.size(); ++t) {
            const auto& q = m.mesh.triangles[t];
            const Vec3 n = cross(sub(m.mesh.positions[q[1]], m.mesh.positions[q[0]]),
                                 sub(m.mesh.positions[q[2]], m.mesh.positions[q[0]]));
            const Vec3 c = vtest::centroid(m.mesh, t);
            for (const double sgn : {-1.0, 1.0}) {
                expectSameHit(grid, tree, c, {sgn * n.x, sgn * n.y, sgn * n.z}, t, INFINITY, "normal");
                expectSameHit(grid, tree, c, {sgn * n.x, sgn * n.y, sgn * n.z}, t, 1.6, "normal, within 1.6 mm");
                expectSameHit(grid, tree, c, {sgn, 0.0, 0.0}, t, INFINITY, "along x");
                expectSameHit(grid, tree, c, {0.0, sgn, 0.0}, t, INFINITY, "along y");
            }
        }
        // At random, from in and around the model.
        std::mt19937 rng(31);
        std::uniform_real_distribution<double> ux(b.min.x - 5, b.max.x + 5), uy(b.min.y - 5, b.max.y + 5),
            uz(b.min.z - 5, b.max.z + 5), ud(-1, 1);
        int random_hits = 0;
        for (int i = 0; i < 3000; ++i) {
            const Vec3 o{ux(rng), uy(rng), uz(rng)}, d{ud(rng), ud(rng), i % 3 == 0 ? 0.0 : ud(rng)};
            expectSameHit(grid, tree, o, d, -1, INFINITY, "random ray " + std::to_string(i));
            random_hits += bool(grid.firstHit(o, d));
        }
        EXPECT_GT(random_hits, 500);  // not vacuous
    }
}

INSTANTIATE_TEST_SUITE_P(FlatAndMirrored, ColumnGridRays, ::testing::Values(Bottom::Flat, Bottom::Mirrored),
                         [](const auto& info) { return info.param == Bottom::Flat ? "Flat" : "Mirrored"; });

// A grid for vertical rays leaves the walls out and answers every vertical
// ray as the tree does (no vertical ray hits a wall), on one thread and on
// several; asked for another ray or for the pairs, it refuses.
TEST(ColumnGrid, AGridForVerticalRaysHitsWhatTheTreeHits) {
    for (const bool large : {false, true}) {
        SceneParams p = vtest::smallFieldParams(large ? Bottom::Mirrored : Bottom::Flat, 0.01);
        p.pitch_mm = 2.0;
        const int n = large ? 45 : 9;
        const Scene s = buildScene(
            test::fieldFromFunction(n, n, [](int c, int r) { return 1.0 + std::sin(c * 0.3) * std::cos(r * 0.2); }), p);
        const Mesh m = meshScene(s);
        if (large) ASSERT_GT(m.triangles.size(), 20000u);  // built on the threads
        const ColumnGrid all(m), vertical(m, ColumnGrid::kTrianglesPerColumn, ColumnGrid::Rays::Vertical);
        EXPECT_EQ(vertical.rays(), ColumnGrid::Rays::Vertical);
        EXPECT_LT(vertical.entries(), all.entries() * 3 / 4) << "the walls are listed";
        const TriangleBvh tree(m);
        const Bounds b = meshBounds(m);
        size_t hits = 0;
        for (size_t k = 0; k < s.keptCount(); ++k) {
            for (const Vec3& q : vtest::cellCentreAndCorners(s, k)) {
                expectSameHit(vertical, tree, {q.x, q.y, b.max.z + 5}, {0, 0, -1}, -1, INFINITY, "down");
                expectSameHit(vertical, tree, {q.x, q.y, b.min.z - 5}, {0, 0, 1}, -1, INFINITY, "up");
                // From inside the solid, halfway up its pillar: the top above, the floor below.
                const double mid = 0.5 * (s.zMm(s.top[k]) + s.zMm(s.bottom[k]));
                expectSameHit(vertical, tree, {q.x, q.y, mid}, {0, 0, 1}, -1, INFINITY, "up from inside");
                expectSameHit(vertical, tree, {q.x, q.y, mid}, {0, 0, -1}, -1, INFINITY, "down from inside");
                hits += bool(vertical.firstHit({q.x, q.y, b.max.z + 5}, {0, 0, -1}));
            }
        }
        EXPECT_EQ(hits, 7 * s.keptCount());
        EXPECT_THROW((void)vertical.firstHit({0, 0, 1}, {1, 0, 0}), std::logic_error);
        EXPECT_THROW((void)vertical.firstHit({0, 0, 1}, {0, 1e-9, -1}), std::logic_error);
        EXPECT_THROW(vertical.forEachOverlappingPair([](unsigned, uint32_t, uint32_t) {}), std::logic_error);
    }
}

TEST(ColumnGrid, SkipMaxDistanceAndDegenerateInputs) {
    const Mesh m = vtest::box({0, 0, 0}, {1, 1, 1});
    const ColumnGrid grid(m);
    const auto hit = grid.firstHit({0.25, 0.5, 0}, {0, 0, 1});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->distance_mm, 0.0);
    const auto through = grid.firstHit({0.25, 0.5, 0}, {0, 0, 1}, hit->triangle);
    ASSERT_TRUE(through);
    EXPECT_DOUBLE_EQ(through->distance_mm, 1.0);
    EXPECT_FALSE(grid.firstHit({0.25, 0.5, 0}, {0, 0, 1}, hit->triangle, 0.5));
    EXPECT_TRUE(grid.firstHit({0.25, 0.5, 0}, {0, 0, 1}, hit->triangle, 1.0));  // a hit at the limit counts
    EXPECT_DOUBLE_EQ(grid.firstHit({0.25, 0.5, -2}, {0, 0, 7})->distance_mm, 2.0);
    EXPECT_DOUBLE_EQ(grid.firstHit({-3, 0.5, 0.5}, {1, 0, 0})->distance_mm, 3.0);  // from outside the grid
    EXPECT_FALSE(grid.firstHit({0.5, 0.5, 5}, {0, 0, 0}));
    EXPECT_FALSE(grid.firstHit({0.5, 0.5, 5}, {0, 0, NAN}));
    EXPECT_FALSE(grid.firstHit({0.5, 0.5, 5}, {0, 0, 1}));   // pointing away
    EXPECT_FALSE(grid.firstHit({5, 0.5, 0.5}, {0, 0, -1}));  // beside the grid
    const Mesh nothing;
    const ColumnGrid empty(nothing);
    EXPECT_EQ(empty.triangleCount(), 0u);
    EXPECT_FALSE(empty.firstHit({0, 0, 0}, {1, 0, 0}));
    empty.forEachOverlappingPair([](unsigned, uint32_t, uint32_t) { ADD_FAILURE() << "a pair in an empty grid"; });
    Mesh bad = m;
    bad.triangles.push_back({0, 1, 100});
    bad.positions[7].z = INFINITY;  // used by 4 triangles of the box
    const ColumnGrid partial(bad);
    EXPECT_EQ(partial.triangleCount(), 12u - 4u);
}

// Widely spread boxes (x from 1 to 2^600): the grid's columns stay bounded
// and every box is still found.
TEST(ColumnGrid, WidelySpreadCoordinates) {
    Mesh all;
    for (int k = 0; k < 600; k += 3) all = test::append(std::move(all), vtest::box({std::ldexp(1.0, k), 0, 0}, {1.5 * std::ldexp(1.0, k), 1, 1}));
    const ColumnGrid grid(all);
    EXPECT_LE(grid.columns(), 4096);
    for (int k = 0; k < 600; k += 3) {
        const auto down = grid.firstHit({1.25 * std::ldexp(1.0, k), 0.5, 5}, {0, 0, -1});
        ASSERT_TRUE(down) << "box " << k;
        EXPECT_EQ(down->point_mm.z, 1.0);
    }
}

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

K::Triangle_3 cgalTriangle(const Mesh& m, uint32_t t) {
    auto p = [&](int i) {
        const Vec3& v = m.positions[m.triangles[t][i]];
        return K::Point_3(v.x, v.y, v.z);
    };
    return {p(0), p(1), p(2)};
}

// Every pair of triangles that touch or cross (CGAL, all pairs) is a
// candidate, exactly once, and every candidate's boxes overlap.
void expectEveryTouchingPair(const Mesh& m, const ColumnGrid& grid, const std::string& what) {
    const auto got = vtest::visitedPairs(grid);
    EXPECT_EQ(std::adjacent_find(got.begin(), got.end()), got.end()) << what << ": a pair was visited twice";
    const size_t n = m.triangles.size();
    std::vector<K::Triangle_3> tris;
    std::vector<CGAL::Bbox_3> boxes;
    for (uint32_t t = 0; t < n; ++t) {
        tris.push_back(cgalTriangle(m, t));
        boxes.push_back(tris.back().bbox());
    }
    size_t touching = 0;
    for (uint32_t a = 0; a < n; ++a)
        for (uint32_t b = a + 1; b < n; ++b) {
            if (!CGAL::do_overlap(boxes[a], boxes[b])) continue;
            if (tris[a].is_degenerate() || tris[b].is_degenerate() || !CGAL::do_intersect(tris[a], tris[b])) continue;
            ++touching;
            EXPECT_TRUE(std::binary_search(got.begin(), got.end(), std::make_pair(a, b)))
                << what << ": triangles " << a << " and " << b << " touch but are no candidate pair";
        }
    for (const auto& [a, b] : got) EXPECT_TRUE(CGAL::do_overlap(boxes[a], boxes[b])) << what;
    EXPECT_GT(touching, n);  // neighbours touch: not vacuous
}

// On a flat bottom, the long thin triangles of the bottom are listed by
// their shadow and the rest by their boxes: pairs of both kinds.
TEST(ColumnGrid, EveryTouchingPairIsACandidateOnce) {
    for (const Bottom bottom : {Bottom::Mirrored, Bottom::Flat}) {
    const vtest::Model model = vtest::smallModel(bottom);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> move(-model.scene.pitch_mm, model.scene.pitch_mm);
    std::uniform_int_distribution<size_t> pick(0, model.mesh.positions.size() - 1);
    for (int round = 0; round < 4; ++round) {
        Mesh m = model.mesh;
        for (int i = 0; i < 3 * round; ++i) {
            Vec3& p = m.positions[pick(rng)];
            p = {p.x + move(rng), p.y + move(rng), p.z + 4 * move(rng)};
        }
        for (const double per_column : {1.0, 4.0, 20.0}) {
            const ColumnGrid grid(m, per_column);
            expectEveryTouchingPair(m, grid, "round " + std::to_string(round) + ", " + std::to_string(per_column) + " a column");
        }
    }
    }
}

// A model large enough for the grid to be built on several threads: the
// same first hits as the tree, and every touching pair of the tree's
// overlapping boxes a candidate, once.
TEST(ColumnGrid, ALargeModelBuiltOnSeveralThreadsAgreesWithTheTree) {
    SceneParams p = vtest::smallFieldParams(Bottom::Mirrored, 0.01);
    p.pitch_mm = 2.0;
    const Scene s = buildScene(test::fieldFromFunction(45, 40, [](int c, int r) { return 1.0 + std::sin(c * 0.3) * std::cos(r * 0.2); }), p);
    const Mesh m = meshScene(s);
    ASSERT_GT(m.triangles.size(), 40000u);
    const ColumnGrid grid(m);
    const TriangleBvh tree(m);
    const Bounds b = meshBounds(m);
    for (size_t k = 0; k < s.keptCount(); k += 7) {
        const Vec3 c = s.point(hexCentre(s.grid, s.col[k], s.row[k]), 0);
        expectSameHit(grid, tree, {c.x, c.y, b.max.z + 1}, {0, 0, -1}, -1, INFINITY, "down");
        expectSameHit(grid, tree, {c.x, c.y, b.min.z - 1}, {0, 0, 1}, -1, INFINITY, "up");
    }
    for (uint32_t t = 0; t < m.triangles.size(); t += 13) {
        const auto& q = m.triangles[t];
        const Vec3 n = cross(sub(m.positions[q[1]], m.positions[q[0]]), sub(m.positions[q[2]], m.positions[q[0]]));
        expectSameHit(grid, tree, vtest::centroid(m, t), {-n.x, -n.y, -n.z}, t, INFINITY, "inward");
    }
    const auto got = vtest::visitedPairs(grid);
    EXPECT_EQ(std::adjacent_find(got.begin(), got.end()), got.end()) << "a pair was visited twice";
    const auto touching = vtest::visitedPairs(
        tree, [&](uint32_t a, uint32_t c) { return CGAL::do_intersect(cgalTriangle(m, a), cgalTriangle(m, c)); });
    for (const auto& pair : touching)
        EXPECT_TRUE(std::binary_search(got.begin(), got.end(), pair)) << pair.first << ", " << pair.second;
    EXPECT_GT(touching.size(), m.triangles.size());
}

// Two triangles that meet only at a point where four columns meet, each in
// the columns on its own side of it.
TEST(ColumnGrid, APairMeetingOnlyAtAColumnCornerIsACandidate) {
    const vtest::Model model = vtest::smallModel(Bottom::Flat);
    Mesh m = model.mesh;
    const ColumnGrid probe(m);
    ASSERT_GT(probe.columns(), 2);
    ASSERT_GT(probe.rows(), 2);
    const Vec3 corner = probe.columnCorner(probe.columns() / 2, probe.rows() / 2);
    const double z = meshBounds(m).max.z + 3;
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.push_back({corner.x, corner.y, z});
    m.positions.push_back({corner.x - 0.3, corner.y - 0.1, z});
    m.positions.push_back({corner.x - 0.1, corner.y - 0.3, z});
    m.positions.push_back({corner.x, corner.y, z});  // the same point, another vertex
    m.positions.push_back({corner.x + 0.3, corner.y + 0.1, z + 0.2});
    m.positions.push_back({corner.x + 0.1, corner.y + 0.3, z - 0.2});
    m.triangles.push_back({base, base + 1, base + 2});
    m.triangles.push_back({base + 3, base + 4, base + 5});
    const ColumnGrid grid(m);
    const uint32_t a = uint32_t(m.triangles.size() - 2), b = a + 1;
    bool found = false;
    grid.forEachOverlappingPair([&](unsigned, uint32_t p, uint32_t q) { found = found || (std::min(p, q) == a && std::max(p, q) == b); }, 1);
    EXPECT_TRUE(found);
}

// A corner of one triangle resting on an edge of another exactly where four
// columns meet, each triangle on its own side of the column lines but for
// that point: the edge's crossings of those lines are rounded, and the two
// must still share a column. Over every interior column corner, with edges of
// random slopes.
TEST(ColumnGrid, ACornerOnAnEdgeAtAColumnCornerIsACandidate) {
    const vtest::Model model = vtest::smallModel(Bottom::Flat);
    const ColumnGrid probe(model.mesh);
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> slope(0.2, 5.0), len(0.05, 0.4);
    const double z = meshBounds(model.mesh).max.z + 3;
    size_t tried = 0;
    for (int32_t c = 1; c < probe.columns(); ++c)
        for (int32_t r = 1; r < probe.rows(); ++r)
            for (int trial = 0; trial < 2; ++trial) {
            Mesh m = model.mesh;
            const Vec3 p = probe.columnCorner(c, r);
            const uint32_t base = uint32_t(m.positions.size());
            // A: a corner at p, the rest south-west of it.
            m.positions.push_back({p.x, p.y, z});
            m.positions.push_back({p.x - len(rng), p.y - len(rng) * 0.3, z});
            m.positions.push_back({p.x - len(rng) * 0.3, p.y - len(rng), z});
            // B: an edge through p falling to the south-east, its third corner north-east.
            const double k = slope(rng), u = len(rng), v = len(rng);
            m.positions.push_back({p.x - u, p.y + k * u, z});
            m.positions.push_back({p.x + v, p.y - k * v, z});
            m.positions.push_back({p.x + 0.3, p.y + 0.3, z});
            m.triangles.push_back({base, base + 1, base + 2});
            m.triangles.push_back({base + 3, base + 4, base + 5});
            // The same column lines as the probe's: the model's bounds hold the new points.
            const ColumnGrid grid(m);
            if (grid.columnCorner(c, r) != p) continue;
            ++tried;
            const uint32_t a = uint32_t(m.triangles.size() - 2), b = a + 1;
            bool found = false;
            grid.forEachOverlappingPair(
                [&](unsigned, uint32_t x, uint32_t y) { found = found || (std::min(x, y) == a && std::max(x, y) == b); }, 1);
            EXPECT_TRUE(found) << "column corner (" << c << ", " << r << ")";
            }
    EXPECT_GT(tried, 40u);
}

}  // namespace
}  // namespace tsf
