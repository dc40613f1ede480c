// --class-names and --class-groups. See class_labels.h.
#include "gen/readers/class_labels.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>

#include "gen/readers/csv_tokenizer.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

bool parseNumber(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    out = std::strtod(text.c_str(), &end);
    return end && *end == '\0' && std::isfinite(out);
}

std::string trimmed(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t"), b = s.find_last_not_of(" \t");
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

}  // namespace

std::vector<RasterClass> parseClassNames(std::string_view text, const std::string& path) {
    CsvTokenizer csv(text, detectCsvDelimiter(text), path);
    std::vector<CsvField> fields;
    std::vector<RasterClass> out;
    bool first = true;
    while (csv.next(fields)) {
        if (fields.empty() || (fields.size() == 1 && fields[0].text.empty())) continue;
        double code = 0;
        if (!parseNumber(fields[0].text, code)) {
            if (first) {  // a header: code,name
                first = false;
                continue;
            }
            throw InputError(path, fields[0].line, fields[0].column,
                             "--class-names: '" + fields[0].text + "' is not a class code (a number); each line is code,name");
        }
        first = false;
        if (fields.size() < 2 || fields[1].text.empty())
            throw InputError(path, fields[0].line, fields[0].column,
                             "--class-names: class " + formatSignificant(code) + " has no name; each line is code,name");
        std::string name = fields[1].text;
        for (size_t k = 2; k < fields.size(); ++k) name += ", " + fields[k].text;  // a name with unquoted commas
        for (const RasterClass& c : out)
            if (c.code == code)
                throw InputError(path, fields[0].line, fields[0].column,
                                 "--class-names: class " + formatSignificant(code) + " is named twice");
        out.push_back({code, name});
    }
    if (out.empty()) throw InputError(path, 0, 0, "--class-names: the file names no class (each line is code,name)");
    std::sort(out.begin(), out.end(), [](const RasterClass& a, const RasterClass& b) { return a.code < b.code; });
    return out;
}

std::vector<ClassGroup> parseClassGroups(const std::string& spec) {
    std::vector<ClassGroup> out;
    size_t at = 0;
    while (at <= spec.size()) {
        size_t end = spec.find_first_of(";,", at);
        if (end == std::string::npos) end = spec.size();
        const std::string entry = trimmed(spec.substr(at, end - at));
        at = end + 1;
        if (entry.empty()) continue;
        const size_t eq = entry.find('=');
        if (eq == std::string::npos)
            throw InputError("--class-groups: '" + entry + "' has no '='; give LO-HI=NAME or CODE=NAME, e.g. 21-24=Developed");
        const std::string codes = trimmed(entry.substr(0, eq)), name = trimmed(entry.substr(eq + 1));
        if (name.empty()) throw InputError("--class-groups: '" + entry + "' gives no name after '='");
        ClassGroup g;
        g.name = name;
        // The range's '-' is one after a digit (so "-2--1" is -2 to -1).
        size_t dash = std::string::npos;
        for (size_t k = 1; k < codes.size(); ++k)
            if (codes[k] == '-' && (std::isdigit(static_cast<unsigned char>(codes[k - 1])) || codes[k - 1] == '.')) {
                dash = k;
                break;
            }
        const std::string lo = trimmed(codes.substr(0, dash)), hi = dash == std::string::npos ? lo : trimmed(codes.substr(dash + 1));
        if (!parseNumber(lo, g.lo) || !parseNumber(hi, g.hi))
            throw InputError("--class-groups: '" + codes + "' in '" + entry + "' is not a code or a range of codes (e.g. 21-24)");
        if (g.lo > g.hi) throw InputError("--class-groups: the range " + codes + " runs downwards; give the lower code first");
        for (const ClassGroup& o : out)
            if (g.lo <= o.hi && o.lo <= g.hi)
                throw InputError("--class-groups: " + codes + " overlaps " + formatSignificant(o.lo) + "-" +
                                 formatSignificant(o.hi) + "; a class belongs to one group");
        out.push_back(g);
    }
    if (out.empty()) throw InputError("--class-groups: no group given (e.g. 21-24=Developed;41-43=Forest)");
    return out;
}

std::vector<RasterClass> mergeClassNames(const std::vector<RasterClass>& file, const std::vector<RasterClass>& names) {
    std::vector<RasterClass> out = names;
    for (const RasterClass& c : file)
        if (std::none_of(names.begin(), names.end(), [&](const RasterClass& n) { return n.code == c.code; })) out.push_back(c);
    std::sort(out.begin(), out.end(), [](const RasterClass& a, const RasterClass& b) { return a.code < b.code; });
    return out;
}

int64_t applyClassGroups(std::vector<double>& values, std::vector<RasterClass>& classes,
                         const std::vector<ClassGroup>& groups) {
    int64_t changed = 0;
    for (double& v : values) {
        if (std::isnan(v)) continue;
        for (const ClassGroup& g : groups)
            if (v >= g.lo && v <= g.hi) {
                changed += v != g.lo;
                v = g.lo;
                break;
            }
    }
    std::vector<RasterClass> kept;
    for (const RasterClass& c : classes)
        if (std::none_of(groups.begin(), groups.end(), [&](const ClassGroup& g) { return c.code >= g.lo && c.code <= g.hi; }))
            kept.push_back(c);
    for (const ClassGroup& g : groups) kept.push_back({g.lo, g.name});
    std::sort(kept.begin(), kept.end(), [](const RasterClass& a, const RasterClass& b) { return a.code < b.code; });
    classes.swap(kept);
    return changed;
}

}  // namespace tsf
