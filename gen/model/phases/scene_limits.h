// What buildScene accepts: the parameters checked before anything is built,
// and the limits that keep every lattice coordinate and height comfortably
// inside int64 arithmetic and the model inside what a printer can make.
#pragma once

#include <cstdint>

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"

namespace tsf {

inline constexpr int32_t kMaxGridSide = 100000;
inline constexpr double kMinPitchMm = 0.05;      // 50 xy snap steps: snapping cannot distort a hexagon
inline constexpr double kMaxModelMm = 100000.0;  // 100 m: anything larger is a unit mistake
inline constexpr double kMinSnapMm = 1e-6;
inline constexpr double kMaxSnapMm = 1.0;

/// Throws InputError for a field buildScene cannot use (empty, too large)
/// or parameters out of range or contradicting each other (--halves
/// without --mirror or with --tilt), naming the option and the value.
void checkSceneParams(const HexField& field, const SceneParams& p);

}  // namespace tsf
