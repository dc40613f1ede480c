// Numbers as text, for every message, report, summary and file tsf writes:
// one formatter, locale-independent (std::to_chars never writes a decimal
// comma), with the precision stated at each use.
//
//   formatSignificant(v, n)  printf's %.ng: up to n significant digits,
//                            no trailing zeros ("0.25", "1.5e-05")
//   formatFixed(v, n)        printf's %.nf: n decimals ("12.700")
//   formatShortest(v)        the shortest text that reads back to exactly v
//                            (JSON, .scad values, golden tables)
// NaN is "nan" and infinities "inf" / "-inf" in all three.
#pragma once

#include <string>

namespace tsf {

/// Significant digits of a measured length or value in a message a person reads.
inline constexpr int kMessageDigits = 6;

std::string formatSignificant(double v, int digits = kMessageDigits);
std::string formatFixed(double v, int decimals);
std::string formatShortest(double v);

}  // namespace tsf
