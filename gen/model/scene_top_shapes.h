// Tilted and dimpled tops as the Scene holds them: data only. Where they come
// from is gen/model/features/top_shapes.h and tilt.h.
#pragma once

#include <array>
#include <cstdint>
#include <cstddef>
#include <vector>

#include "gen/model/scene_marks.h"

namespace tsf {

struct TopShapes {
    // Per kept cell (all empty when no cell is shaped).
    std::vector<std::array<int32_t, 6>> top_dz;     ///< z of corner e minus Scene::top[k], z units
    std::vector<std::array<int32_t, 6>> bottom_dz;  ///< mirrored: z of corner e minus Scene::bottom[k]
    std::vector<int32_t> top_centre_dz;             ///< z of the top's centre minus top[k] (< 0: a dimple)
    std::vector<int32_t> bottom_centre_dz;          ///< mirrored: z of the bottom's centre minus bottom[k]
    std::vector<double> slope_x, slope_y;           ///< the tilt drawn, mm per mm (x east, y north); 0 = level
    std::vector<uint8_t> structural;                ///< 1: kept only to hold the model together (dimpled)
    // Geometry made from the above by buildTopShapeGeometry.
    std::vector<uint8_t> shaped;          ///< 1: top (and mirrored bottom) drawn as a fan from the centre
    std::vector<int64_t> centre_top_id;   ///< planar id of the top fan's centre, -1 if not shaped
    std::vector<int64_t> centre_bottom_id;  ///< mirrored: planar id of the bottom fan's centre
    std::vector<int64_t> crossing_top;      ///< 6 per kept cell (edge e): planar id of the tops' crossing, -1
    std::vector<int64_t> crossing_bottom;   ///< 6 per kept cell: the mirrored bottoms' crossing, -1
    int64_t first_id = 0;                   ///< planar id of extra[0]
    std::vector<PlanarPoint> extra;         ///< fan centres and crossing points, lattice coordinates
    std::vector<int64_t> extra_z;           ///< the one height of each extra vertex, z units
    // Facts for the summary.
    int64_t cells_tilted = 0;    ///< cells whose top is not level
    int64_t cells_slope_limited = 0;  ///< cells whose plane leaned more than max_slope_deg (drawn at that slope)
    int64_t cells_clamped = 0;   ///< cells whose tilt was made shallower to stay within the height range / clear of a mark
    int64_t cells_flat_clamped = 0;  ///< of those, cells that had to stay level
    int64_t cells_textured = 0;  ///< structural cells with a dimple
    int64_t dimple_units = 0;    ///< depth of the dimple at the centre, z units

    bool empty() const { return top_dz.empty(); }
};

/// True when kept cell k is drawn as a fan.
inline bool isShaped(const TopShapes& t, size_t k) { return !t.shaped.empty() && t.shaped[k]; }

/// True when kept cell k is structural (kept only to connect the model).
inline bool isStructural(const TopShapes& t, size_t k) { return !t.structural.empty() && t.structural[k]; }

}  // namespace tsf
