// The orientation tab as the Scene holds it: data only, kept in
// Scene::features (gen/model/feature_state.h) by the tab's feature
// (tab_feature.h); placeTab (orientation_tab.h) places it, the direct
// mesher, the OpenSCAD emitter and the verifier read it through the
// feature contract (gen/model/feature.h), the tab's own files through
// sceneTab. Frame and units as the Scene's: mm in x and y, z in the Scene's
// z units.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// The orientation tab (orientation_tab.h): a flat plate from z = 0 to the
/// floor against the pillars' westernmost walls, its south-west corner cut
/// by the notch, the triangle standing on its top. With it, the Scene's
/// marks in the data (Scene::marks) are none.
struct OrientationTab {
    /// The plate's outline, counter-clockwise from +z: starts at the notch's
    /// mouth on the south edge; the notch's apex is the last point.
    std::vector<OutlinePoint> outline;
    /// joined[n]: the edge outline[n] -> outline[n + 1] is a pillar's wall
    /// (the plate stands against it from 0 to its top and has no wall there).
    std::vector<uint8_t> joined;
    /// The hexagon edges (kept cell, edge 0..5 of hex_grid.h) the plate
    /// covers from 0 to its top: the joined edges, as the pillars see them.
    std::vector<std::pair<int32_t, int>> touched;
    /// The plate's z span: flat, 0 to the floor; mirrored, the span every
    /// pillar it stands against holds (the thickest band they share).
    int64_t bottom_units = 0, top_units = 0;
    double x_west_mm = 0, x_east_mm = 0, y_south_mm = 0, y_north_mm = 0;  ///< its bounding box
    /// The notch: apex at notch_depth_mm from the south-west corner along the diagonal.
    double notch_depth_mm = 0, notch_width_mm = 0, notch_opening_deg = 0;
    /// The triangle: right angle, east end, north end (mm, snapped), standing
    /// triangle_raise_units above the plate's top and, on a mirrored model
    /// (under_triangle), as far below its bottom: the underside shows it
    /// mirrored exactly as it shows the data.
    std::array<OutlinePoint, 3> triangle;
    int64_t triangle_raise_units = 0;
    bool under_triangle = false;
    bool has_notch = false, has_triangle = false;
};

/// The Scene's tab; null when it has none.
inline const OrientationTab* sceneTab(const Scene& scene) { return scene.features.get<OrientationTab>(); }
inline OrientationTab* sceneTab(Scene& scene) { return scene.features.get<OrientationTab>(); }

}  // namespace tsf
