// TextScanner: whitespace-separated tokens of a text with the line and column
// where each starts, for every plain-text reader: PGM P2 and its header and
// ESRI ASCII grids (gen/readers), ASCII STL, OFF and OBJ (gen/mesh_io).
//
// The position convention, the same for every file tsf reads and every
// message it prints (the CSV tokenizer in gen/readers counts the same way):
//   - lines and columns are 1-based; column 0 means "the whole line";
//   - "\r\n", "\n" and a lone "\r" each end one line;
//   - a column counts characters (UTF-8 code points), not bytes, so it is
//     the column an editor shows.
// Whitespace within a line is space, tab, VT and FF. If `comment` is not
// '\0', it starts a comment that runs to the end of the line (and ends a
// token it touches).
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace tsf {

class TextScanner {
public:
    /// Scans `text` (which must outlive the scanner). `path` names the file
    /// in the errors fail() and failHere() throw.
    explicit TextScanner(std::string_view text, std::string path = {}, char comment = '\0');
    /// The same from byte `start` of text, which is at (line, column).
    TextScanner(std::string_view text, std::string path, char comment, size_t start, int line, int column);

    /// Next token, moving over line ends, blank lines and comments; false at
    /// the end of the text.
    bool next(std::string_view& token);
    /// Next token on the current line; false (without moving to the next
    /// line) when the line has no more tokens.
    bool nextOnLine(std::string_view& token);
    /// Skips what is left of the current line and its line end; false if
    /// there is no next line.
    bool skipLine();

    /// Position of the start of the last token returned; before the first
    /// token and after skipLine(): the current line and column 0.
    int line() const { return token_line_; }
    int column() const { return token_column_; }
    /// Byte offset where the scan is now (just past the last token returned).
    size_t offset() const { return pos_; }
    /// Line where the scan is now (after the last token; for "too few values").
    int currentLine() const { return line_; }
    const std::string& path() const { return path_; }

    /// Throws tsf::InputError at the last token: "<path>:<line>:<col>: <what>".
    [[noreturn]] void fail(const std::string& what) const;
    /// Throws tsf::InputError at the current line (column 0), for "unexpected
    /// end of line/file" errors. At the end of a text that ends with a line
    /// end it names the last line, the one a person sees.
    [[noreturn]] void failHere(const std::string& what) const;

private:
    bool atComment() const { return comment_ != '\0' && text_[pos_] == comment_; }
    void skipBlanks();
    void endLine();  ///< at a line end: step over it

    std::string_view text_;
    std::string path_;
    char comment_;
    size_t pos_;
    size_t line_start_;
    int line_;
    int column_;
    int token_line_;
    int token_column_ = 0;
};

}  // namespace tsf
