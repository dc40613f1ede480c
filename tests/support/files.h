// Files for tests: a scratch folder per test, whole files in and out, paths
// in the source tree. Part of the shared test support (tests/support/).
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace tsf::test {

/// A fresh, empty folder TSF_TEST_SCRATCH/name for one test.
inline std::filesystem::path scratchDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(TSF_TEST_SCRATCH) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

/// A fresh, empty scratch folder named after the running test ("Suite.Name").
inline std::filesystem::path scratchDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    return scratchDir(std::string(info->test_suite_name()) + "." + info->name());
}

/// The file's bytes ("" when it cannot be read).
inline std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

/// Writes the bytes as they are (no newline translation); a failure fails the test.
inline void writeText(const std::filesystem::path& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    EXPECT_TRUE(out.good()) << "cannot write " << path;
}

/// Writes `bytes` to TSF_TEST_SCRATCH/name (folder created, not emptied) and returns the path.
inline std::string writeScratch(const std::string& name, const std::string& bytes) {
    const std::filesystem::path dir(TSF_TEST_SCRATCH);
    std::filesystem::create_directories(dir);
    writeText(dir / name, bytes);
    return (dir / name).string();
}

/// A path in the source tree ("examples/volcano.csv").
inline std::string sourcePath(const std::string& relative) { return std::string(TSF_SOURCE_DIR) + "/" + relative; }

/// Names of the files in dir (to check that no temporary file is left behind).
inline std::vector<std::string> listFiles(const std::filesystem::path& dir) {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(dir)) names.push_back(entry.path().filename().string());
    return names;
}

}  // namespace tsf::test
