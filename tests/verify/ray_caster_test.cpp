// RayCaster: watertight at shared edges and vertices, and the same first hit
// as CGAL's AABB tree for random rays.
#include <gtest/gtest.h>

#include <random>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "tests/verify/verify_test_support.h"
#include "verify/ray_caster.h"

namespace tsf {
namespace {

TEST(RayCaster, VerticalRaysThroughEveryLatticePointHitTheTop) {
    // Hex centres lie on the diagonals of the triangulated tops; corners are
    // shared by up to a dozen triangles. No ray may slip through.
    const vtest::Model m = vtest::smallModel(Bottom::Mirrored);
    const Scene& s = m.scene;
    const RayCaster caster(m.mesh);
    const double above = 100;
    size_t rays = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        std::vector<LatticePoint> pts{hexCentre(s.grid, s.col[k], s.row[k])};
        for (int c = 0; c < kHexCorners; ++c) pts.push_back(hexCorner(s.grid, s.col[k], s.row[k], c));
        for (const LatticePoint& lp : pts) {
            const Vec3 p = s.point(lp, 0);
            const auto down = caster.firstHit({p.x, p.y, above}, {0, 0, -1});
            const auto up = caster.firstHit({p.x, p.y, -above}, {0, 0, 1});
            ASSERT_TRUE(down && up) << "ray at (" << p.x << ", " << p.y << ") missed";
            ++rays;
            if (lp == pts[0]) {
                EXPECT_DOUBLE_EQ(down->point_mm.z, s.zMm(s.top[k]));
                EXPECT_DOUBLE_EQ(up->point_mm.z, s.zMm(s.bottom[k]));
                EXPECT_DOUBLE_EQ(down->distance_mm, above - s.zMm(s.top[k]));
            }
        }
    }
    EXPECT_EQ(rays, 7 * s.keptCount());
}

TEST(RayCaster, SameFirstHitAsCgalAabbTree) {
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
    const RayCaster caster(m.mesh);
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

TEST(RayCaster, SkipAndMaxDistance) {
    const Mesh m = vtest::box({0, 0, 0}, {1, 1, 1});
    const RayCaster caster(m);
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

TEST(RayCaster, DegenerateInputsGiveNoHit) {
    const Mesh m = vtest::box({0, 0, 0}, {1, 1, 1});
    const RayCaster caster(m);
    EXPECT_FALSE(caster.firstHit({0.5, 0.5, 5}, {0, 0, 0}));
    EXPECT_FALSE(caster.firstHit({0.5, 0.5, 5}, {0, 0, NAN}));
    EXPECT_FALSE(caster.firstHit({0.5, 0.5, 5}, {0, 0, 1}));  // pointing away
    const RayCaster empty(Mesh{});
    EXPECT_EQ(empty.triangleCount(), 0u);
    EXPECT_FALSE(empty.firstHit({0, 0, 0}, {1, 0, 0}));
    Mesh bad = m;
    bad.triangles.push_back({0, 1, 100});
    bad.positions[7].z = INFINITY;  // used by 4 triangles of the box
    const RayCaster partial(bad);
    EXPECT_EQ(partial.triangleCount(), 12u - 4u);
}

}  // namespace
}  // namespace tsf
