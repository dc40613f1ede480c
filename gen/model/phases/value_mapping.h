// The value mapping of a field: which value stands at the floor (the
// baseline), which at full height, and how values between them rise
// (docs/model.md, "Heights").
#pragma once

#include <string>
#include <vector>

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"

namespace tsf {

/// The mapping the parameters ask for over the field's values. Throws
/// InputError for an infinite value, a field without data, or a baseline
/// and value at full height that contradict each other or the data (an
/// error, not a flat block reported as a constant field). Adds notes for a
/// constant field and for values below the baseline or above full height.
ValueMapping resolveValueMapping(const HexField& field, const SceneParams& p, std::vector<std::string>& notes);

}  // namespace tsf
