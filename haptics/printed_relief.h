// The relief a Scene prints, as the HeightGrid the haptic renderer samples,
// so that `tsf feel` and `tsf gen` given the same input and options make
// the same relief: one value -> height rule (gen/model/scene.h: baseline, value
// max, transfer, snap), one set of cells (culling), one footprint.
//
// Sampling: square samples of side pitch / samples_per_pitch over the
// model's bounding box (Scene frame: x east, y north, origin at the
// south-west corner of the grid; HeightGrid rows run south to north, so row
// j is y = (j - origin_j + 0.5) * side; the box reaches north over the
// legend's plate, east over the tactile scale and west, by whole samples
// (ReliefInfo::origin_i), over the orientation tab). Each sample is the height of the highest
// top of the model's mesh (meshScene, gen/mesh/direct_mesher.h) above the
// sample's centre, less the floor (flat) or the mirrored slab's top of a
// zero, divided by the height of the largest value (max_height_mm); beside
// the model it is 0, the floor. So everything printed is felt as printed,
// from the one mesh: pillars and no-data pits, tilted tops and dimples, the
// notch, the orientation tab and its triangle, the legend's dots, the scale's steps.
// Nothing about the model is decided a second time here.
//
// With kReliefSamplesPerPitch samples per pitch, every tap the bicubic or
// bilinear sampler takes around a cell's centre lies inside that cell (a
// square of half-side 2 samples fits in a pointy-top hexagon when the side is
// at most 0.18 pitch), so the surface at each centre is exactly the cell's
// printed height: the felt order of the cells is the printed order. Fields
// too wide for kMaxReliefSamples get fewer samples per pitch (reported),
// and that exactness at centres is lost.
#pragma once

#include <cstdint>
#include <vector>

#include "gen/model/scene.h"
#include "haptics/field_mapping.h"
#include "haptics/height_grid.h"
#include "haptics/sim_device.h"

namespace tsf::haptics {

/// Samples per pitch (hexagon width): see the file comment for why 6.
inline constexpr int kReliefSamplesPerPitch = 6;
/// Longest side of the relief grid, samples: about 50 um on a Falcon's
/// 54 mm footprint, finer than its encoders resolve.
inline constexpr int32_t kMaxReliefSamples = 1024;

struct ReliefInfo {
    int samples_per_pitch = kReliefSamplesPerPitch;
    double sample_mm = 0.0;        ///< side of one sample in the printed model, mm
    bool exact_at_centres = true;  ///< samples_per_pitch >= kReliefSamplesPerPitch
    /// The sample where the model frame's x = 0 (y = 0) begins: the samples
    /// west (south) of it hold what stands beyond the grid's box (the
    /// orientation tab), so sample i's centre is x = (i - origin_i + 0.5) * sample_mm.
    int32_t origin_i = 0, origin_j = 0;
};

/// The printed relief of `scene` (see the file comment). Heights are in
/// [0, 1]: printed height above the floor / max_height_mm (all 0 when
/// max_height_mm is 0).
HeightGrid printedRelief(const Scene& scene, ReliefInfo* info = nullptr);

/// The same relief read from `mesh` instead of the Scene's own mesh: a model
/// as written, or as OpenSCAD rendered it after a person edited the .scad,
/// on the Scene's grid and heights (so an edited pillar is felt edited).
HeightGrid meshRelief(const Scene& scene, const Mesh& mesh, ReliefInfo* info = nullptr);

/// The model's upper surface in millimetres on a square grid of side
/// sample_mm over its whole footprint (x, y of sample (i, j): x0_mm + (i +
/// 0.5) * sample_mm, y0_mm + (j + 0.5) * sample_mm; z NaN where no surface
/// is above the point): what `tsf feel --relief` writes.
struct ReliefSurface {
    double x0_mm = 0, y0_mm = 0, sample_mm = 0;
    int32_t cols = 0, rows = 0;
    std::vector<double> z_mm;  ///< row-major, row 0 south
};
ReliefSurface reliefSurface(const Scene& scene, double sample_mm);
/// The same from `mesh` (a model file as written or rendered).
ReliefSurface reliefSurface(const Mesh& mesh, double sample_mm);

/// Area (mm^2) of the surface of `mesh` that faces down more than 45
/// degrees, above its lowest point: what a hand from above cannot reach
/// (a mirrored model's underside, an edit that overhangs).
double overhangAreaMm2(const Mesh& mesh);

/// Where the centre of hex cell (col, row) lies in the relief grid's
/// continuous coordinates (height_grid.h) for the given samples per pitch.
GridPoint reliefCellCentre(const Scene& scene, int32_t col, int32_t row, const ReliefInfo& info);

/// One sweep line per row of kept cells, along the row's centre line from
/// just inside its west-most to just inside its east-most cell (device
/// frame), so a sweep crosses every cell through its centre and never the
/// notches between the rows' ends.
std::vector<SweepLine> reliefRowLines(const Scene& scene, const ReliefInfo& info, const FieldMapping& mapping);

/// The printed height of kept cell k as a fraction of max_height_mm (the
/// same number printedRelief puts under the cell): its top at its centre
/// above the floor, so a cell without data (a pit) is below 0 and a cell
/// under the orientation triangle is raised by it (gen/model/features/marks.h).
double printedHeightFraction(const Scene& scene, size_t k);

}  // namespace tsf::haptics
