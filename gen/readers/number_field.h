// Parsing one numeric field of a text file (CSV cell, PGM sample, ESRI value).
//
// Locale-independent: the decimal separator is always '.', whatever the
// user's locale says. Accepted: optional sign ('+' or '-'), decimal or
// scientific notation ("12", "-0.5", "1e-3", ".5", "5."). Not accepted: hex,
// thousands separators, decimal commas, trailing text ("3m").
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace tsf {

enum class NumberField {
    Number,     ///< a finite number; value set
    NoData,     ///< empty, "-", "nan", "NA", "N/A" (any case) or another NaN spelling; value = NaN
    NotNumber,  ///< text that is not a number
    Infinite,   ///< "inf", "Infinity", or a number too large for a double ("1e999")
};

/// Classifies `text` (surrounding spaces/tabs ignored) and sets `value`.
/// Numbers too small for a double ("1e-400") underflow to 0 or a subnormal.
NumberField parseNumberField(std::string_view text, double& value);

/// Like parseNumberField but empty and NaN spellings are NotNumber: for
/// formats where a missing value has no textual form (PGM, ESRI grids).
NumberField parseStrictNumber(std::string_view text, double& value);

/// A whole number written as decimal digits only (no sign, no point), at
/// most `max_value`. Returns false otherwise (out untouched).
bool parseWholeNumber(std::string_view text, int64_t max_value, int64_t& out);

/// A one-line description of why `text` (classified as NotNumber or
/// Infinite) is not a value, for InputError: "expected a number, found
/// \"1,5\" (decimal comma? write 1.5)". `delimiter` (0 = none) is the field
/// delimiter of the file, used for the decimal-comma hint.
std::string badNumberMessage(NumberField kind, std::string_view text, char delimiter = 0);

/// Shortens `text` for an error message: at most `max_chars` bytes, with
/// "..." appended when cut, and control characters shown as '?'.
std::string quoteForMessage(std::string_view text, size_t max_chars = 40);

}  // namespace tsf
