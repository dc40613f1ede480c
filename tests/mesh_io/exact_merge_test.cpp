// Vertices are merged only when exactly equal; nothing is hidden: repeated
// indices are counted, unused vertices noted.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>

#include "gen/mesh_io/exact_vertex_index.h"
#include "gen/mesh_io/exact_weld.h"
#include "gen/mesh_io/obj_reader.h"
#include "gen/mesh_io/off_reader.h"
#include "gen/mesh_io/stl_reader.h"
#include "gen/mesh_io/stl_writer.h"
#include "mesh_io_test_support.h"

namespace tsf {
namespace {

using ::testing::HasSubstr;

// Two triangles sharing the edge (1,0,0)-(0,1,0); in the second one the
// shared corner (1,0,0) is written 1e-9 mm off:
//
//   (0,1,0) 2---------3 (1,1,0)
//           | \       |
//           |   \     |
//           |     \   |
//   (0,0,0) 0---------1 (1,0,0) and 1' = (1.000000001,0,0)
TEST(ExactMerge, VerticesOneNanometreApartStayTwoVertices) {
    const std::string off =
        "OFF\n6 2 0\n"
        "0 0 0\n1 0 0\n0 1 0\n"
        "1.000000001 0 0\n1 1 0\n0 1 0\n"
        "3 0 1 2\n3 3 4 5\n";
    MeshReadReport report;
    const Mesh m = parseOff(off, "gap.off", &report);
    EXPECT_EQ(m.vertexCount(), 5u);  // (0,1,0) merged, (1,0,0) and its neighbour 1e-9 away not
    EXPECT_EQ(report.input_vertices, 6u);
    EXPECT_EQ(report.merged_vertices, 1u);
    EXPECT_EQ(m.triangles[1][2], 2u);  // the exact duplicate of (0,1,0) became vertex 2
    EXPECT_NE(m.triangles[1][0], 1u);

    // The same in ASCII STL, which is parsed as double: still two vertices.
    const std::string stl =
        "solid gap\n"
        "facet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 0 1 0 endloop endfacet\n"
        "facet normal 0 0 1 outer loop vertex 1.000000001 0 0 vertex 1 1 0 vertex 0 1 0 endloop endfacet\n"
        "endsolid gap\n";
    EXPECT_EQ(parseStl(stl, "gap.stl").vertexCount(), 5u);
}

TEST(ExactMerge, NegativeZeroEqualsZero) {
    const Mesh m = parseObj("v 0 0 0\nv -0 -0.0 0\nv 1 0 0\nv 0 1 0\nf 1 3 4\nf 2 3 4\n", "zero.obj");
    EXPECT_EQ(m.vertexCount(), 3u);
    EXPECT_EQ(m.triangles[0], m.triangles[1]);
    EXPECT_FALSE(std::signbit(m.positions[0].x));
}

TEST(ExactMerge, RepeatedIndexTrianglesAreKeptAndCounted) {
    const std::string off =
        "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n9 9 9\n"
        "3 0 1 2\n"
        "3 0 0 2\n"   // repeats 0 in the file
        "3 1 3 2\n";  // 1 and 3 are the same position -> repeats after merging
    MeshReadReport report;
    const Mesh m = parseOff(off, "deg.off", &report);
    EXPECT_EQ(m.triangleCount(), 3u);
    EXPECT_EQ(report.degenerate_index_triangles, 2u);
    EXPECT_EQ(m.vertexCount(), 4u);
    bool noted_degenerate = false, noted_unused = false;
    for (const auto& note : report.notes) {
        noted_degenerate |= note.find("2 triangles use the same vertex more than once (first: triangle 1)") !=
                            std::string::npos;
        noted_unused |= note.find("1 vertices are not used") != std::string::npos;
    }
    EXPECT_TRUE(noted_degenerate);
    EXPECT_TRUE(noted_unused);
}

TEST(ExactVertexIndex, AgreesWithABruteForceSearch) {
    // Many near-duplicates: values differing in the last bit must not merge.
    std::mt19937 rng(3);
    std::vector<Vec3> pool;
    for (int i = 0; i < 300; ++i) {
        const double x = std::uniform_int_distribution<int>(0, 5)(rng) * 0.1;
        pool.push_back({x, std::nextafter(x, 1.0), 0.0});
        pool.push_back({x, x, 0.0});
    }
    mesh_io::ExactVertexIndex index(4);  // starts small: exercises rehashing
    std::vector<Vec3> seen;
    for (const Vec3& p : pool) {
        size_t expected = seen.size();
        for (size_t i = 0; i < seen.size(); ++i) {
            if (seen[i] == p) expected = i;
        }
        if (expected == seen.size()) seen.push_back(p);
        EXPECT_EQ(index.insert(p), expected);
    }
    EXPECT_EQ(index.size(), seen.size());
    EXPECT_EQ(index.size(), 12u);  // 6 values of x, each with 2 distinct y
}

// A batch gives every position the index insert gives it one by one, the
// table growing (rehashing) in the middle of a batch included.
TEST(ExactVertexIndex, ABatchNumbersAsInsertsOneByOne) {
    std::mt19937 rng(5);
    std::vector<Vec3> points;
    for (int i = 0; i < 5000; ++i) {
        const double x = std::uniform_int_distribution<int>(0, 40)(rng) * 0.5;
        const double y = std::uniform_int_distribution<int>(0, 40)(rng) * 0.5;
        points.push_back(i % 7 == 3 ? Vec3{-0.0, y, std::nextafter(x, 100.0)} : Vec3{x, y, 0.0});
    }
    mesh_io::ExactVertexIndex one(4), batch(4);
    std::vector<uint32_t> expected, got(points.size());
    for (const Vec3& p : points) expected.push_back(one.insert(p));
    for (size_t from = 0; from < points.size(); from += 97)
        batch.insertBatch(points.data() + from, std::min<size_t>(97, points.size() - from), got.data() + from);
    EXPECT_EQ(got, expected);
    ASSERT_EQ(batch.size(), one.size());
    for (size_t v = 0; v < one.size(); ++v) EXPECT_TRUE(batch.positions()[v] == one.positions()[v]) << v;
}

// The whole list at once, on any number of threads, numbers every position
// as the index does one by one: near-duplicates one bit apart, -0.0 and
// +0.0, repeats far apart in the list; small lists (one thread, one bucket)
// and large ones (many buckets on several threads).
TEST(WeldExact, NumbersEveryPositionAsTheIndexDoesOneByOne) {
    std::mt19937 rng(11);
    for (const size_t n : {size_t(0), size_t(1), size_t(1000), size_t(70'000), size_t(300'000)}) {
        std::vector<Vec3> points;
        points.reserve(n);
        for (size_t i = 0; i < n; ++i) {
            const double x = std::uniform_int_distribution<int>(-300, 300)(rng) * 0.25;
            const double y = std::uniform_int_distribution<int>(0, 400)(rng) * 0.5;
            switch (std::uniform_int_distribution<int>(0, 5)(rng)) {
                case 0: points.push_back({x, std::nextafter(y, 1e9), 0.0}); break;
                case 1: points.push_back({x == 0 ? -0.0 : x, y, -0.0}); break;
                case 2: if (!points.empty()) { points.push_back(points[std::uniform_int_distribution<size_t>(0, points.size() - 1)(rng)]); break; }
                    [[fallthrough]];
                default: points.push_back({x, y, std::uniform_int_distribution<int>(0, 3)(rng) * 1.5}); break;
            }
        }
        mesh_io::ExactVertexIndex index(4);
        std::vector<uint32_t> expected;
        for (const Vec3& p : points) expected.push_back(index.insert(p));
        for (const unsigned workers : {1u, 2u, 3u, 5u}) {
            const mesh_io::WeldedPositions w = mesh_io::weldExact(points, workers);
            ASSERT_EQ(w.index_of, expected) << n << " positions, " << workers << " threads";
            ASSERT_EQ(w.positions.size(), index.size()) << n;
            for (size_t v = 0; v < w.positions.size(); ++v) {
                // Bit for bit: -0.0 is stored as +0.0 by both.
                EXPECT_EQ(std::signbit(w.positions[v].x), std::signbit(index.positions()[v].x));
                EXPECT_EQ(std::signbit(w.positions[v].z), std::signbit(index.positions()[v].z));
                ASSERT_TRUE(w.positions[v] == index.positions()[v]) << v;
            }
        }
        if (n >= 1000) EXPECT_LT(index.size(), n) << "the list repeats positions";
    }
}

TEST(ExactMerge, TouchingCubesShareCornersOnlyWhenExactlyEqual) {
    // Two cubes touching along a face: exact merging joins the shared corners
    // (which is what the file says), so 12 vertices, not 16; shifted by a
    // float ulp they stay apart.
    Mesh two = test::cube(1.0);
    Mesh second = test::cube(1.0, {1.0, 0.0, 0.0});
    for (auto t : second.triangles) two.triangles.push_back({t[0] + 8, t[1] + 8, t[2] + 8});
    two.positions.insert(two.positions.end(), second.positions.begin(), second.positions.end());
    std::ostringstream touching;
    writeStlBinary(two, touching, "two cubes");
    EXPECT_EQ(parseStl(touching.str(), "touch.stl").vertexCount(), 12u);
    for (size_t i = 8; i < 16; ++i) two.positions[i].x = std::nextafter(float(two.positions[i].x), 10.0f);
    std::ostringstream apart;
    writeStlBinary(two, apart, "two cubes");
    EXPECT_EQ(parseStl(apart.str(), "apart.stl").vertexCount(), 16u);
}

}  // namespace
}  // namespace tsf
