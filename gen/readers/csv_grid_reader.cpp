#include "gen/readers/csv_grid_reader.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "gen/util/error.h"
#include "gen/readers/csv_tokenizer.h"
#include "gen/readers/number_field.h"
#include "gen/readers/raster_limits.h"
#include "gen/util/file_bytes.h"

namespace tsf {
namespace {

// How a field would parse before the table's decimal mark is known.
NumberField classify(const CsvField& f, DecimalMark mark) {
    double v = 0.0;
    return parseWithDecimalMark(f.text, mark, v);
}

bool isNumber(NumberField kind) { return kind == NumberField::Number || kind == NumberField::Infinite; }

bool isHeader(const std::vector<CsvField>& fields, size_t first, DecimalMark mark) {
    int text_fields = 0;
    for (size_t k = first; k < fields.size(); ++k) {
        const NumberField kind = classify(fields[k], mark);
        if (isNumber(kind)) return false;
        if (kind == NumberField::NotNumber) ++text_fields;
    }
    return text_fields > 0;
}

// ",0,1,2" or ",a,b,c": the header pandas writes above a row-index column.
bool isIndexHeader(const std::vector<CsvField>& fields, DecimalMark mark) {
    if (fields.size() < 2 || fields[0].quoted || !fields[0].text.empty()) return false;
    for (size_t k = 1; k < fields.size(); ++k)
        if (fields[k].text.empty()) return false;
    if (isHeader(fields, 1, mark)) return true;
    int64_t first = -1;
    for (size_t k = 1; k < fields.size(); ++k) {
        int64_t n = 0;
        if (!parseWholeNumber(fields[k].text, 1'000'000'000, n)) return false;
        if (k == 1) first = n;
        if ((first != 0 && first != 1) || n != first + int64_t(k - 1)) return false;
    }
    return true;
}

std::string delimiterName(char d) {
    switch (d) {
        case ',': return "comma";
        case ';': return "semicolon";
        case '\t': return "tab";
        default: return "whitespace";
    }
}

// Watches the first column for 0, 1, 2, ... (or 1, 2, 3, ...): a row index
// written without a header, which tsf cannot tell from data.
struct IndexColumnWatch {
    bool counting = true;
    double first = 0.0;
    void see(int64_t row, double v) {
        if (row == 0) first = v;
        counting = counting && (first == 0.0 || first == 1.0) && v == first + double(row);
    }
};

}  // namespace

void checkCsvDelimiter(char delimiter) {
    if (delimiter != 0 && delimiter != ',' && delimiter != ';' && delimiter != '\t' && delimiter != ' ')
        throw InputError(std::string("CSV delimiter ") + quoteForMessage(std::string_view(&delimiter, 1)) +
                         " is not supported; use comma, semicolon, tab or space");
}

Raster parseCsvGrid(std::string_view text, const std::string& path, char delimiter, DecimalMark decimal) {
    checkCsvDelimiter(delimiter);
    if (delimiter == ',' && decimal == DecimalMark::Comma)
        throw InputError("a decimal comma needs another delimiter than the comma (--delimiter ; tab or space)");
    char delim = delimiter != 0 ? delimiter : detectCsvDelimiter(text);
    if (delim == ',' && decimal == DecimalMark::Comma) {
        // "1,5" on every line is one column of decimal commas; "1,2,3" is a
        // comma-separated file that --decimal-comma would misread.
        const size_t start = text.find_first_not_of(" \t\r\n");
        const std::string_view first = start == std::string_view::npos ? std::string_view() : text.substr(start);
        const std::string_view line = first.substr(0, first.find_first_of("\r\n"));
        if (std::count(line.begin(), line.end(), ',') > 1)
            throw InputError(path, 0, 0,
                             "--decimal-comma: the values are separated by commas (\"" +
                                 std::string(line.substr(0, 40)) +
                                 "\"); a decimal comma needs another delimiter: give --delimiter ; tab or space, or "
                                 "leave out --decimal-comma");
        delim = ' ';  // "1,5" on every line: one column
    }
    DecimalMark mark = delim == ',' ? DecimalMark::Point : decimal;
    CsvTokenizer tokenizer(text, delim, path);
    std::vector<CsvField> fields;

    Raster raster;
    raster.source = path;
    raster.kind = "csv";
    raster.facts.push_back({"delimiter", delimiterName(delim) + (delimiter == 0 ? " (detected)" : "")});
    int64_t cols = -1;       // fields per line, index column included
    size_t first_value = 0;  // 1 when the first column is a dropped row index
    int64_t rows = 0;
    int first_line = 0;      // line that fixed the column count
    bool first_record = true;
    bool header_seen = false;
    bool all_last_empty = true;  // every line ends with an empty unquoted field
    IndexColumnWatch index_watch;

    while (tokenizer.next(fields)) {
        if (fields.empty()) continue;  // blank line
        const int line = tokenizer.line();
        if (first_record) {
            first_record = false;
            cols = int64_t(fields.size());
            first_line = line;
            if (isIndexHeader(fields, mark)) first_value = 1;
            if (first_value == 1 || isHeader(fields, 0, mark)) {
                header_seen = true;
                all_last_empty = cols > 1 && !fields.back().quoted && fields.back().text.empty();
                continue;
            }
        }
        if (int64_t(fields.size()) != cols) {
            const int column = int64_t(fields.size()) > cols ? fields[size_t(cols)].column : 0;
            throw InputError(path, line, column,
                             "line has " + std::to_string(fields.size()) + " " + delimiterName(delim) +
                                 "-separated fields, expected " + std::to_string(cols) + " like line " +
                                 std::to_string(first_line));
        }
        checkRasterSize(path, line, cols, rows + 1);
        all_last_empty = all_last_empty && cols - int64_t(first_value) > 1 && !fields.back().quoted &&
                         fields.back().text.empty();
        for (size_t k = first_value; k < fields.size(); ++k) {
            const CsvField& f = fields[k];
            double v = 0.0;
            const NumberField kind = parseWithDecimalMark(f.text, mark, v);
            if (kind == NumberField::Number) {
                raster.values.push_back(v);
            } else if (kind == NumberField::NoData) {
                raster.values.push_back(NAN);
            } else {
                throw InputError(path, f.line, f.column, badValueMessage(kind, f.text, mark, delim));
            }
            if (k == 0) index_watch.see(rows, raster.values.back());
        }
        ++rows;
    }
    if (rows == 0) {
        if (header_seen) throw InputError(path, first_line, 0, "has a header line but no data lines");
        throw InputError(path, 0, 0, "is empty; expected lines of numbers");
    }
    int64_t value_cols = cols - int64_t(first_value);
    if (all_last_empty) {
        // "1,2,3," on every line: the trailing delimiter adds no column.
        std::vector<double> kept;
        kept.reserve(size_t(rows * (value_cols - 1)));
        for (int64_t r = 0; r < rows; ++r)
            for (int64_t c = 0; c + 1 < value_cols; ++c) kept.push_back(raster.values[size_t(r * value_cols + c)]);
        raster.values = std::move(kept);
        --value_cols;
    }
    raster.cols = int32_t(value_cols);
    raster.rows = int32_t(rows);
    if (mark == DecimalMark::Comma)
        raster.facts.push_back({"decimal mark", std::string("comma") + (decimal == DecimalMark::Detect ? " (detected)" : "")});
    if (header_seen) raster.facts.push_back({"header", "line " + std::to_string(first_line) + " skipped"});
    if (first_value == 1)
        raster.facts.push_back({"index column", "first column dropped (row labels under an empty header cell)"});
    else if (index_watch.counting && rows >= 3 && value_cols >= 2)
        raster.facts.push_back({"note", "the first column counts " + std::string(index_watch.first == 0 ? "0, 1, 2" : "1, 2, 3") +
                                            ", ...; if it is a row index, not data, remove it (pandas: "
                                            "to_csv(index=False)) or give it an empty header cell"});
    return raster;
}

Raster readCsvGrid(const std::string& path, char delimiter, DecimalMark decimal) {
    checkCsvDelimiter(delimiter);
    const std::string bytes = readFileBytes(path, kMaxInputFileBytes);
    return parseCsvGrid(bytes, path, delimiter, decimal);
}

}  // namespace tsf
