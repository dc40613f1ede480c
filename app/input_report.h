// What `tsf info` says about an input file before it became hexagons: the
// reader's detections (delimiter, decimal comma, header, index column,
// no-data value) and the raw values' range, for people and (--json) programs.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "gen/field/field_input.h"

namespace tsf::cli {

/// Lines "  read      ...", "  data      ..." (the file's own description
/// of the values, units and step, when it gives them) and "  values    ..."
/// (raw min, max, mean, no-data count).
std::string formatFieldInput(const FieldInput& in);

/// {"kind", "cols", "rows", "values", "nodata_values", "min", "max", "mean"
/// (null when no value has data), "detected": {fact name: value},
/// "description", "variable", "step", "units" (the file's words; "" when none)}.
nlohmann::json fieldInputJson(const FieldInput& in);

}  // namespace tsf::cli
