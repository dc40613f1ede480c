// TriangleBvh: watertight at shared edges and vertices, and the same first hit
// as CGAL's AABB tree for random rays.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "tests/verify/verify_test_support.h"
#include "verify/triangle_bvh.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {

TEST(TriangleBvh, VerticalRaysThroughEveryLatticePointHitTheTop) {
    // Hex centres lie on the diagonals of the triangulated tops; corners are
    // shared by up to a dozen triangles. No ray may slip through.
    const vtest::Model m = vtest::smallModel(Bottom::Mirrored);
    const Scene& s = m.scene;
    const TriangleBvh caster(m.mesh);
    const double above = 100;
    size_t rays = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        const std::vector<Vec3> pts = vtest::cellCentreAndCorners(s, k);
        for (const Vec3& p : pts) {
            const auto down = caster.firstHit({p.x, p.y, above}, {0, 0, -1});
            const auto up = caster.firstHit({p.x, p.y, -above}, {0, 0, 1});
            ASSERT_TRUE(down && up) << "ray at (" << p.x << ", " << p.y << ") missed";
            ++rays;
            if (&p == &pts[0]) {  // the centre
                EXPECT_DOUBLE_EQ(down->point_mm.z, s.zMm(s.top[k]));
                EXPECT_DOUBLE_EQ(up->point_mm.z, s.zMm(s.bottom[k]));
                EXPECT_DOUBLE_EQ(down->distance_mm, above - s.zMm(s.top[k]));
            }
        }
    }
    EXPECT_EQ(rays, 7 * s.keptCount());
}

TEST(TriangleBvh, SameFirstHitAsCgalAabbTree) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Tri = K::Triangle_3;
    using Prim = CGAL::AABB_triangle_primitive<K, std::vector<Tri>::const_iterator>;
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    std::vector<Tri> tris;
    for (const auto& t : m.mesh.triangles) {
        const Vec3 &a = m.mesh.positions[t[0]], &b = m.mesh.positions[t[1]], &c = m.mesh.positions[t[2]];
        tris.emplace_back(K::Point_3(a.x, a.y, a.z), K::Point_3(b.x, b.y, b.z), K::Point_3(c.x, c.y, c.z));
    }
    CGAL::AABB_tree<CGAL::AABB_traits<K, Prim>> tree(tris.cbegin(), tris.cend());
    const TriangleBvh caster(m.mesh);
    const Bounds b = meshBounds(m.mesh);

    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> ux(b.min.x - 5, b.max.x + 5), uy(b.min.y - 5, b.max.y + 5),
        uz(b.min.z - 5, b.max.z + 5), ud(-1, 1);
    int hits = 0;
    for (int i = 0; i < 3000; ++i) {
        const Vec3 o{ux(rng), uy(rng), uz(rng)};
        const Vec3 d{ud(rng), ud(rng), ud(rng)};
        const K::Ray_3 ray(K::Point_3(o.x, o.y, o.z), K::Vector_3(d.x, d.y, d.z));
        const auto expected = tree.first_intersection(ray);
        const auto got = caster.firstHit(o, d);
        ASSERT_EQ(bool(expected), bool(got)) << "ray " << i;
        if (!got) continue;
        ++hits;
        const K::Point_3* p = boost::get<K::Point_3>(&expected->first);
        ASSERT_NE(p, nullptr);
        EXPECT_LT(vtest::distance(got->point_mm, {p->x(), p->y(), p->z()}), 1e-9) << "ray " << i;
    }
    EXPECT_GT(hits, 500);  // the test is not vacuous
}

TEST(TriangleBvh, SkipAndMaxDistance) {
    const Mesh m = vtest::box({0, 0, 0}, {1, 1, 1});
    const TriangleBvh caster(m);
    // From the middle of the bottom face (triangles 0 and 1) straight up.
    const auto hit = caster.firstHit({0.25, 0.5, 0}, {0, 0, 1});
    ASSERT_TRUE(hit);
    EXPECT_EQ(hit->distance_mm, 0.0);  // the bottom face itself, at the origin
    const uint32_t bottom = hit->triangle;
    EXPECT_LT(bottom, 2u);
    const auto through = caster.firstHit({0.25, 0.5, 0}, {0, 0, 1}, bottom);
    ASSERT_TRUE(through);
    EXPECT_DOUBLE_EQ(through->distance_mm, 1.0);
    EXPECT_TRUE(through->triangle == 2 || through->triangle == 3);  // the top
    EXPECT_FALSE(caster.firstHit({0.25, 0.5, 0}, {0, 0, 1}, bottom, 0.5));
    EXPECT_TRUE(caster.firstHit({0.25, 0.5, 0}, {0, 0, 1}, bottom, 1.0));  // a hit at the limit counts
    // Direction length does not change distances.
    EXPECT_DOUBLE_EQ(caster.firstHit({0.25, 0.5, -2}, {0, 0, 7})->distance_mm, 2.0);
}

TEST(TriangleBvh, DegenerateInputsGiveNoHit) {
    const Mesh m = vtest::box({0, 0, 0}, {1, 1, 1});
    const TriangleBvh caster(m);
    EXPECT_FALSE(caster.firstHit({0.5, 0.5, 5}, {0, 0, 0}));
    EXPECT_FALSE(caster.firstHit({0.5, 0.5, 5}, {0, 0, NAN}));
    EXPECT_FALSE(caster.firstHit({0.5, 0.5, 5}, {0, 0, 1}));  // pointing away
    const Mesh nothing;
    const TriangleBvh empty(nothing);
    EXPECT_EQ(empty.triangleCount(), 0u);
    EXPECT_FALSE(empty.firstHit({0, 0, 0}, {1, 0, 0}));
    Mesh bad = m;
    bad.triangles.push_back({0, 1, 100});
    bad.positions[7].z = INFINITY;  // used by 4 triangles of the box
    const TriangleBvh partial(bad);
    EXPECT_EQ(partial.triangleCount(), 12u - 4u);
}

// 600 unit-high boxes, box k from x = 2^k to 1.5 * 2^k: the surface-area
// heuristic peels off one box per level here, and an unbounded tree over
// them overflowed the ray traversal's fixed stack (a crash in tsf verify).
Mesh spreadBoxes() {
    Mesh all;
    for (int k = 0; k < 600; ++k) {
        const double x = std::ldexp(1.0, k);
        all = test::append(std::move(all), vtest::box({x, 0, 0}, {1.5 * x, 1, 1}));
    }
    return all;
}

TEST(TriangleBvh, WidelySpreadCoordinatesKeepTheDepthBounded) {
    const Mesh m = spreadBoxes();
    const TriangleBvh bvh(m);
    EXPECT_EQ(bvh.triangleCount(), 600u * 12u);
    EXPECT_LE(bvh.depth(), 64);
    for (int k = 0; k < 600; k += 7) {
        const double x = 1.25 * std::ldexp(1.0, k);
        // Down onto the top of box k; along -x into its far end.
        const auto down = bvh.firstHit({x, 0.5, 5}, {0, 0, -1});
        ASSERT_TRUE(down) << "box " << k;
        EXPECT_EQ(down->point_mm.z, 1.0);
        EXPECT_EQ(down->triangle / 12, uint32_t(k));
        const auto along = bvh.firstHit({std::ldexp(1.0, k + 1) * 0.9, 0.5, 0.5}, {-1, 0, 0});
        ASSERT_TRUE(along) << "box " << k;
        EXPECT_EQ(along->point_mm.x, 1.5 * std::ldexp(1.0, k));
        // (Ericson's dot products square the coordinates: up to 2^1000.)
        if (k >= 500) continue;
        const ClosestPoint c = bvh.closest({x, 0.5, 3});
        EXPECT_EQ(c.point_mm.z, 1.0) << "box " << k;
        EXPECT_EQ(c.triangle / 12, k);
    }
}

TEST(TriangleBvh, VerifierJudgesWidelySpreadBoxesWithoutCrashing) {
    VerifyOptions o;
    o.printability = true;
    const VerifyReport r = verifyModel(spreadBoxes(), nullptr, o);
    EXPECT_EQ(vtest::check(r, "single_piece").count, 599);
    EXPECT_EQ(vtest::check(r, "closed").status, CheckStatus::Pass);
    EXPECT_EQ(vtest::check(r, "self_intersections").status, CheckStatus::Pass);
    EXPECT_EQ(vtest::check(r, "outward_orientation").status, CheckStatus::Pass);
}

TEST(TriangleBvh, OverlappingPairsAreExactlyTheBruteForceOnes) {
    const vtest::Model m = vtest::smallModel(Bottom::Mirrored);
    const TriangleBvh bvh(m.mesh);
    auto boxOf = [&](uint32_t t) {
        Bounds b{{INFINITY, INFINITY, INFINITY}, {-INFINITY, -INFINITY, -INFINITY}};
        for (uint32_t v : m.mesh.triangles[t]) {
            const Vec3& p = m.mesh.positions[v];
            b.min = {std::min(b.min.x, p.x), std::min(b.min.y, p.y), std::min(b.min.z, p.z)};
            b.max = {std::max(b.max.x, p.x), std::max(b.max.y, p.y), std::max(b.max.z, p.z)};
        }
        return b;
    };
    const size_t n = m.mesh.triangles.size();
    std::vector<Bounds> boxes;
    for (uint32_t t = 0; t < n; ++t) boxes.push_back(boxOf(t));
    std::vector<std::pair<uint32_t, uint32_t>> expected;
    for (uint32_t a = 0; a < n; ++a)
        for (uint32_t b = a + 1; b < n; ++b) {
            const Bounds &p = boxes[a], &q = boxes[b];
            if (p.min.x <= q.max.x && q.min.x <= p.max.x && p.min.y <= q.max.y && q.min.y <= p.max.y &&
                p.min.z <= q.max.z && q.min.z <= p.max.z)
                expected.emplace_back(a, b);
        }
    const auto got = vtest::visitedPairs(bvh);
    EXPECT_EQ(std::adjacent_find(got.begin(), got.end()), got.end()) << "a pair was visited twice";
    EXPECT_EQ(got, expected);
    EXPECT_GT(expected.size(), n);  // neighbours touch: the test is not vacuous
}

}  // namespace
}  // namespace tsf
