// STL: binary byte layout against hand-computed bytes, ASCII parsing, content
// detection, round trips, and errors that point at the byte or line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>
#include <sstream>

#include "gen/util/error.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/mesh_io/stl_reader.h"
#include "gen/mesh_io/stl_writer.h"
#include "mesh_io_test_support.h"

namespace tsf {
namespace {

using test::readText;
using test::scratchDir;
using test::writeText;
using ::testing::HasSubstr;

std::string bytesOf(std::initializer_list<int> values) {
    std::string s;
    for (int v : values) s += static_cast<char>(v);
    return s;
}

std::string binaryStl(const Mesh& mesh, const std::string& title = "tsf") {
    std::ostringstream out;
    writeStlBinary(mesh, out, title);
    return out.str();
}

// Little-endian bytes of a float, from its IEEE bits, independent of the
// writer's code path.
std::string leFloat(float f) {
    uint32_t bits;
    std::memcpy(&bits, &f, 4);
    return bytesOf({int(bits & 0xFF), int((bits >> 8) & 0xFF), int((bits >> 16) & 0xFF), int(bits >> 24)});
}

TEST(StlBinary, LayoutMatchesHandComputedBytes) {
    const std::string stl = binaryStl(test::tetrahedron(), "tetra");
    ASSERT_EQ(stl.size(), 80u + 4u + 4u * 50u);

    // Header: title, units, NUL padding; never "solid".
    const std::string header = stl.substr(0, 80);
    EXPECT_EQ(header.substr(0, 5), "tetra");
    EXPECT_THAT(header, HasSubstr("UNITS=mm"));
    EXPECT_EQ(header.back(), '\0');
    // Count field: 4 triangles, little-endian.
    EXPECT_EQ(stl.substr(80, 4), bytesOf({0x04, 0x00, 0x00, 0x00}));

    // Facet 0 = {0,2,1}: normal (0,0,-1), corners (0,0,0) (0,3,0) (4,0,0).
    // -1.0f = 0xBF800000, 3.0f = 0x40400000, 4.0f = 0x40800000.
    const std::string zero4 = bytesOf({0, 0, 0, 0});
    const std::string expected_facet0 = zero4 + zero4 + bytesOf({0x00, 0x00, 0x80, 0xBF})  // normal
                                        + zero4 + zero4 + zero4                          // (0,0,0)
                                        + zero4 + bytesOf({0x00, 0x00, 0x40, 0x40}) + zero4  // (0,3,0)
                                        + bytesOf({0x00, 0x00, 0x80, 0x40}) + zero4 + zero4  // (4,0,0)
                                        + bytesOf({0x00, 0x00});                            // attributes
    EXPECT_EQ(stl.substr(84, 50), expected_facet0);

    // Facet 3 = {1,2,3}: normal (15,20,12)/sqrt(769) by hand; 5.0f = 0x40A00000.
    const double len = std::sqrt(15.0 * 15 + 20.0 * 20 + 12.0 * 12);
    const std::string facet3 = stl.substr(84 + 3 * 50, 50);
    EXPECT_EQ(facet3.substr(0, 12), leFloat(float(15 / len)) + leFloat(float(20 / len)) + leFloat(float(12 / len)));
    EXPECT_EQ(facet3.substr(12 + 24, 12), zero4 + zero4 + bytesOf({0x00, 0x00, 0xA0, 0x40}));  // (0,0,5)
}

// A mesh of many blocks (each converted on other threads, in one part per
// core, while the one before is written): every facet in its place, its
// corners the float32 of each position, the last block short.
TEST(StlBinary, ALargeMeshKeepsEveryFacetInItsPlace) {
    Mesh m;
    const size_t n = 3 * 16384 + 1234;
    for (size_t t = 0; t < n; ++t) {
        const double x = double(t) * 0.25, y = double(t % 977) * 0.125;
        m.positions.push_back({x, y, 0.0});
        m.positions.push_back({x + 1, y, 0.0});
        m.positions.push_back({x, y + 1, 1.0 + double(t % 13)});
        m.triangles.push_back({uint32_t(3 * t), uint32_t(3 * t + 1), uint32_t(3 * t + 2)});
    }
    const std::string stl = binaryStl(m);
    ASSERT_EQ(stl.size(), 84 + 50 * n);
    size_t wrong = 0;  // every facet: the parts of a block meet anywhere in it
    for (size_t t = 0; t < n; ++t) {
        const std::string facet = stl.substr(84 + 50 * t, 50);
        for (int c = 0; c < 3; ++c) {
            const Vec3& p = m.positions[m.triangles[t][size_t(c)]];
            if (facet.substr(12 + 12 * size_t(c), 12) != leFloat(float(p.x)) + leFloat(float(p.y)) + leFloat(float(p.z)) &&
                wrong++ == 0)
                ADD_FAILURE() << "facet " << t << " corner " << c;
        }
        if (facet.substr(48, 2) != bytesOf({0, 0}) && wrong++ == 0) ADD_FAILURE() << "facet " << t << " attribute";
    }
    EXPECT_EQ(wrong, 0u);
}

TEST(StlBinary, TitleStartingWithSolidIsNotMistakenForAscii) {
    const std::string stl = binaryStl(test::tetrahedron(), "solid model");
    EXPECT_NE(stl.substr(0, 5), "solid");
    EXPECT_THAT(stl.substr(0, 80), HasSubstr("solid model"));
}

TEST(StlBinary, LongTitleIsCutToTheHeader) {
    const std::string stl = binaryStl(test::tetrahedron(), std::string(200, 'T'));
    ASSERT_EQ(stl.size(), 284u);
    EXPECT_THAT(stl.substr(0, 80), HasSubstr("UNITS=mm"));
}

TEST(StlBinary, RoundTripKeepsFloat32PositionsAndTopology) {
    const auto dir = scratchDir();
    // Coordinates that float32 cannot hold exactly.
    const Mesh original = test::cube(10.7, {0.1, -2.5, 1.0 / 3.0});
    const std::string path = (dir / "cube.stl").string();
    writeMesh(original, path);
    MeshReadReport report;
    const Mesh read = readMesh(path, &report);
    EXPECT_EQ(report.format, "stl-binary");
    ASSERT_EQ(read.vertexCount(), 8u);
    ASSERT_EQ(read.triangleCount(), 12u);
    EXPECT_EQ(report.input_vertices, 36u);
    EXPECT_EQ(report.merged_vertices, 28u);
    EXPECT_EQ(report.degenerate_index_triangles, 0u);
    for (size_t t = 0; t < 12; ++t) {
        for (int k = 0; k < 3; ++k) {
            const Vec3& a = original.positions[original.triangles[t][k]];
            const Vec3& b = read.positions[read.triangles[t][k]];
            EXPECT_EQ(float(a.x), b.x);
            EXPECT_EQ(float(a.y), b.y);
            EXPECT_EQ(float(a.z), b.z);
        }
    }
    // Same topology: vertex i of the original is always the same read vertex.
    std::vector<int> map(8, -1);
    for (size_t t = 0; t < 12; ++t) {
        for (int k = 0; k < 3; ++k) {
            int& m = map[original.triangles[t][k]];
            if (m < 0) m = int(read.triangles[t][k]);
            EXPECT_EQ(uint32_t(m), read.triangles[t][k]);
        }
    }
    EXPECT_NEAR(signedVolume(read), 10.7 * 10.7 * 10.7, 1e-3);
}

TEST(StlAscii, RoundTripThroughTextKeepsFloat32Positions) {
    const auto dir = scratchDir();
    const Mesh original = test::cube(10.7, {0.1, -2.5, 1.0 / 3.0});
    const std::string path = (dir / "cube.STL").string();  // extension case does not matter
    MeshWriteOptions opts;
    opts.ascii_stl = true;
    opts.title = "cube";
    writeMesh(original, path, opts);
    const std::string text = readText(path);
    EXPECT_EQ(text.rfind("solid cube\n", 0), 0u);
    EXPECT_THAT(text, HasSubstr("endsolid cube"));
    MeshReadReport report;
    const Mesh read = readMesh(path, &report);
    EXPECT_EQ(report.format, "stl-ascii");
    ASSERT_EQ(read.vertexCount(), 8u);
    for (size_t t = 0; t < 12; ++t) {
        for (int k = 0; k < 3; ++k) {
            const Vec3& a = original.positions[original.triangles[t][k]];
            const Vec3& b = read.positions[read.triangles[t][k]];
            EXPECT_EQ(float(a.x), float(b.x));
            EXPECT_EQ(float(a.y), float(b.y));
            EXPECT_EQ(float(a.z), float(b.z));
        }
    }
}

TEST(StlAscii, HandWrittenFileWithMixedCaseAndCrlfIsRead) {
    const std::string text =
        "solid hand made\r\n"
        "  facet normal 0 0 -1\r\n    outer loop\r\n      vertex 0 0 0\r\n      vertex 0 3 0\r\n"
        "      vertex 4 0 0\r\n    endloop\r\n  endfacet\r\n"
        "  FACET NORMAL 0 -1 0\r\n    OUTER LOOP\r\n      VERTEX 0 0 0\r\n      VERTEX 4 0 0\r\n"
        "      VERTEX 0 0 5\r\n    ENDLOOP\r\n  ENDFACET\r\n"
        "  facet normal -1 0 0 outer loop vertex 0 0 0 vertex 0 0 5 vertex 0 3 0 endloop endfacet\n"
        "  facet normal nan nan nan\n    outer loop\n      vertex +4 0 0\n      vertex 0 3.0 0\n"
        "      vertex 0 0 5e0\n    endloop\n  endfacet\n"
        "endsolid hand made\n";
    MeshReadReport report;
    const Mesh m = parseStl(text, "hand.stl", &report);
    EXPECT_EQ(report.format, "stl-ascii");
    EXPECT_EQ(m.vertexCount(), 4u);
    EXPECT_EQ(m.triangleCount(), 4u);
    EXPECT_DOUBLE_EQ(signedVolume(m), 10.0);
    EXPECT_EQ(m.positions[0], (Vec3{0, 0, 0}));
    EXPECT_EQ(m.positions[1], (Vec3{0, 3, 0}));
    EXPECT_EQ(m.positions[2], (Vec3{4, 0, 0}));
    EXPECT_EQ(m.positions[3], (Vec3{0, 0, 5}));
}

TEST(StlDetection, BinaryFileWhoseHeaderStartsWithSolidIsReadAsBinary) {
    std::string stl = binaryStl(test::tetrahedron());
    const std::string header = "solid exported by some CAD program";
    stl.replace(0, header.size(), header);
    MeshReadReport report;
    const Mesh m = parseStl(stl, "cad.stl", &report);
    EXPECT_EQ(report.format, "stl-binary");
    EXPECT_EQ(m.triangleCount(), 4u);
}

TEST(StlErrors, EmptyFile) {
    try {
        parseStl("", "empty.stl");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("empty file"));
        EXPECT_EQ(e.path(), "empty.stl");
    }
}

TEST(StlErrors, TruncatedBinaryNamesTheCountAndSizes) {
    const std::string stl = binaryStl(test::tetrahedron());
    try {
        parseStl(stl.substr(0, stl.size() - 7), "cut.stl");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("byte 80"));
        EXPECT_THAT(e.what(), HasSubstr("triangle count 4"));
        EXPECT_THAT(e.what(), HasSubstr("284 bytes"));
        EXPECT_THAT(e.what(), HasSubstr("277"));
        EXPECT_THAT(e.what(), HasSubstr("truncated"));
    }
}

TEST(StlErrors, CountLargerThanTheDataIsAMismatch) {
    std::string stl = binaryStl(test::tetrahedron());
    stl[80] = 5;
    EXPECT_THROW(parseStl(stl, "count.stl"), InputError);
    stl[80] = 3;
    EXPECT_THROW(parseStl(stl, "count.stl"), InputError);
}

TEST(StlErrors, ShortNonTextFile) {
    EXPECT_THROW(parseStl(std::string("\x01\x02garbage", 9), "short.stl"), InputError);
}

TEST(StlErrors, NanCoordinateNamesItsByteOffset) {
    std::string stl = binaryStl(test::tetrahedron());
    // Triangle 1, corner 2, y: 84 + 50*1 + 12 (normal) + 12*2 + 4 = 174.
    const float nan = std::numeric_limits<float>::quiet_NaN();
    std::memcpy(&stl[174], &nan, 4);
    try {
        parseStl(stl, "nan.stl");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("byte 174"));
        EXPECT_THAT(e.what(), HasSubstr("triangle 1 corner 2 y"));
        EXPECT_THAT(e.what(), HasSubstr("NaN"));
    }
}

TEST(StlErrors, AsciiErrorsCarryLineAndColumn) {
    const std::string text =
        "solid x\n"
        "facet normal 0 0 1\n"
        " outer loop\n"
        "  vertex 0 0 0\n"
        "  vertex 1 0 oops\n";
    try {
        parseStl(text, "bad.stl");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 5);
        EXPECT_EQ(e.column(), 14);
        EXPECT_THAT(e.what(), HasSubstr("bad.stl:5:14:"));
        EXPECT_THAT(e.what(), HasSubstr("'oops'"));
    }
}

TEST(StlErrors, AsciiNanVertexAndMissingEndsolid) {
    EXPECT_THROW(parseStl("solid x\nfacet normal 0 0 1 outer loop vertex nan 0 0 vertex 1 0 0 vertex 0 1 0 "
                          "endloop endfacet endsolid\n",
                          "nan.stl"),
                 InputError);
    try {
        parseStl("solid x\nfacet normal 0 0 1 outer loop vertex 0 0 0 vertex 1 0 0 vertex 0 1 0 endloop endfacet\n",
                 "cut.stl");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_THAT(e.what(), HasSubstr("end of file"));
        EXPECT_EQ(e.line(), 2);
    }
}

TEST(StlErrors, QuadFacetIsRefusedWithAClearMessage) {
    try {
        parseStl("solid q\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 1 1 0\n"
                 "vertex 0 1 0\nendloop\nendfacet\nendsolid q\n",
                 "quad.stl");
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 7);
        EXPECT_THAT(e.what(), HasSubstr("endloop"));
    }
}

TEST(StlWriter, NormalOfADegenerateTriangleIsZero) {
    Mesh m;
    m.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};  // collinear
    m.triangles = {{0, 1, 2}};
    const std::string stl = binaryStl(m);
    EXPECT_EQ(stl.substr(84, 12), std::string(12, '\0'));
}

TEST(StlWriter, CoordinateBeyondFloat32IsRefused) {
    const auto dir = scratchDir();
    Mesh m = test::tetrahedron();
    m.positions[1].x = 1e39;
    EXPECT_THROW(writeMesh(m, (dir / "big.stl").string()), InputError);
    EXPECT_TRUE(test::listFiles(dir).empty());
}

}  // namespace
}  // namespace tsf
