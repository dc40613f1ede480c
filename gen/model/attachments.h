// The Scene's attachments, cuts and probes (gen/model/scene_attachments.h),
// from whichever features it has: the one place that lists the features
// that give a body, a hole or a place to read back, so the direct mesher,
// the parts and the read-backs draw them without naming any.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// Every attachment of `scene` as `assembly` draws it, in a fixed order (the
/// registry's features placed with the marks: the orientation tab; the
/// legend; then the registry's features beside the pillars:
/// gen/model/feature_registry.h). Meshing a body is
/// deterministic: the same Scene gives the same attachments.
std::vector<Attachment> sceneAttachments(const Scene& scene, Assembly assembly);

/// Every hole into the flat bottom `scene` draws (a half's pin holes, a tile's code pits).
std::vector<BottomHole> sceneBottomHoles(const Scene& scene);

/// Every probe of the Scene (gen/model/scene_attachments.h), one set per
/// read-back check, in a fixed order (the legend, the registry's features
/// beside the pillars, the marks in the data or on the tab);
/// sets without probes are left out.
std::vector<ProbeSet> sceneProbes(const Scene& scene);

/// Checks what the mesher relies on to join each attachment without a
/// boolean operation (each feature's own check). Throws InputError.
void checkAttachments(const Scene& scene);

/// The x, y box (mm) of each attachment (what stands beside the pillars:
/// the tab, the legend's plate, the scale); empty without any.
std::vector<BoxMm> attachmentBoxes(const Scene& scene);

/// The x, y extent (mm) of everything the Scene places: the pillars and
/// every attachment. For a Scene without kept cells, an empty box (x0 > x1).
BoxMm sceneFootprint(const Scene& scene);

/// What stands beside the pillars east or west and takes bed width from
/// them for these parameters (SideWidth, gen/model/scene_attachments.h).
/// Empty when nothing will.
std::vector<SideWidth> attachmentSideWidths(const SceneParams& params);

/// The heights (z units) of the attachments' tops at (x, y) mm, the model
/// frame: what a probe from above may meet there besides the cells. Empty
/// beside every attachment.
std::vector<int64_t> attachmentTopsAt(const Scene& scene, double x_mm, double y_mm);

}  // namespace tsf
