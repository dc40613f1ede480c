// readFileBytes: the one whole-file reader of fields, meshes and sidecars.
#include "gen/util/file_bytes.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "gen/error.h"

namespace tsf {
namespace {

namespace fs = std::filesystem;

fs::path scratch(const std::string& name) {
    const fs::path dir = fs::path(TSF_TEST_SCRATCH) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

TEST(FileBytes, ReturnsTheBytesUnchanged) {
    const fs::path p = scratch("bytes") / "f.bin";
    const std::string bytes("a\r\nb\0c\n", 7);
    std::ofstream(p, std::ios::binary) << bytes;
    EXPECT_EQ(readFileBytes(p.string()), bytes);
    std::ofstream(p, std::ios::binary | std::ios::trunc).close();
    EXPECT_EQ(readFileBytes(p.string()), "");
}

TEST(FileBytes, MissingFileFolderAndSizeLimitAreInputErrors) {
    const fs::path dir = scratch("bytes_errors");
    try {
        readFileBytes((dir / "missing").string());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_EQ(e.path(), (dir / "missing").string());
        EXPECT_NE(e.detail().find("not found"), std::string::npos) << e.what();
    }
    try {
        readFileBytes(dir.string());
        FAIL();
    } catch (const InputError& e) {
        EXPECT_NE(e.detail().find("folder"), std::string::npos) << e.what();
    }
    std::ofstream(dir / "big", std::ios::binary) << std::string(100, 'x');
    EXPECT_EQ(readFileBytes((dir / "big").string(), 100).size(), 100u);
    EXPECT_THROW(readFileBytes((dir / "big").string(), 99), InputError);
}

}  // namespace
}  // namespace tsf
