// The binary STL writer converts blocks of facets on several threads and
// writes them in order through a ring of slots. A mesh of many blocks (each
// slot reused several times) comes out as one facet after another, each
// facet's bytes computed here from its corners alone. Built into the
// sanitizer binaries too (run-sanitizers.sh: ASan + UBSan and ThreadSanitizer).
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/stl_writer.h"

namespace tsf {
namespace {

constexpr size_t kFacetsPerBlock = 16384;  // the writer's block (stl_writer.cpp)

std::string le(float v) {
    const uint32_t u = std::bit_cast<uint32_t>(v);
    std::string out(4, '\0');
    for (int k = 0; k < 4; ++k) out[size_t(k)] = char((u >> (8 * k)) & 0xff);
    return out;
}

// The 50 bytes of a facet: the normal of the float32 corners computed in
// double, then the corners, then a zero attribute.
std::string facetBytes(const Vec3& a, const Vec3& b, const Vec3& c) {
    const float p[3][3] = {{float(a.x), float(a.y), float(a.z)}, {float(b.x), float(b.y), float(b.z)},
                           {float(c.x), float(c.y), float(c.z)}};
    double u[3], v[3];
    for (int k = 0; k < 3; ++k) {
        u[k] = double(p[1][k]) - double(p[0][k]);
        v[k] = double(p[2][k]) - double(p[0][k]);
    }
    const double n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    std::string out;
    for (int k = 0; k < 3; ++k) out += le(length > 0 ? float(n[k] / length) : 0.0f);
    for (const auto& corner : p)
        for (float x : corner) out += le(x);
    return out + std::string(2, '\0');
}

TEST(StlWriterThreads, ManyBlocksComeOutInOrderFacetByFacet) {
    Mesh m;
    const size_t n = 21 * kFacetsPerBlock + 777;  // 22 blocks: every slot of the ring used several times
    for (size_t t = 0; t < n; ++t) {
        const double x = double(t % 1013) * 0.37, y = double(t / 1013) * 0.41, z = double(t % 17) * 0.1;
        const uint32_t first = uint32_t(m.positions.size());
        m.positions.push_back({x, y, z});
        m.positions.push_back({x + 0.3 + double(t % 5) * 0.01, y, z + 0.2});
        m.positions.push_back({x, y + 0.3, z + double(t % 3) * 0.05});
        m.triangles.push_back({first, first + 1, first + 2});
    }
    std::ostringstream out;
    writeStlBinary(m, out, "threads");
    const std::string stl = out.str();
    ASSERT_EQ(stl.size(), 84 + 50 * n);
    uint32_t count = 0;
    std::memcpy(&count, stl.data() + 80, 4);
    EXPECT_EQ(count, n);
    size_t wrong = 0;
    for (size_t t = 0; t < n; ++t) {
        const auto& tri = m.triangles[t];
        if (stl.compare(84 + 50 * t, 50, facetBytes(m.positions[tri[0]], m.positions[tri[1]], m.positions[tri[2]])) != 0 &&
            wrong++ == 0)
            ADD_FAILURE() << "facet " << t << " (block " << t / kFacetsPerBlock << ") is not its own";
    }
    EXPECT_EQ(wrong, 0u);
}

// A stream that fails stops the writer without a hang: the converting
// threads stop once the failure is seen.
TEST(StlWriterThreads, AFailingStreamEndsTheWriteWithoutHanging) {
    Mesh m;
    const size_t n = 9 * kFacetsPerBlock;
    for (size_t t = 0; t < n; ++t) {
        const uint32_t first = uint32_t(m.positions.size());
        m.positions.push_back({double(t), 0, 0});
        m.positions.push_back({double(t) + 1, 0, 0});
        m.positions.push_back({double(t), 1, 0});
        m.triangles.push_back({first, first + 1, first + 2});
    }
    std::ostringstream out;
    out.setstate(std::ios::badbit);
    writeStlBinary(m, out, "fails");
    EXPECT_TRUE(out.fail());
    EXPECT_TRUE(out.str().empty());
}

}  // namespace
}  // namespace tsf
