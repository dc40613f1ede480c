// Helpers for the reader tests: scratch files and checks on InputError.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include "gen/error.h"

namespace tsf::test {

/// Writes `bytes` to TSF_TEST_SCRATCH/name (folder created) and returns the path.
inline std::string writeScratch(const std::string& name, const std::string& bytes) {
    const std::filesystem::path dir(TSF_TEST_SCRATCH);
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / name;
    std::ofstream out(path, std::ios::binary);
    out.write(bytes.data(), std::streamsize(bytes.size()));
    out.close();
    EXPECT_TRUE(out.good()) << path;
    return path.string();
}

inline std::string sourcePath(const std::string& relative) { return std::string(TSF_SOURCE_DIR) + "/" + relative; }

/// The InputError thrown by `f`, or a test failure (returned error then has line -1).
inline InputError catchInputError(const std::function<void()>& f) {
    try {
        f();
    } catch (const InputError& e) {
        return e;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "expected InputError, got another exception: " << e.what();
        return InputError("", -1, -1, "wrong exception");
    }
    ADD_FAILURE() << "expected InputError, nothing was thrown";
    return InputError("", -1, -1, "nothing thrown");
}

}  // namespace tsf::test

/// Asserts that `stmt` throws InputError at (line, column) whose detail contains `text`.
#define EXPECT_INPUT_ERROR_AT(stmt, line_, column_, text)                                         \
    do {                                                                                           \
        const ::tsf::InputError err_ = ::tsf::test::catchInputError([&] { (void)(stmt); });          \
        EXPECT_EQ(err_.line(), (line_)) << err_.what();                                            \
        EXPECT_EQ(err_.column(), (column_)) << err_.what();                                        \
        EXPECT_NE(err_.detail().find(text), std::string::npos) << "message: " << err_.what();       \
    } while (0)
