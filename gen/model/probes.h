// Probes: the places where a mesh must show the Scene's attachments, so that
// one read-back (verify/attachment_readback.h) proves every one of them from
// the written model, whatever feature placed it.
//
// A probe is a vertical line at (x, y) in the model frame (mm). Casting a ray
// down it from above the mesh, the first surface met must be at z_mm (a
// surface probe), or nothing may be met at all (an empty probe: a cut through
// the whole model, such as the orientation notch). Probes stand where the
// surface is level or at a vertex of the drawn surface (a braille dot's
// apex), so the expected height is exact, not sampled from a curve.
//
// What is probed, by attachment:
//   legend  the plate's top north of the braille (both ends), and the apex of
//           every braille dot: plate top + dot height, on the 1 um grid;
//   scale   the foot's floor strip and the middle of every tread;
//   marks   the orientation triangle's centroid and a point near each corner
//           (its region's top + its raise), and inside the notch's V near its
//           apex (empty: the notch cuts the whole height); on the orientation
//           tab also its top, and either side of the notch's apex along its
//           diagonal, so its full depth is proven.
// Cells are read back on their own (verify/readback.h); probes cover what
// stands beside or on them.
#pragma once

#include <string>
#include <vector>

#include "gen/model/scene.h"

namespace tsf {

struct SurfaceProbe {
    std::string attachment;  ///< "legend", "scale" or "marks": one read-back check each
    std::string what;        ///< for a person: "braille dot 3 (line 1)", "the step for 10"
    double x_mm = 0, y_mm = 0;
    bool empty = false;      ///< true: the vertical line meets no surface at all
    double z_mm = 0;         ///< else: z of the first surface met from above
    /// Largest slope (dz per mm in x, y) of the surface next to the probe: 0
    /// for a level surface. A model written in float32 moves each vertex by
    /// up to 2^-24 of its coordinates, so a probe on a slope (a dot's apex)
    /// reads that shift times the slope, which the read-back allows for.
    double slope = 0;
};

/// Every probe of the Scene's attachments, grouped by attachment in the
/// order above. Empty when the Scene has none.
std::vector<SurfaceProbe> attachmentProbes(const Scene& scene);

/// The attachments a Scene has, in the order of attachmentProbes, each with
/// the title of its read-back check.
struct AttachmentKind {
    const char* name;   ///< as SurfaceProbe::attachment
    const char* title;  ///< "every braille dot and the legend plate at its height"
};
const std::vector<AttachmentKind>& attachmentKinds();

}  // namespace tsf
