// self_intersections: the tree's broad phase and exact predicates on the
// candidate pairs find exactly the pairs CGAL's PMP::self_intersections finds
// on a Surface_mesh of the same triangles, with both kernels, on models whose
// vertices were moved at random (folds within a top, corners pushed through
// walls, walls through each other).
#include <gtest/gtest.h>

#include <random>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include "tests/support/cgal_self_intersections.h"
#include "tests/verify/verify_test_support.h"
#include "verify/solid_checks.h"

namespace tsf {
namespace {

using test::cgalPairs;

// The pairs checkSolid reports, with both kernels, against CGAL's.
void expectCgalPairs(const Mesh& m, const std::string& what, size_t& total) {
    const auto expected = cgalPairs(m);
    total += expected.size();
    for (bool exact : {false, true}) {
        SolidOptions o;
        o.exact = exact;
        o.max_offenders = 1000000;
        const SolidResult r = checkSolid(m, o);
        const Check* si = nullptr;
        for (const Check& c : r.checks)
            if (c.id == "self_intersections") si = &c;
        ASSERT_NE(si, nullptr);
        EXPECT_EQ(si->count, int64_t(expected.size())) << what << (exact ? " (exact)" : "");
        std::vector<std::pair<uint32_t, uint32_t>> got;
        for (const Offender& o : si->worst) {
            unsigned a = 0, b = 0;
            ASSERT_EQ(std::sscanf(o.detail.c_str(), "triangles %u and %u", &a, &b), 2) << o.detail;
            got.emplace_back(a, b);
        }
        EXPECT_EQ(got, expected) << what << (exact ? " (exact)" : "");
    }
}

// Vertices moved exactly onto another vertex's plane of z, vertical line or
// position: corners resting on tops, edges lying in walls, faces touching
// without crossing. These are the contacts the verifier decides within a
// plane instead of asking CGAL, so they must get CGAL's verdicts.
TEST(SelfIntersections, SamePairsAsCgalWhenCornersLandExactlyOnOtherSurfaces) {
    const vtest::Model model = vtest::smallModel(Bottom::Mirrored);
    std::mt19937 rng(77);
    std::uniform_int_distribution<size_t> pick(0, model.mesh.positions.size() - 1);
    std::uniform_int_distribution<int> how(0, 3);
    size_t total = 0;
    for (int round = 0; round < 40; ++round) {
        Mesh m = model.mesh;
        for (int i = 0; i < 1 + round % 4; ++i) {
            Vec3& p = m.positions[pick(rng)];
            const Vec3 q = model.mesh.positions[pick(rng)];
            switch (how(rng)) {
                case 0: p.z = q.z; break;               // onto another plane of z
                case 1: p.x = q.x, p.y = q.y; break;    // onto another vertical line
                case 2: p = q; break;                   // onto another vertex
                default: p.x = q.x, p.z = q.z; break;   // onto a line in a plane x = const
            }
        }
        expectCgalPairs(m, "round " + std::to_string(round), total);
    }
    EXPECT_GT(total, 40u);  // the moves do make contacts: the test is not vacuous
}

TEST(SelfIntersections, SamePairsAsCgalOnRandomlyDeformedModels) {
    const vtest::Model model = vtest::smallModel(Bottom::Mirrored);
    std::mt19937 rng(2024);
    const double pitch = model.scene.pitch_mm;
    std::uniform_real_distribution<double> move(-pitch, pitch);
    std::uniform_int_distribution<size_t> pick(0, model.mesh.positions.size() - 1);
    size_t total = 0;
    for (int round = 0; round < 12; ++round) {
        Mesh m = model.mesh;
        for (int i = 0; i < 1 + round % 6; ++i) {
            Vec3& p = m.positions[pick(rng)];
            // Odd rounds move within the vertex's plane of z (folds in a top).
            p = {p.x + move(rng), p.y + move(rng), round % 2 ? p.z : p.z + 4 * move(rng)};
        }
        expectCgalPairs(m, "round " + std::to_string(round), total);
    }
    EXPECT_GT(total, 12u);  // the deformations do intersect: the test is not vacuous
}

// Defects made to slip past a broad phase that trusted the terrain's
// structure (walls and tops on a lattice, triangles near their cells): each
// must get CGAL's verdict.
TEST(SelfIntersections, DefectsThatDoNotLookLikeTerrainGetCgalsVerdict) {
    const vtest::Model model = vtest::smallModel(Bottom::Flat);
    const Mesh& base = model.mesh;
    const Bounds b = meshBounds(base);
    size_t total = 0;
    {
        // A far-away triangle pushed through a top: a thin closed spike from
        // well outside the model, lying over many cells, its tip through the
        // middle of the top surface.
        Mesh m = base;
        const Vec3 tip{(b.min.x + b.max.x) / 2 + 0.013, (b.min.y + b.max.y) / 2 + 0.007, b.min.z + 0.2};
        const uint32_t v = uint32_t(m.positions.size());
        m.positions.push_back({b.min.x - 40, b.min.y - 30, b.max.z + 2});
        m.positions.push_back({b.min.x - 40, b.min.y - 29.5, b.max.z + 2.5});
        m.positions.push_back({b.min.x - 39.5, b.min.y - 30, b.max.z + 2.5});
        m.positions.push_back(tip);
        m.triangles.push_back({v, v + 2, v + 1});
        m.triangles.push_back({v, v + 1, v + 3});
        m.triangles.push_back({v + 1, v + 2, v + 3});
        m.triangles.push_back({v + 2, v, v + 3});
        const size_t before = total;
        expectCgalPairs(m, "a spike from afar", total);
        EXPECT_GT(total, before) << "the spike does cross the top";
    }
    {
        // Two closed tetrahedra above the model touching at one point, each
        // on its own side of it.
        Mesh m = base;
        const Vec3 p{(b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2, b.max.z + 3};
        auto tetra = [&](double sx) {
            const uint32_t v = uint32_t(m.positions.size());
            m.positions.push_back(p);
            m.positions.push_back({p.x + sx * 0.4, p.y + sx * 0.1, p.z});
            m.positions.push_back({p.x + sx * 0.1, p.y + sx * 0.4, p.z});
            m.positions.push_back({p.x + sx * 0.2, p.y + sx * 0.2, p.z + 0.3});
            // Outward for sx = 1; a mirror image for sx = -1, wound the other way.
            if (sx > 0) {
                m.triangles.push_back({v, v + 2, v + 1});
                m.triangles.push_back({v, v + 1, v + 3});
                m.triangles.push_back({v + 1, v + 2, v + 3});
                m.triangles.push_back({v + 2, v, v + 3});
            } else {
                m.triangles.push_back({v, v + 1, v + 2});
                m.triangles.push_back({v, v + 3, v + 1});
                m.triangles.push_back({v + 1, v + 3, v + 2});
                m.triangles.push_back({v + 2, v + 3, v});
            }
        };
        tetra(1);
        tetra(-1);
        const size_t before = total;
        expectCgalPairs(m, "two shells meeting at a point", total);
        EXPECT_GT(total, before) << "the shells do touch";
    }
    {
        // Every wall's upper corners tilted by one unit in the last place, in
        // turn toward and away from its cell: no wall is vertical any more.
        for (const double toward : {-1.0, 1.0}) {
            Mesh m = model.mesh;
            const double z_top = b.max.z;
            for (Vec3& p : m.positions)
                if (p.z > 0 && p.z < z_top) p.x = std::nextafter(p.x, toward * INFINITY);
            expectCgalPairs(m, toward > 0 ? "walls tilted east by an ulp" : "walls tilted west by an ulp", total);
        }
    }
}

}  // namespace
}  // namespace tsf
