#include "haptics/printed_relief.h"
#include "gen/model/features/marks.h"

#include <algorithm>
#include <cmath>

namespace tsf::haptics {

double printedHeightFraction(const Scene& scene, size_t k) {
    const double max_mm = scene.mapping.max_height_mm;
    if (!(max_mm > 0.0)) return 0.0;
    // The top the mesher builds at the cell's centre, above the floor (flat)
    // or above the top of a zero (mirrored): a cell without data is a pit
    // below 0, a cell under the orientation triangle stands its height higher.
    const int64_t zero = scene.params.bottom == Bottom::Mirrored ? scene.mirror_thickness_units : scene.floor_units;
    const int64_t units = scene.top[k] + markRaiseAtCentre(scene, k) - zero;
    return std::clamp(scene.zMm(units) / max_mm, -1.0, 2.0);
}

namespace {

// Height (mm) of kept cell k's printed top at (dx, dy) mm from its centre,
// relative to the centre: a tilted top's plane, a structural cell's cone
// rising from its lowered centre to the hexagon's edge (gen/model/features/top_shapes.h).
double shapedTopOffsetMm(const Scene& scene, size_t k, double dx, double dy) {
    const TopShapes& t = scene.shapes;
    if (t.empty()) return 0.0;
    double z = t.slope_x[k] * dx + t.slope_y[k] * dy;
    if (t.top_centre_dz[k] != 0) {
        // How far out the point is, 0 at the centre and 1 on the edge: the
        // largest projection on the six edge normals (0, 60, ... 300 degrees)
        // over the inradius (half the pitch).
        double out = 0;
        for (int e = 0; e < 6; ++e) {
            const double a = e * (3.14159265358979323846 / 3.0);  // radians
            out = std::max(out, (dx * std::cos(a) + dy * std::sin(a)) / (0.5 * scene.pitch_mm));
        }
        z -= scene.zMm(t.top_centre_dz[k]) * (std::min(1.0, out) - 1.0);
    }
    return z;
}

}  // namespace

HeightGrid printedRelief(const Scene& scene, ReliefInfo* info) {
    const double width_p = gridWidth(scene.grid, 1.0), depth_p = gridDepth(scene.grid, 1.0);  // in pitches
    int per_pitch = kReliefSamplesPerPitch;
    while (per_pitch > 1 && std::max(width_p, depth_p) * per_pitch > kMaxReliefSamples) --per_pitch;
    const double side_p = 1.0 / per_pitch;
    const auto cols = int32_t(std::max(1.0, std::ceil(width_p * per_pitch - 1e-9)));
    const auto rows = int32_t(std::max(1.0, std::ceil(depth_p * per_pitch - 1e-9)));

    std::vector<float> kept_height(scene.keptCount());
    for (size_t k = 0; k < kept_height.size(); ++k) kept_height[k] = float(printedHeightFraction(scene, k));

    HeightGrid g;
    g.cols = cols;
    g.rows = rows;
    g.heights.assign(size_t(cols) * size_t(rows), 0.0f);
    for (int32_t j = 0; j < rows; ++j)
        for (int32_t i = 0; i < cols; ++i) {
            int32_t c = 0, r = 0;
            if (!hexCellAt(scene.grid, (i + 0.5) * side_p, (j + 0.5) * side_p, c, r)) continue;
            const int32_t k = scene.keptAt(c, r);
            if (k < 0) continue;
            g.at(i, j) = kept_height[size_t(k)];
            if (!scene.shapes.empty() && scene.shapes.shaped[size_t(k)] && scene.mapping.max_height_mm > 0) {
                const LatticePoint centre = hexCentre(scene.grid, c, r);
                const double dx = ((i + 0.5) * side_p - latticeX(centre, 1.0)) * scene.pitch_mm;
                const double dy = ((j + 0.5) * side_p - latticeY(centre, 1.0)) * scene.pitch_mm;
                const double h = kept_height[size_t(k)] + shapedTopOffsetMm(scene, size_t(k), dx, dy) / scene.mapping.max_height_mm;
                g.at(i, j) = float(std::clamp(h, -1.0, 2.0));
            }
        }
    if (info) {
        info->samples_per_pitch = per_pitch;
        info->sample_mm = scene.pitch_mm * side_p;
        info->exact_at_centres = per_pitch >= kReliefSamplesPerPitch;
    }
    return g;
}

GridPoint reliefCellCentre(const Scene& scene, int32_t col, int32_t row, int samples_per_pitch) {
    const LatticePoint c = hexCentre(scene.grid, col, row);
    // Sample i covers [i, i + 1) / samples_per_pitch pitches; its centre is grid coordinate i.
    return {latticeX(c, 1.0) * samples_per_pitch - 0.5, latticeY(c, 1.0) * samples_per_pitch - 0.5};
}

std::vector<SweepLine> reliefRowLines(const Scene& scene, const ReliefInfo& info, const FieldMapping& mapping) {
    std::vector<SweepLine> lines;
    // A hair less than half a pitch: inside the hexagon on its centre line.
    const double reach = 0.45 * info.samples_per_pitch;  // grid units
    for (int32_t r = 0; r < scene.grid.rows; ++r) {
        int32_t first = -1, last = -1;
        for (int32_t c = 0; c < scene.grid.cols; ++c)
            if (scene.keptAt(c, r) >= 0) {
                if (first < 0) first = c;
                last = c;
            }
        if (first < 0) continue;
        const GridPoint a = reliefCellCentre(scene, first, r, info.samples_per_pitch);
        const GridPoint b = reliefCellCentre(scene, last, r, info.samples_per_pitch);
        lines.push_back({gridToDevice(mapping, a.gi, a.gj, 0.0).z, gridToDevice(mapping, a.gi - reach, a.gj, 0.0).x,
                         gridToDevice(mapping, b.gi + reach, b.gj, 0.0).x});
    }
    return lines;
}

}  // namespace tsf::haptics
