// Units spelled out for a reader: "degC" is read aloud as "deg c" and
// embossed letter by letter; "degrees Celsius" is what a reader needs.
//
// Units come from the file (a GeoTIFF band's unit type, a NetCDF
// variable's CF "units" attribute, which follows UDUNITS) or from --units.
// A small table of common symbols and names (lengths, times, masses,
// temperatures, pressure, power, percent) is combined the UDUNITS way:
// terms separated by spaces, '.' or '*', powers written m2, m^2, m**2 or
// m-1, and '/' putting what follows below the line:
//   "kg m-2 s-1" -> "kilograms per square metre per second"
//   "mm/day"     -> "millimetres per day"
// A string with any term the table does not know is the fallback: it is
// returned as given (a user's "airports", a file's "W/m^2/sr" with a
// steradian), so nothing is ever made up.
#pragma once

#include <string>

namespace tsf {

struct UnitWords {
    std::string singular;  ///< after the number 1: "degree Celsius"
    std::string plural;    ///< after any other number: "degrees Celsius"
    bool spelled = false;  ///< false: the text as given (unknown terms, or no units)
};

/// The words for `units`; empty words for "" and for "1" (CF's
/// dimensionless unit).
UnitWords unitWords(const std::string& units);

}  // namespace tsf
