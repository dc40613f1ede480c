#include "gen/readers/point_reader.h"

#include <algorithm>

#include "gen/util/error.h"
#include "gen/readers/csv_grid_reader.h"
#include "gen/readers/csv_tokenizer.h"
#include "gen/readers/file_magic.h"
#include "gen/readers/number_field.h"
#include "gen/readers/raster_limits.h"
#include "gen/util/file_bytes.h"

namespace tsf {
namespace {

constexpr int64_t kMaxColumnIndex = 1'000'000;

std::string trimmed(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return std::string(s);
}

std::string headerList(const std::vector<CsvField>& fields) {
    std::string out;
    for (size_t k = 0; k < fields.size() && k < 20; ++k) {
        if (k > 0) out += ", ";
        out += quoteForMessage(fields[k].text, 30);
    }
    if (fields.size() > 20) out += ", ...";
    return out;
}

struct Resolved {
    int index = -1;
    std::string label;  ///< for messages and PointTable names
    const char* role = "";
};

// "'lat', index 4" or "column 4".
std::string columnLabel(const Resolved& w) {
    if (w.label.rfind("column ", 0) == 0) return w.label;
    return "'" + w.label + "', index " + std::to_string(w.index);
}

// How --delimiter names a delimiter.
std::string delimiterOption(char d) { return d == '\t' ? "tab" : d == ' ' ? "space" : std::string(1, d); }

// When the header line split by another delimiter has the column `name`:
// the delimiter seems wrong, and which one works. "" otherwise.
std::string wrongDelimiterHint(const std::vector<CsvField>& fields, char used, bool given, const std::string& name) {
    std::string line;
    for (size_t k = 0; k < fields.size(); ++k) line += (k ? std::string(1, used) : std::string()) + fields[k].text;
    for (const char d : {',', ';', '\t', ' '}) {
        if (d == used) continue;
        size_t start = 0;
        for (;;) {
            const size_t end = std::min(line.find(d, start), line.size());
            std::string field = line.substr(start, end - start);
            while (!field.empty() && (field.front() == ' ' || field.front() == '"')) field.erase(0, 1);
            while (!field.empty() && (field.back() == ' ' || field.back() == '"' || field.back() == '\r')) field.pop_back();
            if (field == name)
                return std::string(". The delimiter seems wrong: the line was split at '") + delimiterOption(used) + "'" +
                       (given ? " (--delimiter " + delimiterOption(used) + ")" : " (detected)") +
                       ", and split at '" + delimiterOption(d) + "' it has the column: give --delimiter " + delimiterOption(d);
            if (end >= line.size()) break;
            start = end + 1;
        }
    }
    return "";
}

}  // namespace

PointColumns parsePointColumns(const std::string& spec) {
    PointColumns cols;
    size_t start = 0;
    while (start <= spec.size()) {
        size_t end = spec.find(',', start);
        if (end == std::string::npos) end = spec.size();
        const std::string item = trimmed(std::string_view(spec).substr(start, end - start));
        start = end + 1;
        if (item.empty()) {
            if (end == spec.size()) break;
            continue;
        }
        const size_t eq = item.find('=');
        if (eq == std::string::npos)
            throw InputError("point columns: expected key=column in " + quoteForMessage(item) +
                             " (e.g. \"x=lon,y=lat,w=count\" or \"x=0,y=1\")");
        const std::string key = trimmed(std::string_view(item).substr(0, eq));
        const std::string value = trimmed(std::string_view(item).substr(eq + 1));
        ColumnRef* ref = nullptr;
        if (key == "x") ref = &cols.x;
        else if (key == "y") ref = &cols.y;
        else if (key == "w" || key == "weight") ref = &cols.weight;
        else
            throw InputError("point columns: unknown key " + quoteForMessage(key) + "; expected x, y or w");
        if (ref->isSet()) throw InputError("point columns: " + key + " is given twice");
        if (value.empty()) throw InputError("point columns: " + key + "= needs a column name or index");
        int64_t index = 0;
        if (parseWholeNumber(value, kMaxColumnIndex, index)) ref->index = int(index);
        else ref->name = value;
        if (end == spec.size()) break;
    }
    if (!cols.x.isSet() || !cols.y.isSet())
        throw InputError("point columns: both x and y are required (e.g. \"x=lon,y=lat\")");
    return cols;
}

PointTable parsePointsCsv(std::string_view text, const std::string& path, const PointColumns& cols) {
    refuseUtf16Text(text.substr(0, 4096), path);
    checkCsvDelimiter(cols.delimiter);
    if (!cols.x.isSet() || !cols.y.isSet()) throw InputError("point columns: both x and y are required");
    const char delim = cols.delimiter != 0 ? cols.delimiter : detectCsvDelimiter(text);
    CsvTokenizer tokenizer(text, delim, path);
    std::vector<CsvField> fields;

    std::vector<Resolved> wanted;
    wanted.push_back({cols.x.name.empty() ? cols.x.index : -1, "", "x"});
    wanted.push_back({cols.y.name.empty() ? cols.y.index : -1, "", "y"});
    const bool weighted = cols.weight.isSet();
    if (weighted) wanted.push_back({cols.weight.name.empty() ? cols.weight.index : -1, "", "weight"});
    const ColumnRef* refs[3] = {&cols.x, &cols.y, &cols.weight};
    const bool by_name = std::any_of(refs, refs + wanted.size(), [](const ColumnRef* r) { return !r->name.empty(); });

    PointTable table;
    table.source = path;
    bool first = true;
    int header_line = 0;
    size_t needed_fields = 0;

    while (tokenizer.next(fields)) {
        if (fields.empty()) continue;
        const int line = tokenizer.line();
        if (first) {
            first = false;
            bool header = false;
            if (by_name) {
                header = true;
                for (size_t k = 0; k < wanted.size(); ++k) {
                    if (refs[k]->name.empty()) continue;
                    const auto it = std::find_if(fields.begin(), fields.end(),
                                                 [&](const CsvField& f) { return f.text == refs[k]->name; });
                    if (it == fields.end())
                        throw InputError(path, line, 0,
                                         "no column named " + quoteForMessage(refs[k]->name) + " for " +
                                             wanted[k].role + " in the header line; it has: " + headerList(fields) +
                                             wrongDelimiterHint(fields, delim, cols.delimiter != 0, refs[k]->name));
                    wanted[k].index = int(it - fields.begin());
                }
            } else {
                // Header if none of the chosen fields is a number.
                header = true;
                for (const Resolved& w : wanted) {
                    if (size_t(w.index) >= fields.size()) {
                        header = false;  // reported below as a missing field
                        break;
                    }
                    double v = 0.0;
                    const NumberField kind = parseNumberField(fields[size_t(w.index)].text, v);
                    if (kind != NumberField::NotNumber) header = false;
                }
            }
            for (size_t k = 0; k < wanted.size(); ++k) {
                const int idx = wanted[k].index;
                const bool has_name = header && size_t(idx) < fields.size() && !fields[size_t(idx)].text.empty();
                wanted[k].label = has_name ? fields[size_t(idx)].text : "column " + std::to_string(idx);
                needed_fields = std::max(needed_fields, size_t(idx) + 1);
            }
            table.x_name = wanted[0].label;
            table.y_name = wanted[1].label;
            if (weighted) table.weight_name = wanted[2].label;
            if (header) {
                header_line = line;
                continue;
            }
        }
        if (fields.size() < needed_fields) {
            for (const Resolved& w : wanted)
                if (size_t(w.index) >= fields.size())
                    throw InputError(path, line, 0,
                                     "line has " + std::to_string(fields.size()) + " fields; " + w.role + " (" +
                                         columnLabel(w) + ") is missing");
        }
        if (int64_t(table.x.size()) >= kMaxPoints)
            throw InputError(path, line, 0, "more than " + std::to_string(kMaxPoints) + " points");
        double xy[2] = {0.0, 0.0};
        for (int k = 0; k < 2; ++k) {
            const CsvField& f = fields[size_t(wanted[size_t(k)].index)];
            const NumberField kind = parseNumberField(f.text, xy[k]);
            if (kind == NumberField::Number) continue;
            const std::string which = std::string(wanted[size_t(k)].role) + " (" + wanted[size_t(k)].label + ")";
            if (kind == NumberField::NoData)
                throw InputError(path, f.line, f.column,
                                 which + " is " + (f.text.empty() ? std::string("empty") : quoteForMessage(f.text)) +
                                     "; every point needs a position (fix or remove the line)");
            throw InputError(path, f.line, f.column, which + ": " + badNumberMessage(kind, f.text, delim));
        }
        table.x.push_back(xy[0]);
        table.y.push_back(xy[1]);
        if (weighted) {
            const CsvField& f = fields[size_t(wanted[2].index)];
            double w = 0.0;
            const NumberField kind = parseNumberField(f.text, w);
            if (kind == NumberField::NotNumber || kind == NumberField::Infinite)
                throw InputError(path, f.line, f.column,
                                 "weight (" + wanted[2].label + "): " + badNumberMessage(kind, f.text, delim));
            if (kind == NumberField::NoData) ++table.missing_weights;
            table.weight.push_back(w);
        }
    }
    if (first) throw InputError(path, 0, 0, "is empty; expected a table of points");
    if (table.x.empty()) throw InputError(path, header_line, 0, "has a header line but no data lines");
    return table;
}

PointTable readPointsCsv(const std::string& path, const PointColumns& cols) {
    checkCsvDelimiter(cols.delimiter);
    const std::string bytes = readFileBytes(path, kMaxInputFileBytes);
    return parsePointsCsv(bytes, path, cols);
}

}  // namespace tsf
