#include "haptics/printed_relief.h"

#include "gen/mesh/direct_mesher.h"
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
    const int64_t zero = scene.params.bottom == Bottom::Mirrored ? scene.mirror_thickness_units + scene.floor_units : scene.floor_units;
    const int64_t units = scene.top[k] + markRaiseAtCentre(scene, k) - zero;
    return std::clamp(scene.zMm(units) / max_mm, -1.0, 2.0);
}

namespace {

// The z (mm) of the highest upward-facing surface of `mesh` over the centre
// of every sample (side side_mm, sample (i, j) centred at ((i + 0.5) side,
// (j + 0.5) side)); NaN where no surface is. Walls (no upward normal) are
// skipped: a vertical line meets them only along an edge that the tops
// beside them share.
std::vector<double> topsOver(const Mesh& mesh, double side_mm, int32_t cols, int32_t rows, double x0_mm, double y0_mm) {
    std::vector<double> z(size_t(cols) * size_t(rows), std::nan(""));
    for (const auto& t : mesh.triangles) {
        const tsf::Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        const double area2 = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);  // > 0: facing up
        if (!(area2 > 0)) continue;
        const double lo_x = std::min({a.x, b.x, c.x}) - x0_mm, hi_x = std::max({a.x, b.x, c.x}) - x0_mm;
        const double lo_y = std::min({a.y, b.y, c.y}) - y0_mm, hi_y = std::max({a.y, b.y, c.y}) - y0_mm;
        const auto i0 = std::max<int32_t>(0, int32_t(std::ceil(lo_x / side_mm - 0.5)));
        const auto i1 = std::min<int32_t>(cols - 1, int32_t(std::floor(hi_x / side_mm - 0.5)));
        const auto j0 = std::max<int32_t>(0, int32_t(std::ceil(lo_y / side_mm - 0.5)));
        const auto j1 = std::min<int32_t>(rows - 1, int32_t(std::floor(hi_y / side_mm - 0.5)));
        for (int32_t j = j0; j <= j1; ++j)
            for (int32_t i = i0; i <= i1; ++i) {
                const double x = x0_mm + (i + 0.5) * side_mm, y = y0_mm + (j + 0.5) * side_mm;
                // Barycentric weights; a point on an edge belongs to both
                // triangles that share it (the same z on a continuous top).
                const double wa = (b.x - x) * (c.y - y) - (b.y - y) * (c.x - x);
                const double wb = (c.x - x) * (a.y - y) - (c.y - y) * (a.x - x);
                const double wc = (a.x - x) * (b.y - y) - (a.y - y) * (b.x - x);
                if (wa < 0 || wb < 0 || wc < 0) continue;
                const double zz = (wa * a.z + wb * b.z + wc * c.z) / area2;
                double& cell = z[size_t(j) * size_t(cols) + size_t(i)];
                if (std::isnan(cell) || zz > cell) cell = zz;
            }
    }
    return z;
}

}  // namespace

HeightGrid printedRelief(const Scene& scene, ReliefInfo* info) {
    // What is felt is the model as meshed, every feature included (the
    // notch, the triangle, tilted and dimpled tops, the legend's plate and
    // dots, the scale): nothing about the model is decided again here.
    return meshRelief(scene, meshScene(scene), info);
}

HeightGrid meshRelief(const Scene& scene, const Mesh& mesh, ReliefInfo* info) {
    const Bounds b = meshBounds(mesh);
    const double width_p = std::max(gridWidth(scene.grid, 1.0), std::isfinite(b.max.x) ? b.max.x / scene.pitch_mm : 0.0);
    const double depth_p = std::max(gridDepth(scene.grid, 1.0, scene.y_scale), std::isfinite(b.max.y) ? b.max.y / scene.pitch_mm : 0.0);
    int per_pitch = kReliefSamplesPerPitch;
    const double west_p = std::isfinite(b.min.x) ? std::max(0.0, -b.min.x / scene.pitch_mm) : 0.0;
    const double south_p = std::isfinite(b.min.y) ? std::max(0.0, -b.min.y / scene.pitch_mm) : 0.0;
    while (per_pitch > 1 && std::max(width_p + west_p, depth_p + south_p) * per_pitch > kMaxReliefSamples) --per_pitch;
    const double side_p = 1.0 / per_pitch;
    // Whole samples west and south of the grid's box for what stands there
    // (the orientation tab), so every cell centre stays on a sample centre.
    const auto origin_i = int32_t(std::ceil(west_p * per_pitch - 1e-9));
    const auto origin_j = int32_t(std::ceil(south_p * per_pitch - 1e-9));
    const auto cols = int32_t(std::max(1.0, std::ceil(width_p * per_pitch - 1e-9))) + origin_i;
    const auto rows = int32_t(std::max(1.0, std::ceil(depth_p * per_pitch - 1e-9))) + origin_j;

    HeightGrid g;
    g.cols = cols;
    g.rows = rows;
    g.heights.assign(size_t(cols) * size_t(rows), 0.0f);
    const double max_mm = scene.mapping.max_height_mm;
    if (max_mm > 0) {
        const int64_t zero = scene.params.bottom == Bottom::Mirrored ? scene.mirror_thickness_units + scene.floor_units : scene.floor_units;
        const double side_mm = side_p * scene.pitch_mm;
        const std::vector<double> tops = topsOver(mesh, side_mm, cols, rows, -origin_i * side_mm, -origin_j * side_mm);
        for (size_t n = 0; n < tops.size(); ++n)
            if (!std::isnan(tops[n]))  // beside the model: the floor
                g.heights[n] = float(std::clamp((tops[n] - scene.zMm(zero)) / max_mm, -1.0, 2.0));
    }
    if (info) {
        info->samples_per_pitch = per_pitch;
        info->sample_mm = scene.pitch_mm * side_p;
        info->exact_at_centres = per_pitch >= kReliefSamplesPerPitch;
        info->origin_i = origin_i;
        info->origin_j = origin_j;
    }
    return g;
}

ReliefSurface reliefSurface(const Scene& scene, double sample_mm) { return reliefSurface(meshScene(scene), sample_mm); }

double overhangAreaMm2(const Mesh& mesh) {
    const Bounds b = meshBounds(mesh);
    double area = 0;
    for (const auto& t : mesh.triangles) {
        const tsf::Vec3 &p = mesh.positions[t[0]], &q = mesh.positions[t[1]], &r = mesh.positions[t[2]];
        if (std::max({p.z, q.z, r.z}) <= b.min.z) continue;  // on the bed
        const tsf::Vec3 n = tsf::cross(tsf::sub(q, p), tsf::sub(r, p));
        const double len = std::sqrt(tsf::dot(n, n));
        if (len > 0 && n.z < -std::sqrt(0.5) * len) area += len / 2;
    }
    return area;
}

ReliefSurface reliefSurface(const Mesh& mesh, double sample_mm) {
    ReliefSurface r;
    if (mesh.positions.empty() || !(sample_mm > 0)) return r;
    const Bounds b = meshBounds(mesh);
    r.sample_mm = sample_mm;
    r.x0_mm = b.min.x;
    r.y0_mm = b.min.y;
    r.cols = int32_t(std::max(1.0, std::ceil((b.max.x - b.min.x) / sample_mm)));
    r.rows = int32_t(std::max(1.0, std::ceil((b.max.y - b.min.y) / sample_mm)));
    r.z_mm = topsOver(mesh, sample_mm, r.cols, r.rows, r.x0_mm, r.y0_mm);
    return r;
}

GridPoint reliefCellCentre(const Scene& scene, int32_t col, int32_t row, const ReliefInfo& info) {
    const LatticePoint c = hexCentre(scene.grid, col, row);
    // Sample i covers [i - origin_i, i - origin_i + 1) / samples_per_pitch
    // pitches of the model frame; its centre is grid coordinate i.
    return {latticeX(c, 1.0) * info.samples_per_pitch - 0.5 + info.origin_i,
            latticeY(c, 1.0, scene.y_scale) * info.samples_per_pitch - 0.5 + info.origin_j};
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
        const GridPoint a = reliefCellCentre(scene, first, r, info);
        const GridPoint b = reliefCellCentre(scene, last, r, info);
        lines.push_back({gridToDevice(mapping, a.gi, a.gj, 0.0).z, gridToDevice(mapping, a.gi - reach, a.gj, 0.0).x,
                         gridToDevice(mapping, b.gi + reach, b.gj, 0.0).x});
    }
    return lines;
}

}  // namespace tsf::haptics
