// Grid CSV reader: a table of numbers, one raster row per line.
//
// Layout: the first data line is the TOP (north) row of the raster, the first
// field of a line its west-most cell. Every data line must have the same
// number of fields.
//
// Format (see csv_tokenizer.h for quoting, line endings and the BOM):
//   - delimiter ',', ';', tab or whitespace; detected from the first
//     non-blank line unless given (detectCsvDelimiter);
//   - an optional header: the first non-blank line is a header when none of
//     its fields is a number and at least one is text ("x1,x2,x3"); it is
//     skipped but still fixes the number of columns;
//   - a row-index column, as pandas writes it (DataFrame.to_csv): when the
//     header's first field is empty and the others are text or count
//     0, 1, 2, ... (",0,1,2"), the first column holds row labels and is
//     dropped, whatever it contains. Without such a header an index column
//     cannot be told from data; when the first column counts 0, 1, 2, ...
//     a fact says how to remove it;
//   - decimal mark (decimal_mark.h): a point, or a comma ("1,5;2,25") when
//     the delimiter is not a comma; detected from the first value that shows
//     one unless given;
//   - no data: an empty field, "-", "nan", "NA" or "N/A" (any case) -> NaN;
//   - blank lines are skipped anywhere;
//   - a delimiter at the end of every line ("1,2,3,") adds no column: when
//     the last field of every line is empty, that column is dropped.
// Raster::facts names the delimiter, the decimal comma, a skipped header and
// a dropped index column, each marked "(detected)" when tsf decided it.
// Errors (tsf::InputError, 1-based line and character column):
//   - a line with a different number of fields than the first (line; the
//     expected and found counts);
//   - a field that is not a number (line, column of the field, the text);
//   - an infinite or overflowing value ("inf", "1e999");
//   - an empty file, a header without data lines, or a size over the limits
//     of raster_limits.h.
#pragma once

#include <string>
#include <string_view>

#include "gen/readers/decimal_mark.h"
#include "gen/field/raster.h"

namespace tsf {

/// Parses grid CSV text. `path` names the source in errors and Raster::source.
/// `delimiter`: 0 = detect, else ',', ';', '\t' or ' ' (runs of blanks).
/// `decimal`: Comma reads "1,5" as 1.5 (with a detected delimiter, a comma
/// is then never taken as the delimiter); an explicit ',' delimiter with
/// Comma is an InputError.
Raster parseCsvGrid(std::string_view text, const std::string& path, char delimiter = 0,
                    DecimalMark decimal = DecimalMark::Detect);

/// Reads and parses a grid CSV file.
Raster readCsvGrid(const std::string& path, char delimiter = 0, DecimalMark decimal = DecimalMark::Detect);

/// Throws InputError unless `delimiter` is 0, ',', ';', '\t' or ' '.
void checkCsvDelimiter(char delimiter);

}  // namespace tsf
