// `tsf verify` on meshes other tools make (print validation of any STL): each
// broken file gets the right verdict - exit 1 with the failed check and where
// it is, or exit 2 for a file that is not a readable mesh, with the place in
// the file - and never a crash.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <cstring>
#include <limits>
#include <string>

#include "tests/support/meshes.h"
#include "tests/support/run.h"

namespace tsf {
namespace {
using test::kExitBadInput;
using test::kExitCheckFailed;
using test::kExitOk;
using test::runTsf;
using test::scratchDir;
using test::writeText;

// Binary STL written here, byte by byte (not by tsf's writer, which refuses
// what these tests need: NaN, wrong counts).
std::string binaryStl(const Mesh& m, const std::string& header = "test", int64_t claimed_count = -1) {
    std::string out(80, '\0');
    std::memcpy(out.data(), header.data(), std::min<size_t>(header.size(), 80));
    const auto put32 = [&](uint32_t v) { out.append(reinterpret_cast<const char*>(&v), 4); };
    const auto putf = [&](double v) {
        const float f = float(v);
        out.append(reinterpret_cast<const char*>(&f), 4);
    };
    put32(uint32_t(claimed_count >= 0 ? uint64_t(claimed_count) : m.triangles.size()));
    for (const auto& t : m.triangles) {
        for (int k = 0; k < 3; ++k) putf(0.0);  // normal: readers recompute it
        for (uint32_t v : t) {
            putf(m.positions[v].x);
            putf(m.positions[v].y);
            putf(m.positions[v].z);
        }
        out.append(2, '\0');
    }
    return out;
}

std::string asciiStl(const Mesh& m) {
    std::string out = "solid test\n";
    for (const auto& t : m.triangles) {
        out += "  facet normal 0 0 0\n    outer loop\n";
        for (uint32_t v : t)
            out += "      vertex " + std::to_string(m.positions[v].x) + " " + std::to_string(m.positions[v].y) + " " +
                   std::to_string(m.positions[v].z) + "\n";
        out += "    endloop\n  endfacet\n";
    }
    return out + "endsolid test\n";
}

struct Verdict {
    int exit_code;
    std::string text;
};

Verdict verifyFile(const std::string& name, const std::string& bytes) {
    const auto dir = scratchDir("foreign_" + name);
    writeText(dir / name, bytes);
    const auto r = runTsf("verify " + (dir / name).string(), dir);
    return {r.exit_code, r.output};
}

const Mesh kCube = test::cube(10.0);

TEST(ForeignMeshes, AClosedCubePassesAsBinaryAndAsAscii) {
    const Verdict b = verifyFile("cube.stl", binaryStl(kCube));
    EXPECT_EQ(b.exit_code, kExitOk) << b.text;
    const Verdict a = verifyFile("cube_ascii.stl", asciiStl(kCube));
    EXPECT_EQ(a.exit_code, kExitOk) << a.text;
}

TEST(ForeignMeshes, AnOpenMeshFailsClosedAndNamesTheHole) {
    Mesh open = kCube;
    open.triangles.pop_back();
    const Verdict v = verifyFile("open.stl", binaryStl(open));
    EXPECT_EQ(v.exit_code, kExitCheckFailed) << v.text;
    EXPECT_NE(v.text.find("FAIL  closed (no border edges)"), std::string::npos) << v.text;
    EXPECT_NE(v.text.find("hole bounded by 3 border edges"), std::string::npos) << v.text;
}

TEST(ForeignMeshes, ADuplicatedTriangleFailsTwoTrianglesPerEdgeWithItsPlace) {
    Mesh dup = kCube;
    dup.triangles.push_back(dup.triangles.front());
    const Verdict v = verifyFile("duplicated.stl", binaryStl(dup));
    EXPECT_EQ(v.exit_code, kExitCheckFailed) << v.text;
    EXPECT_NE(v.text.find("FAIL  every edge has exactly two triangles"), std::string::npos) << v.text;
    EXPECT_NE(v.text.find(" at ("), std::string::npos) << "a located offender: " << v.text;
}

TEST(ForeignMeshes, TwoCubesSharingAnEdgeAreNotManifold) {
    // The second cube touches the first along the edge x = y = 10.
    const Mesh pair = test::append(kCube, test::cube(10.0, {10, 10, 0}));
    const Verdict v = verifyFile("edge_pair.stl", binaryStl(pair));
    EXPECT_EQ(v.exit_code, kExitCheckFailed) << v.text;
    EXPECT_NE(v.text.find("FAIL  every edge has exactly two triangles"), std::string::npos) << v.text;
    EXPECT_NE(v.text.find("at (10.000, 10.000, "), std::string::npos) << "located on the shared edge: " << v.text;
}

TEST(ForeignMeshes, ANanCoordinateIsABadFileAtItsByteOffset) {
    Mesh m = kCube;
    m.positions[3].y = std::numeric_limits<double>::quiet_NaN();
    const Verdict v = verifyFile("nan.stl", binaryStl(m));
    EXPECT_EQ(v.exit_code, kExitBadInput) << v.text;
    EXPECT_NE(v.text.find("nan.stl"), std::string::npos) << v.text;
    EXPECT_NE(v.text.find("byte"), std::string::npos) << "the place in the file: " << v.text;
}

TEST(ForeignMeshes, AFileWithZeroTrianglesIsNotASolid) {
    const Verdict v = verifyFile("empty.stl", binaryStl(Mesh{}));
    EXPECT_NE(v.exit_code, kExitOk) << v.text;
    EXPECT_TRUE(v.exit_code == kExitCheckFailed || v.exit_code == kExitBadInput) << v.text;
    EXPECT_NE(v.text.find("no triangles"), std::string::npos) << v.text;
}

TEST(ForeignMeshes, HugeCoordinatesAreJudgedLikeSmallOnes) {
    // A cube 1e15 mm (a million km) across, far from the origin: float32 holds
    // it; every check must still give its verdict.
    const Mesh big = test::cube(1e15, {1e16, -1e16, 1e15});
    const Verdict v = verifyFile("huge.stl", binaryStl(big));
    EXPECT_EQ(v.exit_code, kExitOk) << v.text;
    Mesh big_open = big;
    big_open.triangles.pop_back();
    const Verdict o = verifyFile("huge_open.stl", binaryStl(big_open));
    EXPECT_EQ(o.exit_code, kExitCheckFailed) << o.text;
    EXPECT_NE(o.text.find("FAIL  closed (no border edges)"), std::string::npos) << o.text;
}

TEST(ForeignMeshes, BinaryWithASolidHeaderIsReadAsBinary) {
    // Many exporters write "solid NAME" into a binary STL's header.
    const Verdict v = verifyFile("solid_header.stl", binaryStl(kCube, "solid exported by a CAD tool"));
    EXPECT_EQ(v.exit_code, kExitOk) << v.text;
}

TEST(ForeignMeshes, ConfusedOrCutFilesAreBadFilesWithAPlace) {
    // ASCII that turns into binary bytes half way (a text-mode transfer of a
    // binary file, or two files joined): refused at its line and column.
    std::string mixed = asciiStl(kCube);
    mixed.insert(mixed.find("endloop"), std::string("\x01\x02\xff\xfe", 4));
    const Verdict m = verifyFile("mixed.stl", mixed);
    EXPECT_EQ(m.exit_code, kExitBadInput) << m.text;
    EXPECT_NE(m.text.find("mixed.stl:"), std::string::npos) << m.text;
    // A binary file whose count claims one triangle more than it holds.
    const Verdict c = verifyFile("count.stl", binaryStl(kCube, "x", int64_t(kCube.triangles.size()) + 1));
    EXPECT_EQ(c.exit_code, kExitBadInput) << c.text;
    EXPECT_NE(c.text.find("triangle count 13"), std::string::npos) << c.text;
    // A binary file cut in the middle of a triangle.
    std::string cut = binaryStl(kCube);
    cut.resize(cut.size() - 20);
    const Verdict t = verifyFile("cut.stl", cut);
    EXPECT_EQ(t.exit_code, kExitBadInput) << t.text;
    EXPECT_NE(t.text.find("truncated"), std::string::npos) << t.text;
    // ASCII STL missing its end.
    std::string open_ascii = asciiStl(kCube);
    open_ascii.resize(open_ascii.find("endsolid"));
    const Verdict e = verifyFile("no_end.stl", open_ascii);
    EXPECT_EQ(e.exit_code, kExitBadInput) << e.text;
    EXPECT_NE(e.text.find("endsolid"), std::string::npos) << e.text;
}

TEST(ForeignMeshes, AnEndlessStreamIsRefusedBeforeItIsRead) {
    const auto dir = scratchDir("foreign_stream");
    const auto r = runTsf("verify /dev/zero", dir);
    EXPECT_EQ(r.exit_code, kExitBadInput) << r.output;
    EXPECT_NE(r.err.find("is a device, not a file"), std::string::npos) << r.err;
    // The same for the scene sidecar.
    writeText(dir / "cube.stl", binaryStl(kCube));
    const auto s = runTsf("verify " + (dir / "cube.stl").string() + " --scene /dev/zero", dir);
    EXPECT_EQ(s.exit_code, kExitBadInput) << s.output;
    EXPECT_NE(s.err.find("/dev/zero: is a device, not a file"), std::string::npos) << s.err;
}

// A large file of another kind (a disk image, a video) is refused from its
// first bytes and its size, before it is read: 2 GiB of a sparse file with
// no mesh extension (not a ZIP, an OFF, an ASCII STL, nor the size its
// binary STL count says), and the same named .3mf (not a ZIP). Reading it
// whole first took seconds and 2 GiB of memory. The peak memory says it was
// not read.
TEST(ForeignMeshes, ALargeFileOfAnotherKindIsRefusedBeforeItIsRead) {
    const auto dir = scratchDir();
    for (const char* name : {"disk.img", "disk.3mf", "disk"}) {
        const std::string path = (dir / name).string();
        ASSERT_EQ(test::runCommand("truncate -s 2G " + path).exit_code, 0);
        const auto [code, peak_mib] = test::runMeasured(std::string(TSF_BINARY) + " verify " + path + " >" +
                                                        (dir / "out.txt").string() + " 2>&1");
        const std::string out = test::readText(dir / "out.txt");
        EXPECT_EQ(code, kExitBadInput) << name << ": " << out;
        EXPECT_NE(out.find(name), std::string::npos) << out;
        EXPECT_NE(out.find(std::string(name) == "disk.3mf" ? "is not a 3MF file" : "unknown mesh file type"),
                  std::string::npos)
            << out;
        EXPECT_LT(peak_mib, 200.0) << name << ": the file was read";
        std::filesystem::remove(path);
    }
}

}  // namespace
}  // namespace tsf
