// readFileBytes: the one whole-file reader of fields, meshes and sidecars.
#include "gen/util/file_bytes.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "gen/util/error.h"
#include "tests/support/files.h"

namespace tsf {
namespace {

namespace fs = std::filesystem;

TEST(FileBytes, ReturnsTheBytesUnchanged) {
    const fs::path p = test::scratchDir("bytes") / "f.bin";
    const std::string bytes("a\r\nb\0c\n", 7);
    test::writeText(p, bytes);
    EXPECT_EQ(readFileBytes(p.string()), bytes);
    test::writeText(p, "");
    EXPECT_EQ(readFileBytes(p.string()), "");
}

TEST(FileBytes, MissingFileFolderAndSizeLimitAreInputErrors) {
    const fs::path dir = test::scratchDir("bytes_errors");
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
    test::writeText(dir / "big", std::string(100, 'x'));
    EXPECT_EQ(readFileBytes((dir / "big").string(), 100).size(), 100u);
    EXPECT_THROW(readFileBytes((dir / "big").string(), 99), InputError);
}

}  // namespace
}  // namespace tsf
