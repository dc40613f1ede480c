#include "gen/model/features/legend_join.h"

#include <algorithm>
#include <cmath>

#include "gen/model/features/legend_plate.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/scene.h"

namespace tsf {
namespace {

double snapUm(double mm) { return std::round(mm * 1000.0) / 1000.0; }

// The plate's outline, height and dots in the model frame; with the sides
// where pillars stand (joined).
PlateSpec plateSpec(const Scene& s, bool dots) {
    const SceneLegend& l = *s.legend;
    PlateSpec spec;
    spec.x0_mm = 0;
    spec.y0_mm = l.plate_south_mm;
    spec.x1_mm = l.plate_east_mm;
    spec.y1_mm = l.plate_north_mm;
    spec.height_mm = s.zMm(l.plate_top_units);
    spec.bottom_mm = s.zMm(l.plate_bottom_units);
    spec.standard = l.layout.standard;
    if (dots)
        for (const LegendDot& d : l.layout.dots) spec.dots.push_back({snapUm(d.x_mm + l.x0_mm), snapUm(d.y_mm + l.y0_mm)});
    spec.outline = legendPlateOutline(s);
    // Against a pillar at or above the plate's top no side; against a lower
    // one (a no-data pit) the side from its top up. (A mirrored model's plate
    // lies in a band every pillar it stands against holds.)
    for (const PlateOutline::Edge& e : spec.outline.edges)
        spec.side_from_mm.push_back(e.cell < 0 ? spec.bottom_mm
                                               : s.zMm(std::clamp(s.top[size_t(e.cell)], l.plate_bottom_units, l.plate_top_units)));
    // Every height the pillars have at a lattice corner of the outline (a
    // pit that meets the plate's own side only at that corner, below its
    // top): the plate's sides split there too, so no T-junction.
    const int64_t ids = latticeVertexIdCount(s.grid);
    for (const TabPoint& p : spec.outline.points) {
        std::vector<double> z;
        if (p.lattice >= 0 && p.lattice < ids) {
            int32_t cols[3], rows[3];
            latticeVertexCells(s.grid, p.lattice, cols, rows);
            for (int c = 0; c < 3; ++c) {
                const int32_t k = s.keptAt(cols[c], rows[c]);
                if (k < 0) continue;
                for (const int64_t u : {cornerTopAt(s, size_t(k), p.lattice), cornerBottomAt(s, size_t(k), p.lattice)})
                    if (u > l.plate_bottom_units && u < l.plate_top_units) z.push_back(s.zMm(u));
            }
        }
        spec.point_heights_mm.push_back(std::move(z));
    }
    return spec;
}

}  // namespace

Mesh legendDotsMesh(const Scene& s) {
    if (!s.legend) return {};
    return meshLegendDots(plateSpec(s, true));
}

Mesh legendPlateMesh(const Scene& s, bool dots) {
    if (!s.legend || s.keptCount() == 0) return {};
    return meshLegendPlate(plateSpec(s, dots));
}

PlateBody legendJoinedBody(const Scene& s, bool dots) {
    if (!s.legend || s.keptCount() == 0) return {};
    return meshPlateBody(plateSpec(s, dots), /*joined=*/true);
}

}  // namespace tsf
