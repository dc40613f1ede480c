// The top-level variables a .scad file assigns, read from its text, so that
// `tsf render -D name=value` can refuse a name the file does not have
// (OpenSCAD itself would add the variable silently and render the model
// unchanged).
#pragma once

#include <string>
#include <vector>

namespace tsf {

/// Names assigned at the top level of a .scad text (`name = ...;` outside any
/// module, function, brace, bracket or parenthesis), in order of first
/// appearance, without repeats. Comments and strings are skipped; `==` is not
/// an assignment. Text that is not valid OpenSCAD gives whatever names were
/// recognised before the confusion (never throws).
std::vector<std::string> scadTopLevelVariables(const std::string& scad_text);

/// True when the text has an include <...> statement (its variables come
/// from another file, so the list above is incomplete).
bool scadHasInclude(const std::string& scad_text);

}  // namespace tsf
