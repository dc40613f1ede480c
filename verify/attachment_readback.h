// The Scene's attachments read back: does the mesh show the braille legend,
// the tactile scale and the orientation marks where and as high as the
// Scene says?
//
// Each probe of the Scene (gen/model/attachments.h: sceneProbes) is a vertical ray cast down from above
// the mesh: the first surface met must be at the probe's z, or nothing may
// be met (the notch). One check per attachment the Scene has
// ("legend_read_back", "scale_read_back", "marks_read_back"); an attachment
// the Scene lacks is not reported. Tolerance as for the pillars
// (verify/readback.h): half a z step plus the float32 rounding of the largest
// z probed (and, for a probe on a slope, the slope times the float32
// rounding of x and y), so a braille dot printed at 30 % of its height, a tread or the
// triangle a layer off, or a notch filled in, fails.
#pragma once

#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"
#include "verify/report.h"
#include "verify/column_grid.h"

namespace tsf {

struct AttachmentReadbackResult {
    size_t probes_checked = 0;
    double max_error_mm = 0;    ///< largest |measured - Scene| over the surfaces met
    std::vector<Check> checks;  ///< one per attachment present
    std::vector<Stage> stages;
};

AttachmentReadbackResult readBackAttachments(const Mesh& mesh, const Scene& scene, const ColumnGrid& caster,
                                             size_t max_offenders = 10);

}  // namespace tsf
