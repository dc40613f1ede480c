#include "gen/model/probes.h"

#include <cmath>
#include <sstream>

#include "gen/util/number_format.h"

namespace tsf {
namespace {


// How far inside the legend plate's north edge and its ends its top is
// probed, mm: north of the braille (margins are 3 mm) and clear of the edge.
constexpr double kPlateProbeInsetMm = 1.0;

void legendProbes(const Scene& s, std::vector<SurfaceProbe>& out) {
    if (!s.legend) return;
    const SceneLegend& l = *s.legend;
    const double plate_z = s.zMm(l.plate_top_units);
    const double y = snapXy(l.plate_north_mm - kPlateProbeInsetMm);
    out.push_back({"legend", "the legend plate's top (west end)", snapXy(kPlateProbeInsetMm), y, false, plate_z});
    out.push_back({"legend", "the legend plate's top (east end)", snapXy(l.plate_east_mm - kPlateProbeInsetMm), y, false,
                   plate_z});
    // The dome's apex is a vertex of the drawn dot (gen/model/features/legend_mesh.h),
    // on the 1 um grid like every coordinate of the model.
    const BrailleStandard& st = l.layout.standard;
    const double apex_z = snapXy(plate_z + st.dot_height_mm);
    // The facets at a dome's apex are less steep than the cone from the apex
    // to the base's rim; twice that slope bounds them.
    const double apex_slope = 2.0 * st.dot_height_mm / (0.5 * st.dot_base_mm);
    for (size_t i = 0; i < l.layout.dots.size(); ++i) {
        const LegendDot& d = l.layout.dots[i];
        out.push_back({"legend", "braille dot " + std::to_string(i + 1) + " of " + std::to_string(l.layout.dots.size()),
                       snapXy(d.x_mm + l.x0_mm), snapXy(d.y_mm + l.y0_mm), false, apex_z, apex_slope});
    }
}

void scaleProbes(const Scene& s, std::vector<SurfaceProbe>& out) {
    if (!s.scale) return;
    const SceneScale& sc = *s.scale;
    out.push_back({"scale", "the scale's foot (the floor)", 0.5 * (sc.x0_mm + sc.xs_mm), 0.5 * (sc.y0_mm + sc.y1_mm),
                   false, s.zMm(sc.foot_top_units)});
    for (const ScaleStep& st : sc.steps)
        out.push_back({"scale", "the step for " + formatSignificant(st.value), 0.5 * (sc.xs_mm + sc.x1_mm),
                       0.5 * (st.y_south_mm + st.y_north_mm), false, s.zMm(st.top_units)});
}

PlanarPoint lerp(const PlanarPoint& a, const PlanarPoint& b, double t) {
    return {a.i + t * (b.i - a.i), a.j + t * (b.j - a.j)};
}

// The orientation tab (gen/model/features/orientation_tab.h): its top at the
// floor near its north-west corner, the triangle as above, and along the
// notch's diagonal a point 0.3 mm short of the apex (empty: the V reaches its
// full depth) and one 0.3 mm beyond it (the tab's top: no deeper).
void tabProbes(const Scene& s, std::vector<SurfaceProbe>& out) {
    const OrientationTab& t = *s.marks.tab;
    const double floor_mm = s.zMm(t.top_units);
    out.push_back({"marks", "the orientation tab's top", t.x_west_mm + 1.0, t.y_north_mm - 1.0, false, floor_mm});
    if (t.has_triangle) {
        const double z = s.zMm(t.top_units + t.triangle_raise_units);
        const double cx = (t.triangle[0].x_mm + t.triangle[1].x_mm + t.triangle[2].x_mm) / 3;
        const double cy = (t.triangle[0].y_mm + t.triangle[1].y_mm + t.triangle[2].y_mm) / 3;
        const char* names[] = {"the orientation triangle's right-angle corner", "the orientation triangle's east corner",
                               "the orientation triangle's north corner"};
        out.push_back({"marks", "the orientation triangle's middle", cx, cy, false, z});
        for (int n = 0; n < 3; ++n)
            out.push_back({"marks", names[n], t.triangle[n].x_mm + 0.2 * (cx - t.triangle[n].x_mm),
                           t.triangle[n].y_mm + 0.2 * (cy - t.triangle[n].y_mm), false, z});
    }
    if (t.has_notch) {
        const double along = 1.0 / std::sqrt(2.0);
        for (const double d : {t.notch_depth_mm - 0.3, t.notch_depth_mm + 0.3}) {
            const bool inside = d < t.notch_depth_mm;
            out.push_back({"marks", inside ? "inside the orientation notch, 0.3 mm short of its apex" : "the tab just beyond the notch's apex",
                           t.x_west_mm + d * along, t.y_south_mm + d * along, inside, inside ? 0.0 : floor_mm});
        }
    }
}

void markProbes(const Scene& s, std::vector<SurfaceProbe>& out) {
    if (s.marks.tab) tabProbes(s, out);
    if (const auto& t = s.marks.triangle; t && t->anchor >= 0 && size_t(t->anchor) < s.keptCount()) {
        const double z = s.zMm(s.top[size_t(t->anchor)] + t->raise_units);
        const PlanarPoint centroid{(t->corner.i + t->east.i + t->north.i) / 3, (t->corner.j + t->east.j + t->north.j) / 3};
        // A fifth of the way from each corner to the centroid: inside the
        // triangle, so a triangle moved or shrunk by more than that is missed.
        const std::pair<const char*, PlanarPoint> places[] = {
            {"the orientation triangle's middle", centroid},
            {"the orientation triangle's right-angle corner", lerp(t->corner, centroid, 0.2)},
            {"the orientation triangle's east corner", lerp(t->east, centroid, 0.2)},
            {"the orientation triangle's north corner", lerp(t->north, centroid, 0.2)},
        };
        for (const auto& [what, p] : places) {
            const Vec3 q = s.point(p, 0);
            out.push_back({"marks", what, q.x, q.y, false, z});
        }
    }
    if (const auto& n = s.marks.notch) {
        // A quarter of the way from the V's apex to the middle of its mouth:
        // inside the model's outline, inside the cut.
        const PlanarPoint mouth{0.5 * (n->mouth_a.i + n->mouth_b.i), 0.5 * (n->mouth_a.j + n->mouth_b.j)};
        const Vec3 q = s.point(lerp(n->apex, mouth, 0.25), 0);
        out.push_back({"marks", "inside the orientation notch", q.x, q.y, true, 0});
    }
}

}  // namespace

const std::vector<AttachmentKind>& attachmentKinds() {
    static const std::vector<AttachmentKind> kinds = {
        {"legend", "the legend plate and every braille dot at its height"},
        {"scale", "every step of the tactile scale at its value's height"},
        {"marks", "the orientation triangle at its height and the notch cut through"},
    };
    return kinds;
}

std::vector<SurfaceProbe> attachmentProbes(const Scene& s) {
    std::vector<SurfaceProbe> out;
    legendProbes(s, out);
    scaleProbes(s, out);
    markProbes(s, out);
    return out;
}

}  // namespace tsf
