// See tiles.h.
#include "gen/model/features/tiles.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>

#include "gen/model/feature_registry.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Tiles that share fewer hexagon edges than this touch at a corner: no seam.
constexpr int64_t kMinSeamEdges = 6;

BoxMm emptyBox() { return {kInf, -kInf, kInf, -kInf}; }

void grow(BoxMm& b, const BoxMm& o) {
    b.x0 = std::min(b.x0, o.x0);
    b.x1 = std::max(b.x1, o.x1);
    b.y0 = std::min(b.y0, o.y0);
    b.y1 = std::max(b.y1, o.y1);
}

BoxMm cellBox(const Scene& s, size_t k) {
    BoxMm b = emptyBox();
    for (int e = 0; e < kHexCorners; ++e) {
        const Vec3 p = s.point(hexCorner(s.grid, s.col[k], s.row[k], e), 0);
        grow(b, {p.x, p.x, p.y, p.y});
    }
    return b;
}

// The kept cells the orientation marks are drawn on or stand against, and
// those of the features a tile keeps whole with them: they stay in one tile.
std::vector<int32_t> markCells(const Scene& s) {
    std::vector<int32_t> out;
    for (size_t k = 0; k < s.drawn_by_face.size(); ++k)
        if (s.drawn_by_face[k]) out.push_back(int32_t(k));
    for (const Feature* f : features())
        if (f->tile_cells)
            for (const int32_t k : f->tile_cells(s)) out.push_back(k);
    if (s.marks.triangle && s.marks.triangle->anchor >= 0) out.push_back(s.marks.triangle->anchor);
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

// One try of the tiling with `rows` x `cols` tiles.
class Tiler {
public:
    Tiler(const Scene& s, int32_t rows, int32_t cols, const BoxMm& all, const std::vector<BoxMm>& cell_boxes)
        : s_(s), rows_(rows), cols_(cols), tile_(s.keptCount(), 0), boxes_(cell_boxes) {
        const double tw = (all.x1 - all.x0) / cols, td = (all.y1 - all.y0) / rows;
        for (size_t k = 0; k < s.keptCount(); ++k) {
            const Vec3 c = s.point(hexCentre(s.grid, s.col[k], s.row[k]), 0);
            const int32_t tc = std::clamp(int32_t(std::floor((c.x - all.x0) / tw)), 0, cols - 1);
            const int32_t tr = std::clamp(int32_t(std::floor((all.y1 - c.y) / td)), 0, rows - 1);
            tile_[k] = tr * cols + tc;
        }
        k_ = std::max(1, int(std::lround(kToothMm / s.pitch_mm)));
    }

    int32_t tileOf(int32_t c, int32_t r) const {
        const int32_t k = s_.keptAt(c, r);
        return k < 0 ? -1 : tile_[size_t(k)];
    }

    // Each piece of the marks (the notch or the tab, the triangle when it
    // stands elsewhere in the data) goes whole to the tile most of it is in.
    // Returns the tile of the piece holding the tab or the notch.
    int32_t gatherMarks(const std::vector<int32_t>& marks, int32_t triangle_anchor) {
        if (marks.empty()) return -1;
        protected_.assign(s_.keptCount(), 0);
        for (int32_t k : marks) protected_[size_t(k)] = 1;
        std::vector<int32_t> piece(s_.keptCount(), -1);
        int32_t pieces = 0, marks_tile = -1;
        for (int32_t start : marks) {
            if (piece[size_t(start)] >= 0) continue;
            std::vector<int32_t> cells{start};
            piece[size_t(start)] = pieces;
            for (size_t n = 0; n < cells.size(); ++n)
                for (int e = 0; e < kHexCorners; ++e) {
                    const int32_t o = s_.keptNeighbour(size_t(cells[n]), e);
                    if (o >= 0 && protected_[size_t(o)] && piece[size_t(o)] < 0) {
                        piece[size_t(o)] = pieces;
                        cells.push_back(o);
                    }
                }
            ++pieces;
            std::map<int32_t, int> count;
            for (int32_t k : cells) ++count[tile_[size_t(k)]];
            int32_t best = count.begin()->first;
            for (const auto& [t, n] : count)
                if (n > count[best]) best = t;
            for (int32_t k : cells) tile_[size_t(k)] = best;
            const bool triangle = std::find(cells.begin(), cells.end(), triangle_anchor) != cells.end();
            if (!triangle || marks_tile < 0) marks_tile = best;
        }
        return marks_tile;
    }

    // Cells cut off from the rest of their tile join a neighbouring tile.
    void makeTilesWhole() {
        const HexGrid& g = s_.grid;
        for (int pass = 0; pass < 64; ++pass) {
            bool changed = false;
            for (int32_t t = 0; t < rows_ * cols_; ++t) {
                std::vector<uint8_t> mask(size_t(g.cellCount()), 0);
                bool any = false;
                for (size_t k = 0; k < s_.keptCount(); ++k)
                    if (tile_[k] == t) mask[size_t(g.index(s_.col[k], s_.row[k]))] = any = 1;
                if (!any) continue;
                std::vector<int32_t> label;
                const int32_t n = labelCellComponents(g, mask, label);
                if (n <= 1) continue;
                std::vector<int64_t> size(size_t(n), 0);
                for (int32_t l : label)
                    if (l >= 0) ++size[size_t(l)];
                // The largest piece stays, and every piece holding a mark
                // (a mark never moves: if that leaves the tile in pieces, the
                // tiling is refused and the next one tried).
                std::vector<uint8_t> stays(size_t(n), 0);
                stays[size_t(std::max_element(size.begin(), size.end()) - size.begin())] = 1;
                for (size_t k = 0; k < s_.keptCount(); ++k)
                    if (!protected_.empty() && protected_[k] && tile_[k] == t) stays[size_t(label[size_t(g.index(s_.col[k], s_.row[k]))])] = 1;
                for (size_t k = 0; k < s_.keptCount(); ++k) {
                    if (tile_[k] != t || stays[size_t(label[size_t(g.index(s_.col[k], s_.row[k]))])]) continue;
                    for (int e = 0; e < kHexCorners; ++e) {
                        const int32_t o = s_.keptNeighbour(k, e);
                        if (o >= 0 && tile_[size_t(o)] != t) {
                            tile_[k] = tile_[size_t(o)];
                            changed = true;
                            break;
                        }
                    }
                }
            }
            if (!changed) return;
        }
    }

    // A tile far smaller than the others (a corner of the outline) joins the
    // neighbour it shares the longest seam with, when the two still fit the
    // bed with room for the teeth: fewer, fuller tiles. Returns the marks'
    // tile, which may have joined another.
    int32_t mergeSmallTiles(double w, double d, int32_t marks_tile, const std::vector<BoxMm>& attached) {
        const int32_t n = rows_ * cols_;
        const double room = (2 * k_ + 1) * s_.pitch_mm;
        for (bool merged = true; merged;) {
            merged = false;
            std::vector<int64_t> count(size_t(n), 0);
            for (int32_t t : tile_) ++count[size_t(t)];
            int64_t used = 0, total = 0;
            for (int64_t c : count) used += c > 0, total += c;
            const double mean = double(total) / double(std::max<int64_t>(1, used));
            for (int32_t t = 0; t < n && !merged; ++t) {
                if (count[size_t(t)] == 0 || double(count[size_t(t)]) >= 0.3 * mean) continue;
                std::map<int32_t, int64_t> shared;  // neighbouring tile -> edges in common
                for (size_t k = 0; k < s_.keptCount(); ++k) {
                    if (tile_[k] != t) continue;
                    for (int e = 0; e < kHexCorners; ++e) {
                        const int32_t o = s_.keptNeighbour(k, e);
                        if (o >= 0 && tile_[size_t(o)] != t) ++shared[tile_[size_t(o)]];
                    }
                }
                std::vector<std::pair<int64_t, int32_t>> order;
                for (const auto& [o, edges] : shared) order.push_back({-edges, o});
                std::sort(order.begin(), order.end());
                for (const auto& [minus_edges, o] : order) {
                    BoxMm box = emptyBox();
                    for (size_t k = 0; k < s_.keptCount(); ++k)
                        if (tile_[k] == t || tile_[k] == o) grow(box, boxes_[k]);
                    if (t == marks_tile || o == marks_tile)
                        for (const BoxMm& b : attached) grow(box, b);
                    if (box.x1 - box.x0 > w - room || box.y1 - box.y0 > d - room) continue;
                    for (int32_t& x : tile_)
                        if (x == t) x = o;
                    if (marks_tile == t) marks_tile = o;
                    merged = true;
                    break;
                }
            }
        }
        return marks_tile;
    }

    bool allTilesWhole() const {
        for (int32_t t = 0; t < rows_ * cols_; ++t)
            if (!oneTileWhole(t)) return false;
        return true;
    }

    bool oneTileWhole(int32_t t) const {
        const HexGrid& g = s_.grid;
        std::vector<uint8_t> mask(size_t(g.cellCount()), 0);
        bool any = false;
        for (size_t k = 0; k < s_.keptCount(); ++k)
            if (tile_[k] == t) mask[size_t(g.index(s_.col[k], s_.row[k]))] = any = 1;
        return !any || componentCount(g, mask) == 1;
    }

    // Moves `cells` to tile `to` unless it leaves `from` or `to` in pieces or
    // touches a mark.
    bool tryTooth(const std::vector<int32_t>& cells, int32_t from, int32_t to) {
        for (int32_t k : cells)
            if (tile_[size_t(k)] != from || (!protected_.empty() && protected_[size_t(k)])) return false;
        for (int32_t k : cells) tile_[size_t(k)] = to;
        if (oneTileWhole(from) && oneTileWhole(to)) return true;
        for (int32_t k : cells) tile_[size_t(k)] = from;
        return false;
    }

    // Teeth of the west tile into the east one, along the seam between them.
    int32_t verticalSeam(int32_t west, int32_t east) {
        std::map<int32_t, int32_t> seam_col;  // lattice row -> first east cell touching the west tile
        for (size_t k = 0; k < s_.keptCount(); ++k) {
            if (tile_[k] != east) continue;
            if (tileOf(s_.col[k] - 1, s_.row[k]) != west) continue;
            auto [at, fresh] = seam_col.emplace(s_.row[k], s_.col[k]);
            if (!fresh) at->second = std::min(at->second, s_.col[k]);
        }
        if (seam_col.empty()) return 0;
        const int32_t reach = 2 * k_;  // rows each side a tooth needs, its holders included
        std::vector<int32_t> centres;
        for (const auto& [r, c] : seam_col) {
            bool room = true;
            for (int32_t dr = -reach; dr <= reach && room; ++dr) room = seam_col.count(r + dr) > 0;
            if (room) centres.push_back(r);
        }
        return placeTeeth(centres, [&](int32_t rt) {
            std::vector<int32_t> cells;
            for (int32_t dr = -(2 * k_ - 1); dr <= 2 * k_ - 1; ++dr)
                for (int32_t u = 0; u < 2 * k_; ++u) {
                    const int32_t r = rt + dr, c = seam_col.at(r) + u;
                    const int32_t kk = s_.keptAt(c, r);
                    const bool neck = u < k_ && std::abs(dr) <= k_ - 1, head = u >= k_;
                    if (kk < 0 || tile_[size_t(kk)] != east) return std::vector<int32_t>();  // a hole: no tooth
                    if (neck || head) cells.push_back(kk);
                }
            return cells;
        }, west, east);
    }

    // Teeth of the north tile into the south one.
    int32_t horizontalSeam(int32_t north, int32_t south) {
        std::map<int32_t, int32_t> first_row;  // lattice column -> first south row touching the north tile
        for (size_t k = 0; k < s_.keptCount(); ++k) {
            if (tile_[k] != south) continue;
            const int32_t ne = s_.keptNeighbour(k, 1), nw = s_.keptNeighbour(k, 2);
            if (!((ne >= 0 && tile_[size_t(ne)] == north) || (nw >= 0 && tile_[size_t(nw)] == north))) continue;
            auto [at, fresh] = first_row.emplace(s_.col[k], s_.row[k]);
            if (!fresh) at->second = std::min(at->second, s_.row[k]);
        }
        if (first_row.empty()) return 0;
        const int32_t reach = 2 * k_ + 1;  // columns each side a tooth needs, its holders included
        std::vector<int32_t> centres;
        for (const auto& [c, r] : first_row) {
            bool room = true;
            for (int32_t dc = -reach; dc <= reach && room; ++dc) {
                const auto at = first_row.find(c + dc);
                room = at != first_row.end() && at->second == r;
            }
            if (room) centres.push_back(c);
        }
        return placeTeeth(centres, [&](int32_t ct) {
            const int32_t r0 = first_row.at(ct);
            const int32_t it = 2 * ct + (r0 & 1);  // half pitches from the west
            std::vector<int32_t> cells;
            for (int32_t d = 0; d < 2 * k_; ++d) {
                const int32_t r = r0 + d;
                for (int32_t c = ct - 2 * k_ - 1; c <= ct + 2 * k_ + 1; ++c) {
                    const int32_t di = std::abs(2 * c + (r & 1) - it);
                    const bool neck = d < k_ && di <= 2 * k_ - 1, head = d >= k_ && di <= 4 * k_ - 3;
                    const bool holder = d < k_ && di > 2 * k_ - 1 && di <= 4 * k_ - 1;
                    if (!neck && !head && !holder) continue;
                    const int32_t kk = s_.keptAt(c, r);
                    if (kk < 0 || tile_[size_t(kk)] != south) return std::vector<int32_t>();
                    if (neck || head) cells.push_back(kk);
                }
            }
            return cells;
        }, north, south);
    }

    // Up to two teeth, at a third and two thirds of the seam's candidate places.
    template <class Cells>
    int32_t placeTeeth(const std::vector<int32_t>& centres, Cells cellsAt, int32_t from_tile, int32_t into_tile) {
        const int32_t before = teeth_;
        placeTeethOn(centres, cellsAt, from_tile, into_tile);
        return teeth_ - before;
    }
    template <class Cells>
    void placeTeethOn(const std::vector<int32_t>& centres, Cells cellsAt, int32_t from_tile, int32_t into_tile) {
        if (centres.empty()) return;
        const size_t n = centres.size();
        std::vector<size_t> wanted = n >= size_t(8 * k_ + 2) ? std::vector<size_t>{n / 3, (2 * n) / 3} : std::vector<size_t>{n / 2};
        int32_t last = std::numeric_limits<int32_t>::min() / 2;
        for (size_t w : wanted) {
            const int32_t at = centres[w];
            if (at - last < 4 * k_ + 2) continue;
            const std::vector<int32_t> cells = cellsAt(at);
            if (cells.empty()) continue;
            if (tryTooth(cells, into_tile, from_tile)) {
                ++teeth_;
                last = at;
            }
        }
    }

    // Every pair of tiles that share an edge is a seam (after merging, not
    // only neighbours in the grid). A seam gets its teeth from the west (or
    // north) tile where the grid says which that is, else whichever way
    // finds room; a seam with none is counted bare.
    void teeth() {
        std::map<std::pair<int32_t, int32_t>, int64_t> pairs;  // -> hexagon edges in common (each counted twice)
        for (size_t k = 0; k < s_.keptCount(); ++k)
            for (int e = 0; e < kHexCorners; ++e) {
                const int32_t o = s_.keptNeighbour(k, e);
                if (o >= 0 && tile_[size_t(o)] != tile_[k])
                    ++pairs[{std::min(tile_[k], tile_[size_t(o)]), std::max(tile_[k], tile_[size_t(o)])}];
            }
        for (const auto& [pair, twice] : pairs) {
            const auto [a, b] = pair;
            // A few edges where four tiles meet are a corner, not a seam.
            if (twice / 2 < kMinSeamEdges) continue;
            ++seams_;
            const bool east = b == a + 1 && a / cols_ == b / cols_, south = b == a + cols_;
            int32_t placed = east ? verticalSeam(a, b) : south ? horizontalSeam(a, b) : 0;
            if (placed == 0 && !east && !south) placed = verticalSeam(a, b);
            if (placed == 0 && !east && !south) placed = horizontalSeam(a, b);
            if (placed == 0 && !east && !south) placed = verticalSeam(b, a);
            if (placed == 0 && !east && !south) placed = horizontalSeam(b, a);
            bare_ += placed == 0;
        }
    }

    TileLayout layout(int32_t marks_tile, const std::vector<BoxMm>& attached) const {
        TileLayout L;
        L.rows = rows_;
        L.cols = cols_;
        L.teeth = teeth_;
        L.seams = seams_;
        L.bare_seams = bare_;
        L.marks_tile = marks_tile;
        if (s_.marks.triangle && s_.marks.triangle->anchor >= 0) L.triangle_tile = tile_[size_t(s_.marks.triangle->anchor)];
        L.tooth_cells = k_;
        L.boxes.assign(size_t(rows_ * cols_), emptyBox());
        L.cells.assign(size_t(rows_ * cols_), 0);
        L.tile_of_cell.assign(size_t(s_.grid.cellCount()), -1);
        for (size_t k = 0; k < s_.keptCount(); ++k) {
            const int32_t t = tile_[k];
            L.tile_of_cell[size_t(s_.grid.index(s_.col[k], s_.row[k]))] = t;
            grow(L.boxes[size_t(t)], boxes_[k]);
            ++L.cells[size_t(t)];
        }
        if (marks_tile >= 0)
            for (const BoxMm& b : attached) grow(L.boxes[size_t(marks_tile)], b);
        return L;
    }

private:
    const Scene& s_;
    int32_t rows_, cols_;
    std::vector<int32_t> tile_;  // per kept cell
    const std::vector<BoxMm>& boxes_;
    std::vector<uint8_t> protected_;
    int k_ = 1;
    int32_t teeth_ = 0, seams_ = 0, bare_ = 0;
};

bool fits(const TileLayout& L, double w, double d) {
    for (const BoxMm& b : L.boxes)
        if (b.x0 <= b.x1 && (b.x1 - b.x0 > w + 1e-9 || b.y1 - b.y0 > d + 1e-9)) return false;
    return true;
}

}  // namespace

TileLayout planTiles(const Scene& s, const std::vector<BoxMm>& attached, double w, double d) {
    if (const Feature* f = featureRefusingTiles(s))
        throw InputError(std::string("--tile cannot cut what ") + f->option + " adds into tiles (a tile would hold a piece of it); leave out " +
                         f->option + " to tile the model");
    if (s.params.bottom != Bottom::Flat || s.halves || featureTopShaping(s) || s.params.tilt != TiltSource::None)
        throw InputError("--tile cuts a flat model with level tops, without a legend or a scale (not yet with --mirror, "
                         "--tilt, class textures, --title, --units or --scale)");
    if (s.keptCount() == 0) throw InputError("--tile: the model has no cells");
    std::vector<BoxMm> cell_boxes(s.keptCount());
    BoxMm all = emptyBox();
    for (size_t k = 0; k < s.keptCount(); ++k) {
        cell_boxes[k] = cellBox(s, k);
        grow(all, cell_boxes[k]);
    }
    BoxMm everything = all;
    for (const BoxMm& b : attached) grow(everything, b);
    const std::vector<int32_t> marks = markCells(s);
    const int32_t min_cols = std::max(1, int32_t(std::ceil((everything.x1 - everything.x0) / w - 1e-9)));
    const int32_t min_rows = std::max(1, int32_t(std::ceil((everything.y1 - everything.y0) / d - 1e-9)));
    if (s.pitch_mm * 4 > std::min(w, d))
        throw InputError("--tile: cells " + formatSignificant(s.pitch_mm, 3) + " mm across are too large to tile a " +
                         formatSignificant(w, 4) + " x " + formatSignificant(d, 4) + " mm bed: a smaller --cell");
    for (const BoxMm& b : attached)
        if (b.x1 - b.x0 > w || b.y1 - b.y0 > d)
            throw InputError("--tile: the orientation tab is " + formatSignificant(b.x1 - b.x0, 3) + " x " +
                             formatSignificant(b.y1 - b.y0, 3) + " mm, larger than the " + formatSignificant(w, 4) + " x " +
                             formatSignificant(d, 4) + " mm a tile may take on this bed: a larger --bed, or --marks-on data");
    for (int32_t n = min_cols * min_rows; n <= kMaxTileCount; ++n)
        for (int32_t cols = min_cols; cols <= n; ++cols) {
            if (n % cols != 0 || n / cols < min_rows) continue;
            const int32_t rows = n / cols;
            // The tiles split the box of everything: the tab's tile (it goes
            // with the marks) has fewer cells.
            Tiler t(s, rows, cols, everything, cell_boxes);
            int32_t marks_tile = t.gatherMarks(marks, s.marks.triangle ? s.marks.triangle->anchor : -1);
            t.makeTilesWhole();
            marks_tile = t.mergeSmallTiles(w, d, marks_tile, attached);
            t.teeth();
            TileLayout L = t.layout(marks_tile, attached);
            if (fits(L, w, d) && t.allTilesWhole()) return L;
        }
    throw InputError("--tile: no tiling into at most " + std::to_string(kMaxTileCount) + " tiles fits the " +
                     formatSignificant(w, 4) + " x " + formatSignificant(d, 4) + " mm bed: a smaller model (--width, --cell)");
}

SceneParams tileParams(const Scene& whole, const TileLayout& L, int32_t tile) {
    SceneParams p = whole.params;
    // The whole model's z grid (a float32 file's coarser one included) and
    // size: the tile is the same model, cut.
    p.z_snap_mm = whole.z_snap_mm;
    p.pitch_mm = whole.pitch_mm;
    p.fit_box_given = false;
    TileRequest request;
    request.cells.assign(L.tile_of_cell.size(), 0);
    for (size_t idx = 0; idx < L.tile_of_cell.size(); ++idx) request.cells[idx] = L.tile_of_cell[idx] == tile;
    request.place = TilePlace{tile / L.cols, tile % L.cols, L.rows, L.cols};
    const bool notch_here = tile == L.marks_tile && whole.marks.notch;
    const bool triangle_here = tile == L.triangle_tile && whole.marks.triangle;
    const bool carried = carriedMarks(whole).has_value();
    if (tile == L.marks_tile && carried) {
        // A feature carries the marks (below): none in the data.
        request.marks = Marks{};
    } else if (!carried && (notch_here || triangle_here)) {
        // Marks in the data: the model's own, not placed again on fewer cells.
        Marks m;
        if (notch_here) m.notch = whole.marks.notch;
        if (triangle_here) {
            m.triangle = whole.marks.triangle;
            const size_t k = size_t(m.triangle->anchor);
            m.triangle->anchor = int32_t(whole.grid.index(whole.col[k], whole.row[k]));
        }
        request.marks = std::move(m);
    } else if (tile != L.marks_tile || whole.params.marks.place == MarkPlace::Data) {
        // Marks in the data are the model's own (above) or none: a tile
        // never places marks the model does not have.
        const MarkPlace place = p.marks.place;
        p.marks = withoutMarks();
        p.marks.place = place;
    }
    // The features a tile keeps whole go with the marks: the model's own,
    // not placed again against fewer pillars.
    if (tile == L.marks_tile)
        for (const Feature* f : features())
            if (f->carry_into_tile) f->carry_into_tile(whole, p);
    p.requests.set(std::move(request));
    return p;
}


}  // namespace tsf
