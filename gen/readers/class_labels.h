// Class names and groups a reader gives a class map from the command line:
// --class-names FILE (a CSV of code,name) names the classes a file leaves
// unnamed (or renames them), and --class-groups "21-24=Developed;41-43=Forest"
// joins several codes into one class, so a model of many land-cover codes
// has the few classes a reader needs.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gen/field/raster.h"

namespace tsf {

/// One group of --class-groups: the codes lo..hi (whole range, inclusive)
/// become one class, coded lo, named `name`.
struct ClassGroup {
    double lo = 0, hi = 0;
    std::string name;
};

/// Parses a class-names CSV: one class a record, its code (a number) then
/// its name; a first record whose code is not a number is a header and is
/// skipped; blank lines are skipped. The delimiter is detected (csv_tokenizer.h).
/// Errors (InputError naming `path`, line and column): a code that is not a
/// number, a missing or empty name, a code given twice, no class at all.
std::vector<RasterClass> parseClassNames(std::string_view text, const std::string& path);

/// Parses --class-groups: entries "LO-HI=NAME" or "CODE=NAME" separated by
/// ';' (or ','); codes are numbers (negative ones allowed: "-2--1=Ice").
/// Errors (InputError naming the option and the entry): an entry without
/// '=', an empty name, a code that is not a number, LO above HI, two groups
/// that overlap.
std::vector<ClassGroup> parseClassGroups(const std::string& spec);

/// Names: the file's classes with `names` laid over them (a code in both
/// takes the name from `names`), by code.
std::vector<RasterClass> mergeClassNames(const std::vector<RasterClass>& file, const std::vector<RasterClass>& names);

/// Joins every value in a group into the group's class (its code lo) and
/// names it; the classes the groups swallow lose their own names. Returns how
/// many values changed. NaN stays NaN.
int64_t applyClassGroups(std::vector<double>& values, std::vector<RasterClass>& classes,
                         const std::vector<ClassGroup>& groups);

}  // namespace tsf
