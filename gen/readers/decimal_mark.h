// Decimal mark of a text table: '.' everywhere tsf writes, ',' in the CSV
// files spreadsheets export in many European locales ("1,5;2,25").
//
// A table has one decimal mark. When it is not given it is decided by the
// first value that shows one: "1,5" (a single comma between digits, in a
// file whose delimiter is not a comma) makes it a comma, "1.5" a point;
// values without either ("12", "NA") decide nothing. Thousands separators are
// never accepted: with a decimal comma, a value with a point ("1.234,5") is
// an error, and with a decimal point "1,5" is (badNumberMessage suggests the
// fix).
#pragma once

#include <string>
#include <string_view>

#include "gen/readers/number_field.h"

namespace tsf {

enum class DecimalMark { Detect, Point, Comma };

/// Parses one field like parseNumberField, reading a decimal comma when
/// `mark` is Comma. With Detect, a field that shows a decimal mark sets
/// `mark` to Point or Comma. Only call with Detect or Comma when the field
/// delimiter is not a comma.
NumberField parseWithDecimalMark(std::string_view text, DecimalMark& mark, double& value);

/// Why `text` (NotNumber or Infinite from parseWithDecimalMark) is not a
/// value, for InputError; names a decimal point in a decimal-comma table.
std::string badValueMessage(NumberField kind, std::string_view text, DecimalMark mark, char delimiter);

/// "comma", "point" or "detect".
const char* decimalMarkName(DecimalMark mark);

}  // namespace tsf
