#include "gen/scad/scad_tab.h"

#include "gen/model/scene.h"
#include "gen/util/number_format.h"

namespace tsf {

void emitTabData(std::string& o, const Scene& s) {
    if (!s.marks.tab) return;
    const OrientationTab& t = *s.marks.tab;
    auto xy = [](const TabPoint& p) { return "[" + formatShortest(p.x_mm) + ", " + formatShortest(p.y_mm) + "]"; };
    o += "/* [Orientation marks] */\n"
         "// The tab west of the pillars: the notch cut into its south-west corner, the\n"
         "// triangle (right angle south-west, the longer leg east) on its top (docs/model.md).\n"
         "show_orientation_tab = true;\n\n"
         "/* [Hidden] */\n"
         "// The tab as tsf placed it, in mm, for the parameters as generated (it does not\n"
         "// follow cell or base; regenerate with tsf gen to change it).\n"
         "orientation_tab = [[";
    for (size_t n = 0; n < t.outline.size(); ++n) o += (n ? ", " : "") + xy(t.outline[n]);
    o += "], " + formatShortest(s.zMm(t.top_units)) + ", [";
    if (t.has_triangle)
        o += xy(t.triangle[0]) + ", " + xy(t.triangle[1]) + ", " + xy(t.triangle[2]) + "], " +
             formatShortest(s.zMm(t.top_units + t.triangle_raise_units));
    else
        o += "], 0";
    o += ", " + formatShortest(s.zMm(t.bottom_units)) + ", " +
         (t.has_triangle && t.under_triangle ? formatShortest(s.zMm(t.bottom_units - t.triangle_raise_units))
                                             : formatShortest(s.zMm(t.bottom_units)));
    o += "];\n";
    // The tab stands against the pillars' walls where tsf put them: another
    // cell, base, snap or mirror would move the walls away from it.
    o += "assert(!show_orientation_tab || [cell, base, snap, mirror] == [" + formatShortest(s.pitch_mm) + ", " +
         formatShortest(s.params.base_mm) + ", " + formatShortest(s.z_snap_mm) + ", " +
         (s.params.bottom == Bottom::Mirrored ? "true" : "false") +
         "],\n       \"the orientation tab was placed by tsf for the cell, base, snap and mirror it wrote: set "
         "show_orientation_tab = false, or run tsf gen again to change them\");\n\n";
}

std::string tabCallPrefix(const Scene& s) { return s.marks.tab ? "tsf_with_tab(orientation_tab, show_orientation_tab) " : ""; }

}  // namespace tsf
