// The self-intersection test decides the pairs of triangles that share a
// vertex index fan by fan (verify/detail/vertex_fans.h): a fan its exact
// certificate clears has no pair tested, any other has each pair decided.
// Here the verdicts are held against two references that know nothing of
// fans: CGAL's PMP::self_intersections on a Surface_mesh, and every pair of
// triangles intersected with the exact kernel's constructions and compared
// with what the two share by index. The defects are the ones that look like
// fans: a vertex pushed through its own fan, a fan folded along an edge, two
// triangles of one fan crossing away from their vertex, coplanar triangles
// of one fan overlapping; and clean models must stay clean.
#include <gtest/gtest.h>

#include <random>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include "tests/support/cgal_self_intersections.h"
#include "tests/verify/verify_test_support.h"
#include "verify/detail/vertex_fans.h"
#include "verify/mesh_topology.h"
#include "verify/solid_checks.h"

namespace tsf {
namespace {

using Pairs = std::vector<std::pair<uint32_t, uint32_t>>;

using test::cgalPairs;

size_t sharedCount(const Mesh& m, uint32_t a, uint32_t b) {
    size_t n = 0;
    for (uint32_t x : m.triangles[a])
        for (uint32_t y : m.triangles[b]) n += x == y;
    return n;
}

// Every pair, with exact constructions: triangles that share nothing
// intersect if they meet at all; sharing a vertex, if their intersection is
// more than that point; sharing an edge, if it is more than that segment.
Pairs exactAllPairs(const Mesh& m) {
    using K = CGAL::Exact_predicates_exact_constructions_kernel;
    std::vector<K::Point_3> pts;
    for (const Vec3& p : m.positions) pts.emplace_back(p.x, p.y, p.z);
    std::vector<K::Triangle_3> tri;
    std::vector<CGAL::Bbox_3> box;
    for (const auto& t : m.triangles) {
        tri.emplace_back(pts[t[0]], pts[t[1]], pts[t[2]]);
        box.push_back(tri.back().bbox());
    }
    Pairs out;
    for (uint32_t a = 0; a < tri.size(); ++a)
        for (uint32_t b = a + 1; b < tri.size(); ++b) {
            if (!CGAL::do_overlap(box[a], box[b])) continue;  // double boxes of double points: exact
            const size_t shared = sharedCount(m, a, b);
            bool meet = false;
            if (shared == 0) {
                meet = CGAL::do_intersect(tri[a], tri[b]);
            } else {
                const auto x = CGAL::intersection(tri[a], tri[b]);
                EXPECT_TRUE(bool(x)) << "triangles " << a << ", " << b << " share a corner";
                if (x) {
                    if (boost::get<K::Point_3>(&*x)) meet = false;            // the shared vertex
                    else if (boost::get<K::Segment_3>(&*x)) meet = shared == 1;  // the shared edge, or more than the vertex
                    else meet = true;                                          // an area
                }
            }
            if (meet) out.emplace_back(a, b);
        }
    return out;
}

// The pairs checkSolid reports (both kernels: the exact one decides the fans'
// fallback pairs with its own predicates).
Pairs solidPairs(const Mesh& m, bool exact) {
    SolidOptions o;
    o.exact = exact;
    o.max_offenders = 1000000;
    const SolidResult r = checkSolid(m, o);
    Pairs got;
    for (const Check& c : r.checks)
        if (c.id == "self_intersections") {
            EXPECT_EQ(c.count, int64_t(c.worst.size()));
            for (const Offender& off : c.worst) {
                unsigned a = 0, b = 0;
                EXPECT_EQ(std::sscanf(off.detail.c_str(), "triangles %u and %u", &a, &b), 2) << off.detail;
                got.emplace_back(a, b);
            }
        }
    return got;
}

void expectReferenceVerdicts(const Mesh& m, const std::string& what, bool all_pairs = true) {
    const Pairs expected = cgalPairs(m);
    if (all_pairs) EXPECT_EQ(exactAllPairs(m), expected) << what << ": the two references disagree";
    EXPECT_EQ(solidPairs(m, false), expected) << what;
    EXPECT_EQ(solidPairs(m, true), expected) << what << " (exact)";
}

// The triangles around v (usable ones), as the self-intersection test sees them.
std::vector<detail::FanCorner> fanOf(const Mesh& m, const VertexCorners& at, uint32_t v) {
    std::vector<detail::FanCorner> fan;
    for (uint32_t e = at.start[v]; e < at.start[v + 1]; ++e) {
        const uint32_t t = at.list[e] / 3, i = at.list[e] % 3;
        fan.push_back({t, m.triangles[t][(i + 1) % 3], m.triangles[t][(i + 2) % 3]});
    }
    return fan;
}

bool cleared(const Mesh& m, const VertexCorners& at, uint32_t v) {
    std::vector<detail::FanCorner> fan = fanOf(m, at, v);
    return detail::orderFan(fan) && detail::fanMeetsOnlyAlongItsEdges(m.positions, v, fan);
}

// A vertex above the bottom whose fan (in cycle order) has two triangles
// in a row lying in its plane of z (a top's corner), and where the first
// of them starts: the fan is rotated to start there.
uint32_t topCorner(const Mesh& m, const VertexCorners& at, std::vector<detail::FanCorner>& fan) {
    const double bottom = meshBounds(m).min.z;
    auto flat = [&](const detail::FanCorner& c, uint32_t v) {
        return m.positions[c.next].z == m.positions[v].z && m.positions[c.prev].z == m.positions[v].z;
    };
    for (uint32_t v = 0; v < m.positions.size(); ++v) {
        if (m.positions[v].z == bottom) continue;
        fan = fanOf(m, at, v);
        if (!detail::orderFan(fan)) continue;
        for (size_t i = 0; i < fan.size(); ++i)
            if (flat(fan[i], v) && flat(fan[(i + 1) % fan.size()], v)) {
                std::rotate(fan.begin(), fan.begin() + long(i), fan.end());
                return v;
            }
    }
    ADD_FAILURE() << "no top corner with two top triangles";
    return 0;
}

bool coplanar(const Mesh& m, uint32_t a, uint32_t b) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    auto p = [&](uint32_t v) { return K::Point_3(m.positions[v].x, m.positions[v].y, m.positions[v].z); };
    const auto& ta = m.triangles[a];
    for (uint32_t w : m.triangles[b])
        if (!CGAL::coplanar(p(ta[0]), p(ta[1]), p(ta[2]), p(w))) return false;
    return true;
}

TEST(VertexFans, CleanModelsStayCleanAndMostFansAreClearedWhole) {
    for (const Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        const vtest::Model model = vtest::smallModel(bottom);
        const Mesh& m = model.mesh;
        expectReferenceVerdicts(m, bottom == Bottom::Flat ? "flat bottom" : "mirrored bottom");
        EXPECT_TRUE(cgalPairs(m).empty());
        // The certificate is what makes the test fast: it must clear the
        // fans of a clean model, not leave them to the pairs.
        const VertexCorners at = cornersByVertex(m);
        size_t clear = 0;
        for (uint32_t v = 0; v < m.positions.size(); ++v) clear += cleared(m, at, v);
        EXPECT_GT(double(clear), 0.9 * double(m.positions.size()));
    }
}

// Soundness of the certificate itself: on every defect below, no fan it
// clears holds a pair either reference finds.
void expectNoClearedFanIntersects(const Mesh& m, const Pairs& reference, const std::string& what) {
    const VertexCorners at = cornersByVertex(m);
    for (const auto& [a, b] : reference)
        for (uint32_t x : m.triangles[a])
            for (uint32_t y : m.triangles[b])
                if (x == y) EXPECT_FALSE(cleared(m, at, x)) << what << ": fan of " << x << " cleared, yet "
                                                             << a << " and " << b << " intersect";
}

TEST(VertexFans, AVertexPushedThroughItsOwnFan) {
    const vtest::Model model = vtest::smallModel(Bottom::Flat);
    const VertexCorners at = cornersByVertex(model.mesh);
    std::vector<detail::FanCorner> fan;
    const uint32_t v = topCorner(model.mesh, at, fan);
    // Within its top, across the far side of a top triangle of its fan (the
    // fan folds over itself and the rest of the top, coplanar), and down
    // through the bottom (the fan crosses the base).
    const Vec3 &pv = model.mesh.positions[v], &a = model.mesh.positions[fan[0].next],
               &b = model.mesh.positions[fan[0].prev];
    const Vec3 across{2 * ((a.x + b.x) / 2 - pv.x), 2 * ((a.y + b.y) / 2 - pv.y), 0};
    for (const Vec3 move : {across, Vec3{0.003, 0.002, -(pv.z - meshBounds(model.mesh).min.z + 1.0)}}) {
        Mesh m = model.mesh;
        Vec3& p = m.positions[v];
        p = {p.x + move.x, p.y + move.y, p.z + move.z};
        const Pairs expected = cgalPairs(m);
        EXPECT_FALSE(expected.empty());
        size_t within_fan = 0;
        for (const auto& [x, y] : expected) within_fan += sharedCount(m, x, y) > 0;
        if (move.z == 0) EXPECT_GT(within_fan, 0u) << "the fan overlaps itself";
        expectReferenceVerdicts(m, move.z == 0 ? "pushed across its top" : "pushed through the bottom");
        expectNoClearedFanIntersects(m, expected, "pushed");
    }
}

TEST(VertexFans, AFanFoldedAlongAnEdge) {
    const vtest::Model model = vtest::smallModel(Bottom::Flat);
    const VertexCorners at = cornersByVertex(model.mesh);
    std::vector<detail::FanCorner> fan;
    const uint32_t v = topCorner(model.mesh, at, fan);
    // Two top triangles of the fan sharing the edge v-u: the far corner of
    // the second moved into the first, so the second folds onto it.
    const detail::FanCorner first = fan[0], second = fan[1];
    ASSERT_EQ(second.next, first.prev);
    Mesh m = model.mesh;
    const Vec3 &pv = m.positions[v], &pu = m.positions[first.prev], &pc = m.positions[first.next];
    m.positions[second.prev] = {(pv.x + pu.x + 2 * pc.x) / 4, (pv.y + pu.y + 2 * pc.y) / 4, pv.z};
    const Pairs expected = cgalPairs(m);
    const std::pair<uint32_t, uint32_t> folded{std::min(first.t, second.t), std::max(first.t, second.t)};
    EXPECT_NE(std::find(expected.begin(), expected.end(), folded), expected.end()) << "the folded pair overlaps";
    expectReferenceVerdicts(m, "a folded fan");
    expectNoClearedFanIntersects(m, expected, "folded");
}

// Link vertices moved at random near their fan's vertex, exactly into
// planes of the model or off them: among the defects, triangles of one fan
// crossing away from their vertex (not coplanar) and coplanar ones
// overlapping, each sharing only that vertex.
TEST(VertexFans, TrianglesOfOneFanMeetingAwayFromTheirVertex) {
    for (const Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        const vtest::Model model = vtest::smallModel(bottom);
        const VertexCorners at = cornersByVertex(model.mesh);
        const double pitch = model.scene.pitch_mm;
        std::mt19937 rng(bottom == Bottom::Flat ? 5 : 6);
        std::uniform_int_distribution<uint32_t> pick(0, uint32_t(model.mesh.positions.size() - 1));
        std::uniform_real_distribution<double> move(-pitch, pitch);
        size_t crossing = 0, overlapping = 0;
        for (int round = 0; round < 40; ++round) {
            Mesh m = model.mesh;
            const uint32_t v = pick(rng);
            const std::vector<detail::FanCorner> fan = fanOf(m, at, v);
            if (fan.empty()) continue;
            const uint32_t w = fan[std::uniform_int_distribution<size_t>(0, fan.size() - 1)(rng)].next;
            const Vec3 pv = m.positions[v];
            Vec3& pw = m.positions[w];
            switch (round % 3) {
                case 0: pw = {pv.x + move(rng), pv.y + move(rng), pv.z + move(rng)}; break;  // anywhere near v
                case 1: pw = {pv.x + move(rng), pv.y + move(rng), pv.z}; break;              // in v's plane of z
                default: pw = {pv.x + 0.5 * move(rng), pv.y + 0.5 * move(rng), pw.z}; break;  // sideways at its height
            }
            const Pairs expected = cgalPairs(m);
            for (const auto& [a, b] : expected)
                if (sharedCount(m, a, b) == 1) (coplanar(m, a, b) ? overlapping : crossing) += 1;
            expectReferenceVerdicts(m, "round " + std::to_string(round), round < 12);
            expectNoClearedFanIntersects(m, expected, "round " + std::to_string(round));
        }
        // Not vacuous: both kinds of a fan's pairs that meet beyond their vertex occur.
        EXPECT_GT(crossing, 0u);
        EXPECT_GT(overlapping, 0u);
    }
}

// Two triangles that share only a vertex and cross elsewhere: an
// octahedron whose ring vertex is pulled past the opposite one, so that
// triangles of the apexes' fans pass through triangles sharing only the apex.
TEST(VertexFans, TwoTrianglesSharingOneVertexCrossElsewhere) {
    Mesh m;
    // The ring 0-3 counter-clockwise seen from above, apexes 4 (top) and 5.
    m.positions = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    for (uint32_t i = 0; i < 4; ++i) {
        const uint32_t j = (i + 1) % 4;
        m.triangles.push_back({i, j, 4});
        m.triangles.push_back({j, i, 5});
    }
    ASSERT_TRUE(analyzeTopology(m).isClosedOrientedManifold());
    expectReferenceVerdicts(m, "an octahedron");
    EXPECT_TRUE(cgalPairs(m).empty());
    // Ring vertex 0 moved so that the edge 1-0 passes through (-0.3, -0.3,
    // 0.4), then (-0.2, -0.5, 0.3), inside the triangle 2-3-4 (the plane
    // -x - y + z = 1): triangles 0-1-4 and 2-3-4 share only the apex 4 and
    // cross there. Last, onto vertex 2's position (a contact, another index).
    for (const Vec3 pulled : {Vec3{-0.6, -1.6, 0.8}, Vec3{-0.4, -2.0, 0.6}, Vec3{-1.0, 0.0, 0.0}}) {
        Mesh d = m;
        d.positions[0] = pulled;
        const Pairs expected = cgalPairs(d);
        size_t crossing = 0;
        for (const auto& [a, b] : expected) crossing += sharedCount(d, a, b) == 1 && !coplanar(d, a, b);
        if (pulled.y < -1) EXPECT_GT(crossing, 0u) << "pulled through the opposite face";
        expectReferenceVerdicts(d, "ring vertex at " + std::to_string(pulled.x));
        expectNoClearedFanIntersects(d, expected, "octahedron");
    }
}

}  // namespace
}  // namespace tsf
