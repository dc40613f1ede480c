// writeMesh dispatch: extensions, case, unknown types, empty meshes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "gen/util/error.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/mesh_writer.h"
#include "mesh_io_test_support.h"

namespace tsf {
namespace {

using test::scratchDir;
using ::testing::HasSubstr;

TEST(WriteMesh, FormatFollowsTheExtensionInAnyCase) {
    const auto dir = scratchDir();
    const Mesh tetra = test::tetrahedron();
    const std::pair<const char*, const char*> cases[] = {
        {"a.stl", "stl-binary"}, {"b.STL", "stl-binary"}, {"c.3mf", "3mf"}, {"d.3MF", "3mf"},
        {"e.off", "off"},        {"f.Off", "off"},        {"g.obj", "obj"}, {"h.OBJ", "obj"}};
    for (const auto& [name, format] : cases) {
        const std::string path = (dir / name).string();
        writeMesh(tetra, path);
        MeshReadReport report;
        const Mesh m = readMesh(path, &report);
        EXPECT_EQ(report.format, format) << name;
        EXPECT_DOUBLE_EQ(signedVolume(m), 10.0) << name;
    }
}

TEST(WriteMesh, UnknownExtensionListsTheSupportedOnes) {
    const auto dir = scratchDir();
    for (const char* name : {"model.ply", "model"}) {
        try {
            writeMesh(test::tetrahedron(), (dir / name).string());
            FAIL() << name;
        } catch (const InputError& e) {
            EXPECT_THAT(e.what(), HasSubstr(".stl, .3mf, .off, .obj"));
        }
    }
    EXPECT_TRUE(test::listFiles(dir).empty());
}

TEST(WriteMesh, EmptyMeshIsAnEmptyFileExceptFor3mf) {
    const auto dir = scratchDir();
    for (const char* name : {"e.stl", "e.off", "e.obj"}) {
        const std::string path = (dir / name).string();
        writeMesh(Mesh{}, path);
        MeshReadReport report;
        EXPECT_EQ(readMesh(path, &report).triangleCount(), 0u) << name;
        ASSERT_FALSE(report.notes.empty());
        EXPECT_THAT(report.notes.back(), HasSubstr("no triangles"));
    }
    EXPECT_THROW(writeMesh(Mesh{}, (dir / "e.3mf").string()), InputError);
    EXPECT_FALSE(std::filesystem::exists(dir / "e.3mf"));
}

TEST(WriteMesh, OutOfRangeIndexIsABugReportedBeforeWriting) {
    const auto dir = scratchDir();
    Mesh m = test::tetrahedron();
    m.triangles.push_back({0, 1, 4});
    EXPECT_THROW(writeMesh(m, (dir / "bug.stl").string()), std::invalid_argument);
    EXPECT_TRUE(test::listFiles(dir).empty());
}

TEST(ReadMesh, ContentDecidesForUnknownExtensions) {
    const auto dir = scratchDir();
    writeMesh(test::tetrahedron(), (dir / "t.3mf").string());
    writeMesh(test::tetrahedron(), (dir / "t.off").string());
    writeMesh(test::tetrahedron(), (dir / "t.stl").string());
    std::filesystem::rename(dir / "t.3mf", dir / "t.bin1");
    std::filesystem::rename(dir / "t.off", dir / "t.bin2");
    std::filesystem::rename(dir / "t.stl", dir / "t");
    MeshReadReport report;
    readMesh((dir / "t.bin1").string(), &report);
    EXPECT_EQ(report.format, "3mf");
    readMesh((dir / "t.bin2").string(), &report);
    EXPECT_EQ(report.format, "off");
    readMesh((dir / "t").string(), &report);
    EXPECT_EQ(report.format, "stl-binary");
    test::writeText(dir / "t.txt", "hello");
    EXPECT_THROW(readMesh((dir / "t.txt").string()), InputError);
}

TEST(ReadMesh, MissingFileAndFolderAreInputErrors) {
    const auto dir = scratchDir();
    try {
        readMesh((dir / "missing.stl").string());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.path(), (dir / "missing.stl").string());
        EXPECT_THAT(e.what(), HasSubstr("No such file"));
    }
    EXPECT_THROW(readMesh(dir.string()), InputError);
}

}  // namespace
}  // namespace tsf
