// Point tables: x, y (and an optional weight) per line of a delimited file,
// to be binned into hexagons (point_binning.h).
//
// Columns are chosen by header name (case-sensitive, after trimming) or by
// 0-based index. When any column is chosen by name the first non-blank line
// must be a header that has that name. When all are chosen by index, the
// first line is a header if none of the chosen fields in it is a number
// (e.g. "lon,lat"), else it is data.
//
// Per data line (see csv_tokenizer.h for quoting, delimiters and the BOM):
//   - x and y must be finite numbers; otherwise InputError with the line and
//     the field's 1-based character column and text (empty or NaN included:
//     a point without a position cannot be placed, so the line must be fixed
//     or removed);
//   - the weight, if chosen, is a finite number, or empty/NaN/NA = missing
//     (stored as NaN and counted in missing_weights);
//   - the line must have enough fields for the chosen columns; other fields
//     are not looked at (text columns such as names are fine);
//   - blank lines are skipped.
// An empty file, a header without data lines, or more than kMaxPoints points
// is an InputError.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tsf {

/// Largest number of points read (16 bytes each plus weights).
inline constexpr int64_t kMaxPoints = 100'000'000;

/// A column picked by header name or by 0-based index.
struct ColumnRef {
    std::string name;  ///< header name; used when not empty
    int index = -1;    ///< 0-based column index; used when name is empty
    bool isSet() const { return !name.empty() || index >= 0; }
};

struct PointColumns {
    ColumnRef x;
    ColumnRef y;
    ColumnRef weight;     ///< optional: leave unset for unweighted points
    char delimiter = 0;   ///< 0 = detect (detectCsvDelimiter), else ',', ';', '\t', ' '
};

/// Parses a column spec like "x=lon,y=lat,w=passengers" or "x=0,y=1": keys
/// x, y, and w (or weight); a value of digits only is a 0-based index,
/// anything else a header name. x and y are required. Throws InputError.
PointColumns parsePointColumns(const std::string& spec);

struct PointTable {
    std::vector<double> x;       ///< data units, east
    std::vector<double> y;       ///< data units, north
    std::vector<double> weight;  ///< same size as x when a weight column was chosen, else empty; NaN = missing
    int64_t missing_weights = 0; ///< weights that were empty or NaN
    std::string source;          ///< file name
    std::string x_name, y_name, weight_name;  ///< header names (or "column N")
    size_t size() const { return x.size(); }
    bool hasWeight() const { return !weight.empty(); }
};

/// Parses delimited text into points. `path` names the source in errors.
PointTable parsePointsCsv(std::string_view text, const std::string& path, const PointColumns& cols);

/// Reads a delimited file of points.
PointTable readPointsCsv(const std::string& path, const PointColumns& cols);

}  // namespace tsf
