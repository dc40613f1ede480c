// Units spelled out. See unit_words.h.
#include "gen/key/unit_words.h"

#include <cctype>
#include <cstdlib>
#include <vector>

namespace tsf {
namespace {

struct Named {
    const char* symbol;
    const char* singular;
    const char* plural;
};

// Whole unit strings that are one name (temperatures spelled many ways).
constexpr Named kWhole[] = {
    {"degC", "degree Celsius", "degrees Celsius"},         {"degree_C", "degree Celsius", "degrees Celsius"},
    {"degrees_C", "degree Celsius", "degrees Celsius"},     {"degree_Celsius", "degree Celsius", "degrees Celsius"},
    {"degrees_Celsius", "degree Celsius", "degrees Celsius"}, {"deg C", "degree Celsius", "degrees Celsius"},
    {"\xC2\xB0" "C", "degree Celsius", "degrees Celsius"},  {"Celsius", "degree Celsius", "degrees Celsius"},
    {"celsius", "degree Celsius", "degrees Celsius"},       {"degF", "degree Fahrenheit", "degrees Fahrenheit"},
    {"degree_F", "degree Fahrenheit", "degrees Fahrenheit"}, {"\xC2\xB0" "F", "degree Fahrenheit", "degrees Fahrenheit"},
    {"degrees", "degree", "degrees"},                       {"degree", "degree", "degrees"},
    {"percent", "percent", "percent"},                      {"%", "percent", "percent"},
    {"ppm", "part per million", "parts per million"},       {"ppb", "part per billion", "parts per billion"},
};

// The terms of a compound unit, by symbol and by name.
constexpr Named kTerms[] = {
    {"m", "metre", "metres"},           {"km", "kilometre", "kilometres"},   {"cm", "centimetre", "centimetres"},
    {"mm", "millimetre", "millimetres"}, {"um", "micrometre", "micrometres"}, {"\xC2\xB5m", "micrometre", "micrometres"},
    {"ft", "foot", "feet"},             {"mi", "mile", "miles"},             {"in", "inch", "inches"},
    {"s", "second", "seconds"},         {"sec", "second", "seconds"},        {"min", "minute", "minutes"},
    {"h", "hour", "hours"},             {"hr", "hour", "hours"},             {"d", "day", "days"},
    {"day", "day", "days"},             {"days", "day", "days"},             {"month", "month", "months"},
    {"mon", "month", "months"},         {"yr", "year", "years"},             {"year", "year", "years"},
    {"kg", "kilogram", "kilograms"},    {"g", "gram", "grams"},              {"mg", "milligram", "milligrams"},
    {"t", "tonne", "tonnes"},           {"K", "kelvin", "kelvin"},           {"Pa", "pascal", "pascals"},
    {"hPa", "hectopascal", "hectopascals"}, {"kPa", "kilopascal", "kilopascals"}, {"mbar", "millibar", "millibars"},
    {"W", "watt", "watts"},             {"kW", "kilowatt", "kilowatts"},     {"J", "joule", "joules"},
    {"N", "newton", "newtons"},         {"mol", "mole", "moles"},            {"L", "litre", "litres"},
    {"l", "litre", "litres"},           {"ha", "hectare", "hectares"},       {"dB", "decibel", "decibels"},
    {"metre", "metre", "metres"},       {"metres", "metre", "metres"},       {"meter", "metre", "metres"},
    {"meters", "metre", "metres"},      {"second", "second", "seconds"},     {"seconds", "second", "seconds"},
    {"hour", "hour", "hours"},          {"hours", "hour", "hours"},          {"kelvin", "kelvin", "kelvin"},
    {"people", "person", "people"},     {"persons", "person", "persons"},
};

const Named* find(const Named* begin, const Named* end, const std::string& symbol) {
    for (const Named* n = begin; n != end; ++n)
        if (symbol == n->symbol) return n;
    return nullptr;
}

std::string powerWord(int power, const std::string& name) {
    if (power == 1) return name;
    if (power == 2) return "square " + name;
    if (power == 3) return "cubic " + name;
    return name + " to the power of " + std::to_string(power);
}

struct Term {
    const Named* name;
    int power;  ///< negative: below the line
};

/// Splits "m-2" / "m^2" / "m**-2" / "m2" into a term; false for an unknown symbol or a bad power.
bool parseTerm(std::string text, bool below, std::vector<Term>& out) {
    if (const size_t at = text.find("**"); at != std::string::npos) text.replace(at, 2, "^");
    size_t digits = text.size();
    while (digits > 0 && (std::isdigit(static_cast<unsigned char>(text[digits - 1])) || text[digits - 1] == '-' ||
                          text[digits - 1] == '+'))
        --digits;
    std::string symbol = text.substr(0, digits), power_text = text.substr(digits);
    if (!symbol.empty() && symbol.back() == '^') symbol.pop_back();
    int power = 1;
    if (!power_text.empty()) {
        char* end = nullptr;
        const long p = std::strtol(power_text.c_str(), &end, 10);
        if (*end != '\0' || p == 0 || p < -9 || p > 9) return false;
        power = int(p);
    }
    const Named* n = find(std::begin(kTerms), std::end(kTerms), symbol);
    if (!n) return false;
    out.push_back({n, below ? -power : power});
    return true;
}

}  // namespace

UnitWords unitWords(const std::string& units) {
    const size_t a = units.find_first_not_of(' '), b = units.find_last_not_of(' ');
    const std::string u = a == std::string::npos ? "" : units.substr(a, b - a + 1);
    if (u.empty() || u == "1") return {"", "", true};
    if (const Named* n = find(std::begin(kWhole), std::end(kWhole), u)) return {n->singular, n->plural, true};
    // Terms: ' ', '.' and '*' separate them; each '/' puts the rest below the line.
    std::vector<Term> terms;
    bool below = false;
    std::string token;
    auto flush = [&]() {
        if (token.empty()) return true;
        const bool ok = parseTerm(token, below, terms);
        token.clear();
        return ok;
    };
    for (size_t k = 0; k <= u.size(); ++k) {
        const char c = k < u.size() ? u[k] : ' ';
        if (c == ' ' || c == '.' || c == '*' || c == '/') {
            // '*' of "**" is part of a power.
            if (c == '*' && k + 1 < u.size() && u[k + 1] == '*') {
                token += "**";
                ++k;
                continue;
            }
            if (!flush()) return {u, u, false};
            if (c == '/') below = true;
        } else {
            token += c;
        }
    }
    if (terms.empty()) return {u, u, false};
    // Above the line: "kilowatt hours" (the last term takes the plural);
    // below: "per square metre per second".
    std::vector<const Term*> above, under;
    for (const Term& t : terms) (t.power > 0 ? above : under).push_back(&t);
    UnitWords w{"", "", true};
    for (size_t k = 0; k < above.size(); ++k) {
        const bool last = k + 1 == above.size();
        const std::string sep = k ? " " : "";
        w.singular += sep + powerWord(above[k]->power, above[k]->name->singular);
        w.plural += sep + powerWord(above[k]->power, last ? above[k]->name->plural : above[k]->name->singular);
    }
    for (const Term* t : under) {
        const std::string per = std::string(w.singular.empty() ? "" : " ") + "per " + powerWord(-t->power, t->name->singular);
        w.singular += per;
        w.plural += per;
    }
    return w;
}

}  // namespace tsf
