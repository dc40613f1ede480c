// OFF and OBJ: exact double round trips, the syntax variants real files use,
// and errors that point at the line and column.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>
#include <sstream>

#include "gen/util/error.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/mesh_io/obj_reader.h"
#include "gen/mesh_io/obj_writer.h"
#include "gen/mesh_io/off_reader.h"
#include "gen/mesh_io/off_writer.h"
#include "mesh_io_test_support.h"

namespace tsf {
namespace {

using test::scratchDir;
using ::testing::HasSubstr;

// A mesh whose coordinates use every bit of a double: random values over
// several magnitudes, plus awkward ones.
Mesh awkwardMesh() {
    Mesh m;
    std::mt19937_64 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const double scale = std::pow(10.0, (i % 9) - 4);
        m.positions.push_back({unit(rng) * scale, unit(rng) * scale, unit(rng) * scale});
    }
    m.positions.push_back({0.1, 1.0 / 3.0, 2.0 / 3.0});
    m.positions.push_back({1e-300, -1e300, 5e-324});  // tiny, huge, smallest denormal
    m.positions.push_back({123456789.123456789, -0.30000000000000004, 0.1 + 0.2});
    for (uint32_t i = 0; i + 2 < m.positions.size(); i += 3) m.triangles.push_back({i, i + 1, i + 2});
    return m;
}

void expectExactlyEqual(const Mesh& a, const Mesh& b) {
    ASSERT_EQ(a.positions.size(), b.positions.size());
    for (size_t i = 0; i < a.positions.size(); ++i) EXPECT_EQ(a.positions[i], b.positions[i]) << "vertex " << i;
    EXPECT_EQ(a.triangles, b.triangles);
}

TEST(OffObjRoundTrip, PositionsComeBackBitForBit) {
    const auto dir = scratchDir();
    const Mesh original = awkwardMesh();
    for (const char* name : {"awkward.off", "awkward.obj", "AWKWARD.OFF"}) {
        const std::string path = (dir / name).string();
        writeMesh(original, path);
        MeshReadReport report;
        const Mesh read = readMesh(path, &report);
        expectExactlyEqual(original, read);
        EXPECT_EQ(report.merged_vertices, 0u) << name;
        EXPECT_TRUE(report.format == "off" || report.format == "obj");
    }
}

TEST(OffObjRoundTrip, ClosedCubeAndTetrahedronKeepTheirVolume) {
    const auto dir = scratchDir();
    for (const char* name : {"c.off", "c.obj"}) {
        const std::string path = (dir / name).string();
        writeMesh(test::cube(2.5, {1, 2, 3}), path);
        EXPECT_DOUBLE_EQ(signedVolume(readMesh(path)), 2.5 * 2.5 * 2.5);
        writeMesh(test::tetrahedron(), path);
        EXPECT_DOUBLE_EQ(signedVolume(readMesh(path)), 10.0);
    }
}

TEST(OffWriter, TextLayout) {
    std::ostringstream out;
    writeOff(test::tetrahedron(), out, "tetra");
    EXPECT_EQ(out.str(),
              "OFF\n# tetra\n4 4 0\n0 0 0\n4 0 0\n0 3 0\n0 0 5\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
}

TEST(ObjWriter, TextLayoutIsOneBased) {
    std::ostringstream out;
    writeObj(test::tetrahedron(), out, "tetra");
    EXPECT_EQ(out.str(),
              "# tetra\no tetra\nv 0 0 0\nv 4 0 0\nv 0 3 0\nv 0 0 5\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
}

TEST(OffReader, VariantsCommentsAndPolygons) {
    const std::string text =
        "# a quad and a triangle\n"
        "COFF 5 2 0\n"
        "0 0 0 255 0 0 255\n"
        "1 0 0 255 0 0 255  # red\n"
        "1 1 0 0 255 0 255\n"
        "0 1 0 0 0 255 255\n"
        "\n"
        "0.5 0.5 1 0 0 0 255\n"
        "4 0 1 2 3 1 0 0\n"
        "3\n 0 1 4\n";
    MeshReadReport report;
    const Mesh m = parseOff(text, "v.off", &report);
    ASSERT_EQ(m.vertexCount(), 5u);
    ASSERT_EQ(m.triangleCount(), 3u);
    EXPECT_EQ(m.triangles[0], (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(m.triangles[1], (std::array<uint32_t, 3>{0, 2, 3}));
    EXPECT_EQ(m.triangles[2], (std::array<uint32_t, 3>{0, 1, 4}));
    EXPECT_EQ(m.positions[4], (Vec3{0.5, 0.5, 1}));
    ASSERT_FALSE(report.notes.empty());
    EXPECT_THAT(report.notes[0], HasSubstr("1 faces with more than 3 corners"));
}

TEST(ObjReader, CornerFormsNegativeIndicesAndIgnoredStatements) {
    const std::string text =
        "# exported\n"
        "mtllib x.mtl\n"
        "o thing\n"
        "v 0 0 0\n"
        "v 1 0 0 1.0\n"
        "v 1 1 0 0.5 0.5 0.5\n"
        "vt 0 0\n"
        "vn 0 0 1\n"
        "v 0 1 0\n"
        "usemtl red\n"
        "s off\n"
        "f 1/1/1 2/1/1 3/1/1 4/1/1\n"
        "f -4//1 -3//1 -1//1\n"
        "v 0.5 0.5 1\n"
        "f 1/1 2/1 -1/1\n"
        "l 1 2\n";
    MeshReadReport report;
    const Mesh m = parseObj(text, "forms.obj", &report);
    ASSERT_EQ(m.vertexCount(), 5u);
    ASSERT_EQ(m.triangleCount(), 4u);
    EXPECT_EQ(m.triangles[0], (std::array<uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(m.triangles[1], (std::array<uint32_t, 3>{0, 2, 3}));
    EXPECT_EQ(m.triangles[2], (std::array<uint32_t, 3>{0, 1, 3}));
    EXPECT_EQ(m.triangles[3], (std::array<uint32_t, 3>{0, 1, 4}));
    bool noted_line = false;
    for (const auto& n : report.notes) noted_line |= n.find("'l' at line 16") != std::string::npos;
    EXPECT_TRUE(noted_line);
}

TEST(ObjReader, FaceMayUseAVertexDefinedLater) {
    const Mesh m = parseObj("f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "later.obj");
    EXPECT_EQ(m.triangleCount(), 1u);
}

struct ErrorCase {
    const char* name;
    const char* text;
    int line;
    int column;
    const char* message_part;
};

class OffErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(OffErrors, PointAtTheProblem) {
    const ErrorCase& c = GetParam();
    try {
        parseOff(c.text, "bad.off");
        FAIL() << "no error for " << c.name;
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), c.line) << e.what();
        EXPECT_EQ(e.column(), c.column) << e.what();
        EXPECT_THAT(e.what(), HasSubstr(c.message_part));
    }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, OffErrors,
    ::testing::Values(
        ErrorCase{"empty", "", 0, 0, "empty file"},
        ErrorCase{"no header", "3 1 0\n", 1, 1, "'OFF' expected"},
        ErrorCase{"4OFF", "4OFF\n", 1, 1, "unsupported OFF variant"},
        ErrorCase{"binary", "OFF BINARY\n", 1, 5, "binary OFF"},
        ErrorCase{"bad count", "OFF\nthree 1 0\n", 2, 1, "vertex count"},
        ErrorCase{"bad number", "OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", 4, 3, "'x'"},
        ErrorCase{"nan", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 nan 0\n3 0 1 2\n", 5, 3, "not a finite number"},
        ErrorCase{"index range", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 6, 7, "out of range"},
        ErrorCase{"negative index", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 -1 2\n", 6, 5, "out of range"},
        ErrorCase{"two corners", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 6, 1, "at least 3"},
        ErrorCase{"missing face", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", 6, 0, "face 1 of 2"},
        ErrorCase{"missing vertex", "OFF\n3 1 0\n0 0 0\n1 0 0\n", 4, 0, "vertex 2 of 3"},
        ErrorCase{"trailing data", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 1 2\n", 7, 1,
                  "end of file expected"}),
    [](const auto& info) {
        std::string n = info.param.name;
        for (char& ch : n) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
        return n;
    });

class ObjErrors : public ::testing::TestWithParam<ErrorCase> {};

TEST_P(ObjErrors, PointAtTheProblem) {
    const ErrorCase& c = GetParam();
    try {
        parseObj(c.text, "bad.obj");
        FAIL() << "no error for " << c.name;
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), c.line) << e.what();
        EXPECT_EQ(e.column(), c.column) << e.what();
        EXPECT_THAT(e.what(), HasSubstr(c.message_part));
    }
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ObjErrors,
    ::testing::Values(
        ErrorCase{"empty", "", 0, 0, "empty file"},
        ErrorCase{"unknown", "v 0 0 0\nbogus 1 2\n", 2, 1, "unknown OBJ statement 'bogus'"},
        ErrorCase{"short v", "v 0 0\n", 1, 0, "3 coordinates"},
        ErrorCase{"inf", "v 0 inf 0\n", 1, 5, "not a finite number"},
        ErrorCase{"index 0", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", 4, 3, "start at 1"},
        ErrorCase{"beyond", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n", 4, 7, "out of range"},
        ErrorCase{"relative before", "v 0 0 0\nf -1 -2 -3\n", 2, 6, "before the first vertex"},
        ErrorCase{"two corners", "v 0 0 0\nv 1 0 0\nf 1 2\n", 3, 0, "at least 3"},
        ErrorCase{"bad corner", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/x 3\n", 4, 5, "texture index"},
        ErrorCase{"bad slashes", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/1/ 3\n", 4, 5, "'v/vt/vn'"}),
    [](const auto& info) {
        std::string n = info.param.name;
        for (char& ch : n) ch = std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
        return n;
    });

}  // namespace
}  // namespace tsf
