// The two measuring tools behind the sampled Hausdorff bound: triangle
// samples that cover a triangle to a known radius, and the closest point on a
// mesh, both checked against brute force.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <array>
#include <random>

#include "tests/verify/verify_test_support.h"
#include "verify/triangle_bvh.h"
#include "verify/triangle_samples.h"

namespace tsf {
namespace {

Vec3 at(const Vec3& a, const Vec3& b, const Vec3& c, double u, double v) {
    // Barycentric (1 - u - v, u, v).
    return {a.x + u * (b.x - a.x) + v * (c.x - a.x), a.y + u * (b.y - a.y) + v * (c.y - a.y),
            a.z + u * (b.z - a.z) + v * (c.z - a.z)};
}

// The largest distance from a random point of the triangle (and from its
// corners and edge midpoints) to the nearest sample.
double coveringRadius(const Vec3& a, const Vec3& b, const Vec3& c, const std::vector<Vec3>& samples,
                      std::mt19937& rng) {
    std::uniform_real_distribution<double> u01(0.0, 1.0);
    double worst = 0;
    auto nearest = [&](const Vec3& p) {
        double best = std::numeric_limits<double>::infinity();
        for (const Vec3& s : samples) best = std::min(best, vtest::distance(p, s));
        return best;
    };
    for (const auto& [u, v] : std::vector<std::pair<double, double>>{{0, 0}, {1, 0}, {0, 1}, {0.5, 0}, {0.5, 0.5}, {0, 0.5}})
        worst = std::max(worst, nearest(at(a, b, c, u, v)));
    for (int i = 0; i < 3000; ++i) {
        double u = u01(rng), v = u01(rng);
        if (u + v > 1) {
            u = 1 - u;
            v = 1 - v;
        }
        worst = std::max(worst, nearest(at(a, b, c, u, v)));
    }
    return worst;
}

TEST(TriangleSamples, EveryPointIsWithinTheRadiusOfASample) {
    std::mt19937 rng(7);
    struct Case {
        const char* name;
        Vec3 a, b, c;
        double r;
    };
    const std::vector<Case> cases = {
        {"equilateral", {0, 0, 0}, {1, 0, 0}, {0.5, std::sqrt(3.0) / 2, 0}, 0.1},
        {"right angle", {0, 0, 0}, {2, 0, 0}, {0, 1, 0}, 0.07},
        {"obtuse", {0, 0, 0}, {3, 0, 0}, {0.3, 0.4, 0}, 0.05},
        {"very obtuse", {0, 0, 0}, {0.3, 0.4, 0}, {4, 0.1, 0}, 0.05},
        {"sliver", {0, 0, 0}, {150, 0, 0}, {75, 0.01, 0}, 0.2},
        {"tilted", {1, 2, 3}, {4, -1, 5}, {0, 0, 7}, 0.3},
        {"radius larger than the triangle", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, 5.0},
    };
    for (const Case& k : cases) {
        // Each corner order, so that the longest edge is not always a-b.
        const std::array<Vec3, 3> v{k.a, k.b, k.c};
        for (int rot = 0; rot < 3; ++rot) {
            const Vec3 &a = v[size_t(rot)], &b = v[size_t((rot + 1) % 3)], &c = v[size_t((rot + 2) % 3)];
            std::vector<Vec3> s;
            sampleTriangle(a, b, c, k.r, s);
            EXPECT_EQ(s.size(), triangleSampleCount(a, b, c, k.r)) << k.name << " rotation " << rot;
            EXPECT_LE(coveringRadius(a, b, c, s, rng), k.r) << k.name << " rotation " << rot;
        }
    }
}

TEST(TriangleSamples, CornersLeftOutAreTheOnlyPointsMissing) {
    // A caller measuring each vertex once leaves the corners out; with them
    // added back, the covering radius holds again.
    std::mt19937 rng(5);
    const Vec3 a{0, 0, 0}, b{3, 1, 0}, c{1, 2, 1};
    for (double r : {0.1, 0.7, 10.0}) {
        std::vector<Vec3> all, inner;
        sampleTriangle(a, b, c, r, all);
        sampleTriangle(a, b, c, r, inner, Corners::Omit);
        EXPECT_EQ(inner.size(), all.size() - 3) << r;
        EXPECT_EQ(inner.size(), triangleSampleCount(a, b, c, r, Corners::Omit)) << r;
        for (const Vec3& p : inner)
            for (const Vec3& corner : {a, b, c}) EXPECT_GT(vtest::distance(p, corner), 0.0);
        inner.insert(inner.end(), {a, b, c});
        EXPECT_LE(coveringRadius(a, b, c, inner, rng), r) << r;
    }
    // At a radius as long as the longest edge (a-b; a hair longer, against
    // rounding), the corners are all there is.
    EXPECT_EQ(triangleSampleCount(a, b, c, 1.000001 * vtest::distance(a, b), Corners::Omit), 0u);
}

TEST(TriangleSamples, SliverCostsItsLengthNotItsLengthSquared) {
    // 150 mm long, 0.01 mm high, radius 0.1 mm: one row of ~1500 points and
    // an apex, not (150 / 0.1)^2.
    const size_t n = triangleSampleCount({0, 0, 0}, {150, 0, 0}, {75, 0.01, 0}, 0.1);
    EXPECT_GE(n, 1500u);
    EXPECT_LE(n, 1510u);
}

TEST(TriangleSamples, ZeroAreaTriangleIsSampledAlongItsLongestEdge) {
    std::mt19937 rng(3);
    const Vec3 a{0, 0, 0}, b{10, 0, 0}, c{4, 0, 0};  // c between a and b
    std::vector<Vec3> s;
    sampleTriangle(a, c, b, 0.5, s);
    EXPECT_EQ(s.size(), 21u);  // 0, 0.5, ..., 10
    EXPECT_LE(coveringRadius(a, c, b, s, rng), 0.5);
    std::vector<Vec3> one;
    sampleTriangle(a, a, a, 0.5, one);
    EXPECT_EQ(one.size(), 1u);
}

// Brute force, sharing no code with the tree: per triangle, the best node of
// a fine barycentric grid, refined by a pattern search (the distance to a
// point is convex over a triangle, so the search ends at its minimum).
double bruteDistance(const Mesh& m, const Vec3& p) {
    double best = std::numeric_limits<double>::infinity();
    for (const auto& t : m.triangles) {
        const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
        // Minimise over a fine barycentric grid, then refine around the best node.
        double local = std::numeric_limits<double>::infinity();
        double bu = 0, bv = 0;
        const int n = 40;
        for (int i = 0; i <= n; ++i)
            for (int j = 0; i + j <= n; ++j) {
                const double d = vtest::distance(p, at(a, b, c, double(i) / n, double(j) / n));
                if (d < local) {
                    local = d;
                    bu = double(i) / n;
                    bv = double(j) / n;
                }
            }
        for (double h = 1.0 / n; h > 1e-9; h /= 2) {
            bool moved = true;
            while (moved) {
                moved = false;
                for (const auto& [du, dv] : std::vector<std::pair<double, double>>{{h, 0}, {-h, 0}, {0, h}, {0, -h}, {h, -h}, {-h, h}}) {
                    const double u = bu + du, v = bv + dv;
                    if (u < 0 || v < 0 || u + v > 1) continue;
                    const double d = vtest::distance(p, at(a, b, c, u, v));
                    if (d < local) {
                        local = d;
                        bu = u;
                        bv = v;
                        moved = true;
                    }
                }
            }
        }
        best = std::min(best, local);
    }
    return best;
}

TEST(TriangleBvh, MatchesBruteForceOnASmallModel) {
    const vtest::Model m = vtest::smallModel(Bottom::Mirrored);
    const TriangleBvh tree(m.mesh);
    EXPECT_EQ(tree.triangleCount(), m.mesh.triangles.size());
    const Bounds b = meshBounds(m.mesh);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> ux(b.min.x - 3, b.max.x + 3), uy(b.min.y - 3, b.max.y + 3),
        uz(b.min.z - 3, b.max.z + 3);
    int64_t hint = -1;
    for (int i = 0; i < 60; ++i) {
        const Vec3 p{ux(rng), uy(rng), uz(rng)};
        const ClosestPoint c = tree.closest(p, hint);
        ASSERT_GE(c.triangle, 0);
        hint = c.triangle;
        const double brute = bruteDistance(m.mesh, p);
        EXPECT_NEAR(c.distance_mm, brute, 1e-6) << "at " << p.x << ", " << p.y << ", " << p.z;
        EXPECT_NEAR(vtest::distance(p, c.point_mm), c.distance_mm, 1e-12);
        // The hint does not change the answer.
        EXPECT_NEAR(tree.closest(p).distance_mm, c.distance_mm, 1e-12);
    }
}

TEST(TriangleBvh, EnoughStopsEarlyWithAnUpperBound) {
    const Mesh box = vtest::box({0, 0, 0}, {10, 10, 10});
    const TriangleBvh tree(box);
    const Vec3 p{5, 5, 11};  // 1 mm above the top
    EXPECT_NEAR(tree.closest(p).distance_mm, 1.0, 1e-12);
    // With enough = 20 any triangle within 20 mm will do: at least the true
    // distance, at most 20.
    const ClosestPoint c = tree.closest(p, 0 /* a bottom triangle */, 20.0);
    EXPECT_GE(c.distance_mm, 1.0);
    EXPECT_LE(c.distance_mm, 20.0);
}

TEST(TriangleBvh, EmptyMeshAndBadQueries) {
    const Mesh nothing;
    const TriangleBvh empty(nothing);
    EXPECT_TRUE(std::isinf(empty.closest({0, 0, 0}).distance_mm));
    EXPECT_EQ(empty.closest({0, 0, 0}).triangle, -1);
    const Mesh cube = vtest::box({0, 0, 0}, {1, 1, 1});
    const TriangleBvh box(cube);
    EXPECT_TRUE(std::isinf(box.closest({NAN, 0, 0}).distance_mm));
    EXPECT_NEAR(box.closest({0.5, 0.5, 0.5}).distance_mm, 0.5, 1e-15);  // inside: to the nearest face
}

}  // namespace
}  // namespace tsf
