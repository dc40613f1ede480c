// Typed errors for bad user data (see docs/design.md, "Three kinds of failure").
//
// A bug is an assertion. Bad input is an InputError: it names the file, the
// 1-based line and column where the problem is (0 = not applicable), and says
// what was expected, so a person can fix the file without reading our code.
#pragma once

#include <stdexcept>
#include <string>

namespace tsf {

/// Bad input data or a bad parameter; message() is ready to show to a person.
class InputError : public std::runtime_error {
public:
    /// path: file the problem is in ("" for a command-line parameter).
    /// line, column: 1-based position; 0 when the position is not meaningful.
    InputError(std::string path, int line, int column, const std::string& what);
    /// A parameter error with no file position.
    explicit InputError(const std::string& what);

    const std::string& path() const { return path_; }
    int line() const { return line_; }
    int column() const { return column_; }
    /// The bare description without the "path:line:col: " prefix.
    const std::string& detail() const { return detail_; }

private:
    std::string path_;
    int line_ = 0;
    int column_ = 0;
    std::string detail_;
};

/// An output file could not be written where the user asked: its folder is
/// missing or not writable, the disk is full, or a file-size limit was hit.
/// The user can fix it, so it is bad input (exit 2), not a failed tool.
class OutputError : public InputError {
public:
    /// path: the output the user named; what: the reason (the OS message).
    OutputError(const std::string& path, const std::string& what) : InputError(path, 0, 0, what) {}
};

}  // namespace tsf
