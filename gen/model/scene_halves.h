// The cut into support-free halves and the pin holes as the Scene holds
// them: data only. Where they come from is gen/model/features/halves.h.
#pragma once

#include <cstdint>
#include <vector>

#include "gen/field/hex_grid.h"

namespace tsf {

/// Pin diameter, mm: printed standing, a 3 mm PLA pin does not snap when
/// the halves are pressed together or pulled apart.
inline constexpr double kPinDiameterMm = 3.0;
/// Gap between pin and hole on each side, mm: the 0.2 mm per side a sliding
/// fit needs on FDM printers (docs/printing.md cites the source).
inline constexpr double kPinClearanceMm = 0.2;
/// How deep each hole goes into its half, mm, before the cone that closes it.
inline constexpr double kHoleDepthMm = 3.0;
/// The cone's height over the hole's vertex radius: 1.1 makes every cone
/// face 48.3 degrees from the horizontal (steeper than 45), which prints without
/// supports or bridging.
inline constexpr double kHoleConeRatio = 1.1;
/// Material above a hole's cone tip, mm (two nozzle widths).
inline constexpr double kHoleRoofMm = 0.8;
/// How closely buildScene finds the thinnest slab that gives three pillars
/// room for the pins, mm (a layer of a fine printer).
inline constexpr double kHalvesSlabSearchMm = 0.1;
/// Material between a hole and the model's outer wall, mm (five perimeters
/// of a 0.4 mm nozzle).
inline constexpr double kHoleEdgeMarginMm = 2.0;
/// Sides of the polygons that stand for the round holes and pins.
inline constexpr int kHoleSides = 16;
/// The three distances between hole centres differ pairwise by at least this
/// much, mm: far more than the 4 x 0.2 mm two loose pins can take up, so a
/// turned or reflected half cannot be pushed on.
inline constexpr double kPinLayoutMinSideDifferenceMm = 2.0;
/// Number of pins (and of holes in each cut face).
inline constexpr int kPinCount = 3;

/// Which piece a Scene draws.
enum class HalfKind : uint8_t {
    Whole,  ///< the whole mirrored model (the holes are not drawn)
    Upper,  ///< the pillars above the cut, standing on the cut
    Lower,  ///< the pillars below the cut, reflected in z about it (see the file comment)
};

/// Holes radius, depth and the pins that fit them (mm).
struct PinGeometry {
    double hole_radius_mm = kPinDiameterMm / 2 + kPinClearanceMm;  ///< inscribed radius of the hole polygon
    double hole_vertex_radius_mm = 0;  ///< circumradius of the hole polygon
    double pin_radius_mm = kPinDiameterMm / 2;  ///< circumradius of the pin polygon (the pin fits in this circle)
    double hole_depth_mm = kHoleDepthMm;        ///< straight part of the hole, from the cut face
    double cone_mm = 0;                         ///< height of the cone over the straight part
    double pin_length_mm = 0;                   ///< two hole depths less the clearance at each end
};

/// The halves in the Scene (model frame unless said otherwise).
struct SceneHalves {
    HalfKind kind = HalfKind::Whole;  ///< what this Scene draws (halfScene sets Upper or Lower)
    int64_t split_units = 0;          ///< z of the cut, z units (model frame)
    int64_t slab_bottom_units = 0;    ///< highest pillar bottom: the common slab starts here
    int64_t slab_top_units = 0;       ///< lowest pillar top: the common slab ends here
    int64_t thickness_grown_units = 0;  ///< how much the mirror thickness grew for the slab
    PinGeometry pins;
    std::vector<int32_t> hole_cells;        ///< kept index of the cell each hole is centred on
    std::vector<LatticePoint> hole_centres; ///< the holes' centres (the cells' centres)
    int64_t hole_depth_units = 0;           ///< straight part of a hole, z units
    int64_t hole_apex_units = 0;            ///< tip of the cone above the cut face, z units
};

}  // namespace tsf
