// TextScanner: whitespace-separated tokens of a text file with their line and
// column, and number parsing that names the position on failure. Internal to
// gen/mesh_io/ (ASCII STL, OFF, OBJ readers).
//
// Lines end at '\n'; '\r' counts as whitespace, so CRLF files read the same.
// Lines and columns are 1-based; a column counts bytes. If comment is not
// '\0', it starts a comment running to the end of the line.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace tsf::mesh_io {

class TextScanner {
public:
    TextScanner(std::string_view text, std::string path, char comment = '\0');

    /// Next token on the current line; false (without moving to the next
    /// line) when the line has no more tokens.
    bool tokenOnLine(std::string_view& token);
    /// Next token, moving over line ends as needed; false at end of text.
    bool token(std::string_view& token);
    /// Skips what is left of the current line; false if there is no next line.
    bool nextLine();

    /// Position of the last token returned (or of the line start before any).
    int line() const { return token_line_; }
    int column() const { return token_column_; }

    /// Throws tsf::InputError at the last token: "<path>:<line>:<col>: <what>".
    [[noreturn]] void fail(const std::string& what) const;
    /// Throws tsf::InputError at the current line, for "unexpected end of
    /// line/file" errors.
    [[noreturn]] void failHere(const std::string& what) const;

    /// token as a finite double (an optional leading '+' is accepted), or fail
    /// saying that `what` was expected.
    double finiteNumber(std::string_view token, const char* what) const;
    /// token as a double, NaN and infinities allowed (for values that are
    /// read and ignored, like STL facet normals).
    double anyNumber(std::string_view token, const char* what) const;
    /// token as a whole number, or fail.
    int64_t integer(std::string_view token, const char* what) const;

    /// The path given at construction.
    const std::string& path() const { return path_; }

private:
    std::string_view text_;
    std::string path_;
    char comment_;
    size_t pos_ = 0;
    size_t line_start_ = 0;
    int line_ = 1;
    int token_line_ = 1;
    int token_column_ = 0;
};

/// True if token equals keyword ignoring ASCII case.
bool equalsIgnoringCase(std::string_view token, std::string_view keyword);

}  // namespace tsf::mesh_io
