#include "gen/model/features/felt_heights.h"

#include <algorithm>
#include <cmath>

#include "gen/util/number_format.h"

namespace tsf {

int levelsReadWithoutScale(double range_mm) {
    if (!(range_mm > 0)) return 1;
    const int steps = int(std::floor(range_mm / kLevelStepMm + 1e-9));
    return std::clamp(steps + 1, 1, kLevelsReadWithoutScale);
}

std::string feltLevelsSentence(double range_mm, bool has_scale) {
    const int levels = levelsReadWithoutScale(range_mm);
    const std::string count = levels == 1 ? "one height" : levels == 2 ? "two heights" : "about three heights";
    return "By touch alone a reader tells " + count + " apart (" + (levels == 3 ? "low, middle, high; " : "") +
           "Wabinski et al. 2022, on FDM prints); finer differences are read by comparing "
           "neighbours, which feel different from " + formatSignificant(kFeltHeightStepMm, 2) + " mm apart" +
           (has_scale ? ", or against the scale." : ".");
}

}  // namespace tsf
