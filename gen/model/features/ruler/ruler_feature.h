// The edge ruler's entry in the feature registry (gen/model/feature.h).
#pragma once

#include "gen/model/feature.h"

namespace tsf {

const Feature& rulerFeature();

}  // namespace tsf
