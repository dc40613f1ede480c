// See tile_code.h.
#include "gen/model/features/tile_code.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "gen/model/features/bottom_hole_ring.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {

void placeTileCode(Scene& s) {
    SceneTile t;
    t.place = s.params.requests.get<TileRequest>()->place;
    const double narrowest = s.pitch_mm * std::min(1.0, s.y_scale);
    double radius = std::min(kTileCodePitRadiusMm, 0.3 * narrowest);
    if (radius < kTileCodeMinPitRadiusMm) radius = std::min(kTileCodeMinPitRadiusMm, 0.5 * narrowest - 0.2);
    const int64_t wall = std::max<int64_t>(1, snapUnits(kTileCodePitWallMm, s.z_snap_mm));
    const int64_t apex = wall + std::max<int64_t>(1, int64_t(std::ceil(kHoleConeRatio * radius / s.z_snap_mm - 1e-9)));
    const int64_t roof = snapUnits(kTileCodeRoofMm, s.z_snap_mm);
    // Pits a fingertip tells apart: at least kTileCodeSpacingMm between centres.
    const int32_t east_step = std::max(1, int32_t(std::ceil(kTileCodeSpacingMm / s.pitch_mm - 1e-9)));
    const double row_mm = s.pitch_mm * kSqrt3 / 2 * s.y_scale;
    const int32_t south_step = 2 * std::max(1, int32_t(std::ceil(kTileCodeSpacingMm / (2 * row_mm) - 1e-9)));
    // A pit under a cell inside the tile: its neighbours all there and
    // holding data, so no outer wall or no-data pit comes near it.
    const auto inside = [&](int32_t k) {
        for (int e = 0; e < kHexCorners; ++e) {
            const int32_t o = s.keptNeighbour(size_t(k), e);
            if (o < 0 || s.kind[size_t(o)] != CellKind::Data) return false;
        }
        return true;
    };
    const auto usable = [&](int32_t k) {
        return k >= 0 && inside(k) && s.kind[size_t(k)] == CellKind::Data && s.bottom[size_t(k)] == 0 &&
               (s.drawn_by_face.empty() || !s.drawn_by_face[size_t(k)]) && s.top[size_t(k)] - roof >= apex;
    };
    const auto codeAt = [&](size_t corner) {
        std::vector<int32_t> cells{int32_t(corner)};
        for (int32_t e = 1; e <= t.place.col + 1; ++e) cells.push_back(s.keptAt(s.col[corner] + e * east_step, s.row[corner]));
        for (int32_t n = 1; n <= t.place.row + 1; ++n) cells.push_back(s.keptAt(s.col[corner], s.row[corner] + n * south_step));
        for (int32_t k : cells)
            if (!usable(k)) return std::vector<int32_t>();
        return cells;
    };
    // The L nearest the tile's middle.
    double cx = 0, cy = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        const Vec3 p = s.point(hexCentre(s.grid, s.col[k], s.row[k]), 0);
        cx += p.x;
        cy += p.y;
    }
    cx /= double(std::max<size_t>(1, s.keptCount()));
    cy /= double(std::max<size_t>(1, s.keptCount()));
    std::vector<std::pair<double, size_t>> order;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        const Vec3 p = s.point(hexCentre(s.grid, s.col[k] + (t.place.col + 1) * east_step / 2, s.row[k] + (t.place.row + 1) * south_step / 2), 0);
        order.push_back({std::hypot(p.x - cx, p.y - cy), k});
    }
    std::sort(order.begin(), order.end());
    if (radius >= 0.3)
        for (const auto& [dist, k] : order) {
            std::vector<int32_t> cells = codeAt(k);
            if (cells.empty()) continue;
            t.code_cells = std::move(cells);
            t.pit_radius_mm = radius;
            for (int32_t c : t.code_cells) {
                const LatticePoint centre = hexCentre(s.grid, s.col[size_t(c)], s.row[size_t(c)]);
                t.code_pits.push_back({bottomHoleRing(s, centre, radius), centre, wall, apex});
            }
            break;
        }
    if (t.code_cells.empty())
        s.notes.push_back("tile " + tileName(t.place) + " has no room for its code (" + std::to_string(t.place.col + t.place.row + 3) +
                          " pits under cells at least " + formatSignificant(s.zMm(apex + roof), 2) +
                          " mm thick): its place is in its file name only");
    s.features.set(std::move(t));
}

const SceneTile* sceneTile(const Scene& s) { return s.features.get<SceneTile>(); }

void keepTileShare(const HexGrid& grid, const SceneParams& params, std::vector<uint8_t>& keep) {
    const TileRequest* tile = params.requests.get<TileRequest>();
    if (!tile) return;
    // planTiles made each tile one piece.
    if (tile->cells.size() != keep.size()) throw InputError("a tile's cell list does not match the grid");
    for (size_t idx = 0; idx < keep.size(); ++idx) keep[idx] = keep[idx] && tile->cells[idx];
    if (componentCount(grid, keep) != 1) throw InputError("a tile of the model is not one piece");
}

bool tileKeepsLevel(const Scene& s, size_t k) {
    if (const TiledWholeRequest* tiled = s.params.requests.get<TiledWholeRequest>();
        tiled && !tiled->level_cells.empty() && tiled->level_cells[size_t(s.grid.index(s.col[k], s.row[k]))])
        return true;
    const SceneTile* t = sceneTile(s);
    return t && std::find(t->code_cells.begin(), t->code_cells.end(), int32_t(k)) != t->code_cells.end();
}

std::vector<BottomHole> tileBottomHoles(const Scene& s) {
    const SceneTile* t = sceneTile(s);
    return t ? t->code_pits : std::vector<BottomHole>();
}

std::string tileName(const TilePlace& p) {
    return "row " + std::to_string(p.row + 1) + ", column " + std::to_string(p.col + 1);
}

}  // namespace tsf
