// Checks on tsf::InputError: the error type every bad input must end in
// (never an assertion). Part of the shared test support (tests/support/).
#pragma once

#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "gen/util/error.h"

namespace tsf::test {

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

/// Asserts that `stmt` throws InputError whose detail contains `text`, at any position.
#define EXPECT_INPUT_ERROR(stmt, text)                                                            \
    do {                                                                                           \
        const ::tsf::InputError err_ = ::tsf::test::catchInputError([&] { (void)(stmt); });          \
        EXPECT_NE(err_.detail().find(text), std::string::npos) << "message: " << err_.what();       \
    } while (0)
