// sameFile and checkOutputPaths: paths compared as files, not as strings.
#include "gen/util/output_paths.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "tests/support/files.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {

TEST(OutputPaths, SpellingsOfOneFileAreTheSameFile) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "a.csv", "1\n");
    EXPECT_TRUE(sameFile((dir / "a.csv").string(), (dir / "." / "a.csv").string()));
    EXPECT_TRUE(sameFile((dir / "a.csv").string(), (dir / "x" / ".." / "a.csv").string()));
    std::filesystem::create_symlink(dir / "a.csv", dir / "link.csv");
    EXPECT_TRUE(sameFile((dir / "a.csv").string(), (dir / "link.csv").string()));
    EXPECT_TRUE(sameFile((dir / "new.stl").string(), (dir / "." / "new.stl").string())) << "not existing yet";
    EXPECT_FALSE(sameFile((dir / "a.csv").string(), (dir / "b.csv").string()));
}

TEST(OutputPaths, InputsAndRepeatedOutputsAreRefused) {
    const auto dir = test::scratchDir();
    const std::string in = (dir / "in.csv").string();
    test::writeText(in, "1\n");
    EXPECT_INPUT_ERROR(checkOutputPaths({{in, "the input"}}, {{in, "-o"}}), "is the input and would be overwritten by -o");
    EXPECT_INPUT_ERROR(checkOutputPaths({}, {{"m.stl", "-o"}, {"./m.stl", "--preview"}}), "(-o and --preview)");
    EXPECT_NO_THROW(checkOutputPaths({{in, "the input"}, {"", "-p"}}, {{"m.stl", "-o"}, {"", "--png"}}));
}

}  // namespace
}  // namespace tsf
