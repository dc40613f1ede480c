// CsvTokenizer: splits delimited text into records of fields, with the
// 1-based line and character column of every field for error messages.
//
// Accepted dialect (RFC 4180 plus what spreadsheets and scripts write):
//   - a UTF-8 byte-order mark at the start is skipped;
//   - records end at "\n", "\r\n" or a lone "\r";
//   - a field may be quoted with '"'; inside quotes the delimiter and line
//     breaks are ordinary characters and '""' is one '"'; spaces between the
//     closing quote and the next delimiter are ignored, anything else there is
//     an error;
//   - unquoted fields are trimmed of surrounding spaces (and tabs, unless tab
//     is the delimiter);
//   - delimiter ' ' means "runs of spaces and tabs": leading and trailing
//     blanks make no empty fields, so a whitespace-separated record never has
//     an empty unquoted field.
// Columns count characters (UTF-8 code points; the BOM is not counted) from 1
// at the start of the line; a field's column is that of its first
// non-blank character (the opening quote for a quoted field).
#pragma once

#include <string>
#include <string_view>
#include <vector>

namespace tsf {

struct CsvField {
    std::string text;     ///< unquoted, unescaped, trimmed content
    int line = 0;         ///< 1-based line where the field starts
    int column = 0;       ///< 1-based character column where the field starts
    bool quoted = false;  ///< the field was written in quotes
};

/// Picks the delimiter of a delimited text from its first non-blank line
/// (outside quotes): tab if it has one (but ' ' when that line is only
/// numbers separated by a mix of tabs and blanks, "1  2\t3"), else ';' (so
/// "1,5;2,5" with decimal commas is read as two fields), else ',', else ' '
/// (whitespace-separated).
char detectCsvDelimiter(std::string_view text);

class CsvTokenizer {
public:
    /// `text` must outlive the tokenizer. `path` is only used in errors.
    /// `delimiter` is ',', ';', '\t' or ' ' (see the file comment).
    CsvTokenizer(std::string_view text, char delimiter, std::string path);

    /// Reads the next record into `fields` (cleared first). Returns false at
    /// the end of the text. A blank line yields a record with no fields.
    /// Throws InputError for an unterminated quote (at the opening quote) or
    /// text after a closing quote.
    bool next(std::vector<CsvField>& fields);

    /// Line number of the last record returned (its first line).
    int line() const { return record_line_; }

private:
    bool atEnd() const { return pos_ >= text_.size(); }
    bool atLineBreak() const;
    void consumeLineBreak();
    void advance();  // one byte; keeps line_/column_ up to date
    void skipBlanks();
    CsvField readField();

    std::string_view text_;
    char delimiter_;
    std::string path_;
    size_t pos_ = 0;
    int line_ = 1;
    int column_ = 1;
    int record_line_ = 0;
};

}  // namespace tsf
