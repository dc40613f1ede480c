// TextScanner: whitespace-separated tokens of a text with their 1-based line
// and character column, for the plain-text raster formats (PGM P2 and its
// header, ESRI ASCII grids).
//
// Whitespace is space, tab, CR, LF, VT and FF; "\r\n", "\n" and a lone "\r"
// each end one line. With hash_comments, '#' starts a comment running to the
// end of the line (netpbm). Columns count UTF-8 code points.
#pragma once

#include <cstddef>
#include <string_view>

namespace tsf {

class TextScanner {
public:
    /// Scans `text` (which must outlive the scanner) from byte `start`, which
    /// is at line `line`, column 1 unless given.
    explicit TextScanner(std::string_view text, bool hash_comments = false, size_t start = 0, int line = 1,
                         int column = 1);

    /// Next token, or false at the end of the text.
    bool next(std::string_view& token);

    /// Position of the start of the last token returned.
    int line() const { return token_line_; }
    int column() const { return token_column_; }
    /// Byte offset just past the last token returned.
    size_t offset() const { return pos_; }
    /// Line where the scan is now (after the last token; for "too few values").
    int currentLine() const { return line_; }

private:
    void advance();

    std::string_view text_;
    bool hash_comments_;
    size_t pos_;
    int line_;
    int column_;
    int token_line_ = 0;
    int token_column_ = 0;
};

}  // namespace tsf
