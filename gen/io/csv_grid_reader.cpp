#include "gen/io/csv_grid_reader.h"

#include <cmath>
#include <vector>

#include "gen/error.h"
#include "gen/io/csv_tokenizer.h"
#include "gen/io/number_field.h"
#include "gen/io/raster_limits.h"
#include "gen/util/file_bytes.h"

namespace tsf {
namespace {

bool isHeader(const std::vector<CsvField>& fields) {
    int text_fields = 0;
    for (const CsvField& f : fields) {
        double v = 0.0;
        const NumberField kind = parseNumberField(f.text, v);
        if (kind == NumberField::Number || kind == NumberField::Infinite) return false;
        if (kind == NumberField::NotNumber) ++text_fields;
    }
    return text_fields > 0;
}

std::string delimiterName(char d) {
    switch (d) {
        case ',': return "comma";
        case ';': return "semicolon";
        case '\t': return "tab";
        default: return "whitespace";
    }
}

}  // namespace

void checkCsvDelimiter(char delimiter) {
    if (delimiter != 0 && delimiter != ',' && delimiter != ';' && delimiter != '\t' && delimiter != ' ')
        throw InputError(std::string("CSV delimiter ") + quoteForMessage(std::string_view(&delimiter, 1)) +
                         " is not supported; use comma, semicolon, tab or space");
}

Raster parseCsvGrid(std::string_view text, const std::string& path, char delimiter) {
    checkCsvDelimiter(delimiter);
    const char delim = delimiter != 0 ? delimiter : detectCsvDelimiter(text);
    CsvTokenizer tokenizer(text, delim, path);
    std::vector<CsvField> fields;

    Raster raster;
    raster.source = path;
    raster.kind = "csv";
    int64_t cols = -1;
    int64_t rows = 0;
    int first_line = 0;      // line that fixed the column count
    bool first_record = true;
    bool header_seen = false;
    bool all_last_empty = true;  // every line ends with an empty unquoted field

    while (tokenizer.next(fields)) {
        if (fields.empty()) continue;  // blank line
        const int line = tokenizer.line();
        if (first_record) {
            first_record = false;
            cols = int64_t(fields.size());
            first_line = line;
            if (isHeader(fields)) {
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
        ++rows;
        checkRasterSize(path, line, cols, rows);
        all_last_empty = all_last_empty && cols > 1 && !fields.back().quoted && fields.back().text.empty();
        for (const CsvField& f : fields) {
            double v = 0.0;
            const NumberField kind = parseNumberField(f.text, v);
            if (kind == NumberField::Number) {
                raster.values.push_back(v);
            } else if (kind == NumberField::NoData) {
                raster.values.push_back(NAN);
            } else {
                throw InputError(path, f.line, f.column, badNumberMessage(kind, f.text, delim));
            }
        }
    }
    if (rows == 0) {
        if (header_seen) throw InputError(path, first_line, 0, "has a header line but no data lines");
        throw InputError(path, 0, 0, "is empty; expected lines of numbers");
    }
    if (all_last_empty) {
        // "1,2,3," on every line: the trailing delimiter adds no column.
        std::vector<double> kept;
        kept.reserve(size_t(rows * (cols - 1)));
        for (int64_t r = 0; r < rows; ++r)
            for (int64_t c = 0; c + 1 < cols; ++c) kept.push_back(raster.values[size_t(r * cols + c)]);
        raster.values = std::move(kept);
        --cols;
    }
    raster.cols = int32_t(cols);
    raster.rows = int32_t(rows);
    return raster;
}

Raster readCsvGrid(const std::string& path, char delimiter) {
    checkCsvDelimiter(delimiter);
    const std::string bytes = readFileBytes(path, kMaxInputFileBytes);
    return parseCsvGrid(bytes, path, delimiter);
}

}  // namespace tsf
