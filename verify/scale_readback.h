// The tactile scale read back: does each tread stand at the height of its
// value, and the foot at the floor?
//
// For each step of the Scene's scale (gen/model/features/scale.h) a vertical ray is cast
// down at the middle of its tread, and one at the middle of the foot's floor
// strip; the first surface met is compared with the Scene's z (the pillars'
// own snapped height of the step's value above the floor). Tolerance as for
// the pillars (verify/readback.h): half a z step plus the float32 rounding of
// the largest z. Without a scale the check is skipped.
#pragma once

#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"
#include "verify/report.h"
#include "verify/triangle_bvh.h"

namespace tsf {

struct ScaleReadbackResult {
    size_t surfaces_checked = 0;  ///< treads and the foot
    double max_error_mm = 0;      ///< largest |measured - Scene| over the surfaces met
    std::vector<Check> checks;    ///< "scale_read_back"
    std::vector<Stage> stages;
};

ScaleReadbackResult readBackScale(const Mesh& mesh, const Scene& scene, const TriangleBvh& caster);

}  // namespace tsf
