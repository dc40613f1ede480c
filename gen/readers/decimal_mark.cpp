#include "gen/readers/decimal_mark.h"

#include <string>

namespace tsf {
namespace {

// "1,5" -> "1.5" when the text has exactly one comma; "" otherwise.
std::string commaToPoint(std::string_view text) {
    const size_t comma = text.find(',');
    if (comma == std::string_view::npos || text.find(',', comma + 1) != std::string_view::npos) return {};
    std::string s(text);
    s[comma] = '.';
    return s;
}

}  // namespace

NumberField parseWithDecimalMark(std::string_view text, DecimalMark& mark, double& value) {
    if (mark == DecimalMark::Point) return parseNumberField(text, value);
    const bool has_point = text.find('.') != std::string_view::npos;
    if (mark == DecimalMark::Comma) {
        if (has_point) return NumberField::NotNumber;
        const std::string fixed = commaToPoint(text);
        return parseNumberField(fixed.empty() ? text : std::string_view(fixed), value);
    }
    // Detect: the first value that shows a mark decides.
    const std::string fixed = has_point ? std::string() : commaToPoint(text);
    if (!fixed.empty()) {
        const NumberField kind = parseNumberField(fixed, value);
        if (kind == NumberField::Number) mark = DecimalMark::Comma;
        return kind == NumberField::Number ? kind : parseNumberField(text, value);
    }
    const NumberField kind = parseNumberField(text, value);
    if (kind == NumberField::Number && has_point) mark = DecimalMark::Point;
    return kind;
}

std::string badValueMessage(NumberField kind, std::string_view text, DecimalMark mark, char delimiter) {
    if (mark == DecimalMark::Comma && kind == NumberField::NotNumber && text.find('.') != std::string_view::npos)
        return "found " + quoteForMessage(text) +
               ": a decimal point in a table read with decimal commas (thousands separators are not "
               "supported; export the numbers without them)";
    return badNumberMessage(kind, text, delimiter);
}

const char* decimalMarkName(DecimalMark mark) {
    switch (mark) {
        case DecimalMark::Comma: return "comma";
        case DecimalMark::Point: return "point";
        default: return "detect";
    }
}

}  // namespace tsf
