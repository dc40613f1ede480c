// See tiles_check.h.
#include "verify/tiles_check.h"

#include <algorithm>
#include <cmath>

#include "gen/model/features/tiles.h"
#include "gen/model/features/top_shapes.h"
#include "verify/detail/format.h"

namespace tsf {
namespace {

Check makeCheck(const char* id, const char* title, CheckStatus status, int64_t count, const std::string& note) {
    Check c;
    c.id = id;
    c.title = title;
    c.status = status;
    c.count = count;
    c.note = note;
    c.stage = "tiles";
    return c;
}

}  // namespace

bool TilesCheckResult::passed() const {
    return std::all_of(checks.begin(), checks.end(), [](const Check& c) { return c.status != CheckStatus::Fail; });
}

TilesCheckResult checkTiles(const Scene& whole, const Mesh& whole_mesh, const std::vector<const Scene*>& tiles,
                            const std::vector<const Mesh*>& meshes, const TilesCheckInput& in) {
    TilesCheckResult r;
    TilesCheckFigures& f = r.figures;

    // Every cell once, at its own span.
    const HexGrid& g = whole.grid;
    std::vector<int32_t> seen(size_t(g.cellCount()), 0);
    int64_t wrong = 0, extra = 0;
    std::string first;
    const auto note = [&](const std::string& what) {
        ++wrong;
        if (first.empty()) first = what;
    };
    for (const Scene* t : tiles) {
        for (size_t k = 0; k < t->keptCount(); ++k) {
            const int32_t c = t->col[k], row = t->row[k];
            const int32_t w = whole.keptAt(c, row);
            const std::string at = "cell (" + std::to_string(c) + ", " + std::to_string(row) + ")";
            if (w < 0) {
                ++extra;
                note(at + " is in a tile but not in the model");
                continue;
            }
            ++seen[size_t(g.index(c, row))];
            const size_t wk = size_t(w);
            if (t->top[k] != whole.top[wk] || t->bottom[k] != whole.bottom[wk])
                note(at + " spans " + std::to_string(t->bottom[k]) + ".." + std::to_string(t->top[k]) + " z units in its tile, " +
                     std::to_string(whole.bottom[wk]) + ".." + std::to_string(whole.top[wk]) + " in the model");
            if (t->kind[k] != whole.kind[wk]) note(at + " is of another kind in its tile");
            for (int e = 0; e < kHexCorners; ++e)
                if (cornerTop(*t, k, e) != cornerTop(whole, wk, e)) {
                    note(at + "'s top is shaped otherwise in its tile");
                    break;
                }
            if (centreTop(*t, k) != centreTop(whole, wk)) note(at + "'s top centre is at another height in its tile");
            const bool mark_t = !t->drawn_by_face.empty() && t->drawn_by_face[k];
            const bool mark_w = !whole.drawn_by_face.empty() && whole.drawn_by_face[wk];
            if (mark_t != mark_w) note(at + (mark_w ? " carries a mark in the model, not in its tile" : " carries a mark in its tile only"));
        }
    }
    int64_t missing = 0, twice = 0;
    for (size_t k = 0; k < whole.keptCount(); ++k) {
        const int32_t n = seen[size_t(g.index(whole.col[k], whole.row[k]))];
        if (n == 0) ++missing;
        if (n > 1) ++twice;
        if (n != 1)
            note("cell (" + std::to_string(whole.col[k]) + ", " + std::to_string(whole.row[k]) + ") is in " + std::to_string(n) + " tiles");
    }
    r.checks.push_back(makeCheck("tiles_cells", "every cell in one tile, at its height", wrong == 0 ? CheckStatus::Pass : CheckStatus::Fail, wrong,
                                 wrong == 0 ? std::to_string(whole.keptCount()) + " cells in " + std::to_string(tiles.size()) +
                                                  " tiles, each once, at the model's heights and marks"
                                            : std::to_string(wrong) + " wrong (" + std::to_string(missing) + " missing, " +
                                                  std::to_string(twice) + " twice, " + std::to_string(extra) + " extra); first: " + first));

    // The material: the tiles' volumes against the whole's less the pits.
    f.whole_volume_mm3 = signedVolume(whole_mesh);
    for (const Mesh* m : meshes) f.tiles_volume_mm3 += signedVolume(*m);
    for (const Scene* t : tiles)
        for (const BottomHole& h : tileBottomHoles(*t)) f.pits_volume_mm3 += bottomHoleVolumeMm3(*t, h);
    f.volume_error_mm3 = f.tiles_volume_mm3 - (f.whole_volume_mm3 - f.pits_volume_mm3);
    // Float sums over the models' triangles (and float32 files): a relative 1e-6.
    const double tolerance = 1e-6 * std::max(1.0, std::fabs(f.whole_volume_mm3));
    const bool volume_ok = std::fabs(f.volume_error_mm3) <= tolerance;
    r.checks.push_back(makeCheck("tiles_volume", "the tiles are the model's material less the code pits",
                                 volume_ok ? CheckStatus::Pass : CheckStatus::Fail, volume_ok ? 0 : 1,
                                 detail::fmtMm(f.tiles_volume_mm3) + " mm^3 in the tiles vs " + detail::fmtMm(f.whole_volume_mm3) + " - " +
                                     detail::fmtMm(f.pits_volume_mm3) + " mm^3 (difference " + detail::fmtNum(f.volume_error_mm3) +
                                     " mm^3, tolerance " + detail::fmtNum(tolerance) + ")"));

    // Each tile fits the bed.
    int64_t too_big = 0;
    for (const Mesh* m : meshes) {
        if (m->positions.empty()) continue;
        const Bounds b = meshBounds(*m);
        const double w = b.max.x - b.min.x, d = b.max.y - b.min.y;
        f.largest_width_mm = std::max(f.largest_width_mm, w);
        f.largest_depth_mm = std::max(f.largest_depth_mm, d);
        too_big += w > in.bed_width_mm + 1e-6 || d > in.bed_depth_mm + 1e-6;
    }
    r.checks.push_back(makeCheck("tiles_fit", "every tile fits the bed", too_big == 0 ? CheckStatus::Pass : CheckStatus::Fail, too_big,
                                 "largest tile " + detail::fmtMm(f.largest_width_mm) + " x " + detail::fmtMm(f.largest_depth_mm) +
                                     " mm; the bed less its margins " + detail::fmtMm(in.bed_width_mm) + " x " +
                                     detail::fmtMm(in.bed_depth_mm) + " mm"));

    // Teeth: a seam without one is a warning (the tiles still go together,
    // by their outline and their codes).
    const bool teeth_ok = in.bare_seams == 0;
    r.checks.push_back(makeCheck("tiles_teeth", "dovetail teeth along the seams", teeth_ok ? CheckStatus::Pass : CheckStatus::Warn,
                                 in.bare_seams,
                                 std::to_string(in.teeth) + " teeth on " + std::to_string(in.seams) + " seams" +
                                     (teeth_ok ? "" : "; " + std::to_string(in.bare_seams) + (in.bare_seams == 1 ? " seam" : " seams") + " too short for one")));
    return r;
}

}  // namespace tsf
