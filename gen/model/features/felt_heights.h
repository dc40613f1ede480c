// Heights as a fingertip reads them on a print: the perceptual numbers
// behind the summary's and the key's words on heights, and behind the
// tactile checks (verify/tactile.h prints them with their sources).
//
// Detecting a step is not telling levels apart: a fingertip finds a 1 um
// edge on a smooth surface, but readers of 3D-printed maps compare heights
// in steps of about half a millimetre, and tell about three levels apart by
// touch alone.
// Units: millimetres.
#pragma once

#include <string>

namespace tsf {

/// Smallest height step between neighbours a reader uses to compare them,
/// mm: printdisability.org's guidance for 3D-printed tactile graphics
/// (>= 0.5 mm to detect, >= 1 mm for what matters); Wabinski et al. 2022
/// used steps of 0.56 mm.
inline constexpr double kFeltHeightStepMm = 0.5;

/// The step of Wabinski et al.'s three levels on FDM maps, mm (0.56, 1.12, 1.68).
inline constexpr double kLevelStepMm = 0.56;

/// Heights a reader identifies by touch alone, without a scale to compare
/// with: three worked on FDM prints (Wabinski, Mościcka, Touya, PLOS ONE
/// 17(3):e0264564, 2022).
inline constexpr int kLevelsReadWithoutScale = 3;

/// How many heights a reader tells apart without the scale on a model whose
/// heights span `range_mm` above the floor: at most kLevelsReadWithoutScale,
/// fewer when the range holds fewer steps of kLevelStepMm (the floor counts).
int levelsReadWithoutScale(double range_mm);

/// One sentence for the summary and the key: how many levels a reader
/// tells apart by touch alone, and how finer differences are read.
std::string feltLevelsSentence(double range_mm, bool has_scale);

}  // namespace tsf
