#include "gen/model/phases/shaped_tops.h"

#include <algorithm>
#include <limits>
#include <optional>

#include "gen/model/feature_registry.h"
#include "gen/model/features/tilt.h"
#include "gen/model/features/top_shapes.h"

namespace tsf {

namespace {

// Structural: a kept cell at the floor that no input value fell in (a bin
// without points): kept only because the hull holds the model together
// there. A raster cell always holds pixels, so at the floor it is a value
// (0 rain is data) and is never dimpled. Not when nothing rises above the
// floor (the whole model is then such cells).
std::vector<uint8_t> structuralCells(const HexField& field, const std::vector<int64_t>& h_units, const SceneParams& params,
                                     const Scene& s) {
    const size_t kept = s.col.size();
    std::vector<uint8_t> structural(kept, 0);
    const bool dimples = params.structural_texture && s.cells_nonempty > 0 && !field.moments.empty();
    if (!dimples) return structural;
    for (size_t k = 0; k < kept; ++k) {
        const size_t idx = size_t(s.grid.index(s.col[k], s.row[k]));
        structural[k] = s.kind[k] == CellKind::Data && h_units[idx] == 0 && field.moments[idx].n == 0 &&
                        (s.drawn_by_face.empty() || !s.drawn_by_face[k]) && !featureKeepsLevel(s, k);
    }
    return structural;
}

// Tilted mirrored tops kept the whole height below them (cell_heights.h);
// now that their corners are known, the model comes down to stand on its
// lowest corner, z units. Before the legend and the tab, which take their z
// from the cells; tilt has no halves or tiles.
void lowerToLowestCorner(Scene& s) {
    const size_t kept = s.col.size();
    int64_t lowest = std::numeric_limits<int64_t>::max();
    for (size_t k = 0; k < kept; ++k) {
        lowest = std::min(lowest, centreBottom(s, k));
        for (int e = 0; e < kHexCorners; ++e) lowest = std::min(lowest, cornerBottom(s, k, e));
    }
    if (lowest <= 0 || lowest == std::numeric_limits<int64_t>::max()) return;
    for (size_t k = 0; k < kept; ++k) {
        s.top[k] -= lowest;
        s.bottom[k] -= lowest;
    }
    for (int64_t& z : s.shapes.extra_z) z -= lowest;
    s.floor_units -= lowest;
}

}  // namespace

void shapeTops(const HexField& field, const std::vector<int64_t>& h_units, const SceneParams& params, Scene& s) {
    if (params.structural_texture && params.halves)
        s.notes.push_back("structural cells are left level on a model cut into halves (the cut and the pin "
                          "holes are drawn on level cells): give --no-texture-structural to silence this");
    // A feature's shaped tops (a class map's textures), drawn as they are:
    // such a feature refuses --tilt (its slopes replace the tilt's).
    std::optional<TopShaping> shaping = featureTopShaping(s);
    if (params.tilt != TiltSource::None || (params.structural_texture && !params.halves) || shaping) {
        const std::vector<uint8_t> structural = structuralCells(field, h_units, params, s);
        std::vector<PlaneSlope> slopes = tiltSlopes(field, s, params.tilt);
        std::vector<int32_t> centre_dz;
        if (shaping) {
            slopes = std::move(shaping->slopes);
            centre_dz = std::move(shaping->centre_dz);
        }
        // Nothing to shape (a raster's cells are never structural, and no
        // tilt or shaped tops were asked for): every top stays a level
        // hexagon, with no per-cell shape lists to build, check and carry.
        const bool any = params.tilt != TiltSource::None || shaping ||
                         std::any_of(structural.begin(), structural.end(), [](uint8_t b) { return b != 0; });
        if (any) resolveTopShapes(s, slopes, shaping ? 1.0 : params.steepness, structural, centre_dz);
        if (any && params.bottom == Bottom::Mirrored && params.tilt != TiltSource::None) lowerToLowestCorner(s);
    }
    if (shaping && !shaping->note.empty()) s.notes.push_back(shaping->note);
}

}  // namespace tsf
