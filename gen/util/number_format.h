// Numbers as text, for every message, report, summary and file tsf writes:
// one formatter, locale-independent (std::to_chars never writes a decimal
// comma), with the precision stated at each use.
//
//   formatSignificant(v, n)  printf's %.ng: up to n significant digits,
//                            no trailing zeros ("0.25", "1.5e-05")
//   formatFixed(v, n)        printf's %.nf: n decimals ("12.700")
//   formatShortest(v)        the shortest text that reads back to exactly v
//                            (JSON, .scad values, golden tables)
//   formatForReader(v, n)    for a person listening to a screen reader or
//                            reading braille: up to n significant digits,
//                            never e-notation, thousands grouped by commas
//                            ("1,680,000", "0.0000152")
// NaN is "nan" and infinities "inf" / "-inf" in all three.
#pragma once

#include <string>

namespace tsf {

/// Significant digits of a measured length or value in a message a person reads.
inline constexpr int kMessageDigits = 6;

std::string formatSignificant(double v, int digits = kMessageDigits);
std::string formatFixed(double v, int decimals);
std::string formatShortest(double v);

/// A number for the key and the summary's reader. Up to `digits`
/// significant digits, no trailing zeros, written out in full: e-notation
/// ("1.5e-05") is read aloud as letters and embossed as a letter between
/// two numbers. Whole parts of 10,000 and more are grouped in threes by
/// commas: braille (UEB and EBAE alike) keeps a comma inside one number,
/// where a space would start a new number, and screen readers say
/// "1,680,000" as one million six hundred eighty thousand. Magnitudes from
/// 10^15 up and below 10^-6 (fixed digits a reader cannot count) are
/// written "2.5 times ten to the power of minus 9". NaN and infinities as
/// formatSignificant.
std::string formatForReader(double v, int digits = 4);

}  // namespace tsf
