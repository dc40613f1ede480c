// The braille legend's entry in the feature registry (gen/model/feature.h).
#pragma once

#include "gen/model/feature.h"

namespace tsf {

const Feature& legendFeature();

}  // namespace tsf
