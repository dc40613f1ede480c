#include "gen/model/features/legend/legend_join.h"

#include <algorithm>
#include <cmath>

#include "gen/model/features/legend/legend.h"
#include "gen/model/features/legend/legend_plate.h"
#include "gen/util/number_format.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/scene.h"

namespace tsf {
namespace {

// How far inside the legend plate's north edge and its ends its top is
// probed, mm: north of the braille (margins are 3 mm) and clear of the edge.
constexpr double kPlateProbeInsetMm = 1.0;


double snapUm(double mm) { return std::round(mm * 1000.0) / 1000.0; }

// The plate's outline, height and dots in the model frame; with the sides
// where pillars stand (joined).
PlateSpec plateSpec(const Scene& s, bool dots, const PlateOutline& outline) {
    const SceneLegend& l = *sceneLegend(s);
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
    spec.outline = outline;
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
    for (const OutlinePoint& p : spec.outline.points) {
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
    if (!sceneLegend(s)) return {};
    return meshLegendDots(plateSpec(s, true, legendPlateOutline(s)));
}

Mesh legendPlateMesh(const Scene& s, bool dots) {
    if (!sceneLegend(s) || s.keptCount() == 0) return {};
    return meshLegendPlate(plateSpec(s, dots, legendPlateOutline(s)));
}

std::optional<Attachment> legendAttachment(const Scene& s, Assembly assembly) {
    if (!sceneLegend(s) || s.keptCount() == 0) return std::nullopt;
    const SceneLegend& l = *sceneLegend(s);
    Attachment a;
    a.part = "legend";
    // The plate stands against a hexagon drawn by a face (a mark in the
    // data) along the face's ring, whose points may split the edge.
    const PlateOutline plate = legendPlateOutline(s);
    for (const PlateOutline::Edge& e : plate.edges) {
        if (e.cell < 0) continue;
        if (s.drawn_by_face.empty() || !s.drawn_by_face[size_t(e.cell)])
            a.walls.push_back({e.cell, e.side, l.plate_bottom_units, l.plate_top_units});
        else  // the face's direction runs against the plate's outline
            a.ring_walls.push_back({plate.points[e.b].lattice, plate.points[e.a].lattice, l.plate_bottom_units, l.plate_top_units});
    }
    PlateSpec spec = plateSpec(s, /*dots=*/true, plate);
    if (assembly == Assembly::Parts) {
        a.own_part = meshLegendDots(spec);
        spec.dots.clear();  // the plate stays with the pillars, the dots are the legend's part
    }
    a.joined = meshPlateBody(spec, /*joined=*/true);
    return a;
}

std::optional<BoxMm> legendBoxMm(const Scene& s) {
    if (!sceneLegend(s)) return std::nullopt;
    const SceneLegend& l = *sceneLegend(s);
    return BoxMm{l.x0_mm, l.plate_east_mm, l.plate_south_mm, l.plate_north_mm};
}

std::optional<FootprintClaim> legendClaim(const Scene& s) {
    const std::optional<BoxMm> box = legendBoxMm(s);
    if (!box) return std::nullopt;
    return FootprintClaim{*box, "the braille legend's plate", "--title/--units (the plate north of the pillars)"};
}

std::optional<int64_t> legendTopAt(const Scene& s, double x, double y) {
    if (!sceneLegend(s)) return std::nullopt;
    const SceneLegend& l = *sceneLegend(s);
    if (x > l.plate_east_mm || y < l.plate_south_mm || y > l.plate_north_mm) return std::nullopt;
    return l.plate_top_units;
}

ProbeSet legendProbes(const Scene& s) {
    ProbeSet set{"legend", "the legend plate and every braille dot at its height", {}};
    if (!sceneLegend(s)) return set;
    std::vector<SurfaceProbe>& out = set.probes;
    const SceneLegend& l = *sceneLegend(s);
    const double plate_z = s.zMm(l.plate_top_units);
    const double y = snapXy(l.plate_north_mm - kPlateProbeInsetMm);
    out.push_back({"the legend plate's top (west end)", snapXy(kPlateProbeInsetMm), y, false, plate_z});
    out.push_back({"the legend plate's top (east end)", snapXy(l.plate_east_mm - kPlateProbeInsetMm), y, false,
                   plate_z});
    // The dome's apex is a vertex of the drawn dot (gen/model/features/legend/legend_mesh.h),
    // on the 1 um grid like every coordinate of the model.
    const BrailleStandard& st = l.layout.standard;
    const double apex_z = snapXy(plate_z + st.dot_height_mm);
    // The facets at a dome's apex are less steep than the cone from the apex
    // to the base's rim; twice that slope bounds them.
    const double apex_slope = 2.0 * st.dot_height_mm / (0.5 * st.dot_base_mm);
    for (size_t i = 0; i < l.layout.dots.size(); ++i) {
        const LegendDot& d = l.layout.dots[i];
        out.push_back({"braille dot " + std::to_string(i + 1) + " of " + std::to_string(l.layout.dots.size()),
                       snapXy(d.x_mm + l.x0_mm), snapXy(d.y_mm + l.y0_mm), false, apex_z, apex_slope});
    }
    return set;
}

}  // namespace tsf
