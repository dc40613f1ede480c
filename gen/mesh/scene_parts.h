// meshSceneParts: a Scene's solid as separate parts, one per feature, for a
// multi-part 3MF (tsf gen --parts, docs/printing.md).
//
// The parts, in this order, each present only when the Scene has it:
//   "pillars" - the pillars with the notch cut (and, with a legend, its plate
//               joined to them), the orientation triangle's region level;
//   "marks"   - the raised orientation triangle: a prism over the triangle's
//               face (Scene::faces, the face with raise_units > 0) from its
//               region's top up by raise_units;
//   "legend"  - the braille dots, one closed dome each on the plate's top.
//   "scale"   - the tactile scale (gen/model/features/scale.h): its foot and steps, touching
//               the pillars' east walls from the bed to the floor.
// Beyond the raised faces, the parts are the Scene's attachments' own
// pieces (gen/model/attachments.h), in the part each names: a new
// attachment becomes a part without an edit here.
// Each part is closed, 2-manifold and outward-facing on its own, with no
// T-junctions inside it; the parts touch (the triangle's and the domes' bases
// lie on the pillars' top) and never overlap, and their union is the solid of
// meshScene(scene). Everything is read from the Scene; nothing is decided here.
#pragma once

#include <vector>

#include "gen/geometry/mesh_parts.h"
#include "gen/model/scene.h"

namespace tsf {

/// The Scene's parts as above. An empty Scene gives no parts. Throws as meshScene does.
std::vector<MeshPart> meshSceneParts(const Scene& scene);

}  // namespace tsf
