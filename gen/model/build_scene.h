// buildScene: a HexField and the user's parameters -> the Scene (the one
// description every mesher, the OpenSCAD emitter and the verifier draw).
// Cells, heights and the value mapping first, then each feature places what
// it adds (marks, top shapes, legend, scale, halves); each phase is a free
// function of its own in gen/model/phases/.
#pragma once

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"

namespace tsf {

/// Builds the Scene for a field. Throws InputError for invalid parameters or a
/// field with no usable value (empty grid, all NaN).
///
/// Defined outcomes (docs/model.md):
///   - NaN cells are "no data": never non-empty, modelled at the floor when kept;
///   - constant field: all cells at the same height (full height if the constant
///     is above the baseline, else the floor), with a note;
///   - a single non-empty cell or collinear non-empty cells: the hull is
///     degenerate; cells within one circumradius of it are kept so the model is
///     one piece, with a note;
///   - no non-empty cell at all (all at the floor): with Cull::Hull every cell
///     with data is kept (a flat slab) and a note says so;
///   - kept cells without data are pits nodata_pit_units below the floor
///     (mirrored: also above the underside), so touch never reads them as the
///     lowest value;
///   - the orientation marks (notch, triangle) are placed as MarkParams asks,
///     where they fit; a note says when one does not;
///   - tops tilt as params.tilt asks (gen/model/features/tilt.h), clamped so no corner goes
///     below the floor; structural cells (params.structural_texture) get a
///     dimple; a note says when a tilt was clamped.
Scene buildScene(const HexField& field, const SceneParams& params);

}  // namespace tsf
