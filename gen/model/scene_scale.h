// The tactile scale as the Scene holds it: data only. Where it comes from is
// gen/model/features/scale.h (placeScale).
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace tsf {

/// What the user asks for (tsf gen --scale, --scale-step), in
/// SceneParams::requests: none there, no scale.
struct ScaleRequest {
    std::optional<double> step;  ///< data units; none = chosen by chooseScaleStep
};

struct ScaleStep {
    double value = 0;           ///< the level it stands for, data units
    int64_t top_units = 0;      ///< z of its tread
    double y_south_mm = 0, y_north_mm = 0;
};

/// The scale as placed on a model (see above).
struct SceneScale {
    double step = 0;               ///< data units between levels
    bool step_given = false;       ///< --scale-step (else chosen)
    int64_t x0_i = 0;              ///< lattice i of the foot's west face
    int64_t y0_j = 0, y1_j = 0;    ///< lattice j of its south and north faces
    double x0_mm = 0, xs_mm = 0, x1_mm = 0, y0_mm = 0, y1_mm = 0;
    int64_t foot_top_units = 0;    ///< the floor
    std::vector<ScaleStep> steps;  ///< south to north, lowest first
    std::vector<int32_t> contacts; ///< kept cells it touches along their east walls, south to north
    /// Between two contacts (6 lattice rows apart) the foot fills the notch
    /// the hexagons leave (a trapezoid: the upper contact's south-east wall,
    /// the lower's north-east wall, and the east wall of the cell between,
    /// kept here in order), so the join leaves no hole down to the bed.
    std::vector<int32_t> fillers;
};

}  // namespace tsf
