// The model fitted to the bed (--bed, printer_fit.h): what stands beside
// the pillars (the legend's plate, the tab, the scale) does not shrink
// with them, so the Scene is built again for a smaller box while it takes
// the model past the bed; after meshing, a model still larger than the bed
// is refused with what does fit.
#pragma once

#include "app/gen_run/gen_command_options.h"
#include "gen/field/hex_field.h"
#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"

namespace tsf::cli {

/// The Scene of o.gen for the bed. Each fit again (at most 6: a culled
/// outline can need a second step) shrinks o.gen's box and reads the field
/// again: a raster resampled to fit it keeps cells a fingertip tells apart
/// (fewer of them), never narrower.
Scene buildSceneForBed(GenCommandOptions& o, HexField& field);

/// Throws InputError when the mesh's footprint is larger than the bed
/// (without --tile), each --cell it suggests tried by making the model
/// again at that cell (the field read and the Scene built as asked
/// otherwise).
void checkMeshFitsBed(const GenCommandOptions& o, const Scene& scene, const Mesh& mesh);

}  // namespace tsf::cli
