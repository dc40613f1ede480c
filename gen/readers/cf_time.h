// CF time coordinates (the "units" and "calendar" attributes of a time
// variable, CF Conventions 4.4) as dates, for saying which time step a band
// of a NetCDF file is. Pure text and arithmetic: no GDAL, fuzzed
// (tests/fuzz/cf_time_fuzzer.cpp) because the strings come from the file.
#pragma once

#include <string>

namespace tsf {

/// The date of `value` in `units` ("days since 1850-01-01", "hours since
/// 2000-01-01 00:00:00"; days, hours, minutes or seconds), "YYYY-MM-DD" or
/// "YYYY-MM-DD HH:MM" when not at midnight, on the proleptic Gregorian
/// calendar. "" for any other calendar (noleap, 360_day, julian: the number
/// is then said as it is), units it does not know, or a date beyond +-3
/// million years.
std::string cfDate(const std::string& units, const std::string& calendar, double value);

/// A band's step, short, from its description ("time = 59 days since
/// 1850-01-01 (1850-03-01)"): the date in the last parentheses when there is
/// one, else the description as it is.
std::string stepLabel(const std::string& description);

}  // namespace tsf
