// Direct mesher: Scene -> exact boundary mesh. See direct_mesher.h.
//
// Vertices. A mesh vertex is a lattice vertex (dense id from hex_grid.h) at a
// snapped height. The heights used at a lattice vertex are the tops of its
// kept incident cells, plus their bottoms where a bottom face touches it
// (mirrored: always; flat: only on the rim, where the bottom polygon passes).
// They are enumerated from the lattice, so no float is ever compared.
//
// Walls. Along edge k of kept cell a, the wall is the part of a's z interval
// that the neighbour b does not cover (all of it if b is not kept). Each wall
// piece is a vertical planar polygon whose two vertical sides carry every
// height used at their lattice vertex; it is triangulated by a zipper that
// always takes one point from each side, so no triangle is degenerate.
//
// Flat bottom. The rim of the kept region is one simple polygon (hexagons
// meet three to a vertex, so the region's boundary never pinches, and the
// culling rules keep the region simply connected: docs/model.md). It is
// triangulated as a whole by a constrained Delaunay triangulation with exact
// predicates, with the interior lattice vertices of a coarse sublattice
// (every kSparseStride-th row and column, staggered) as extra vertices: the
// triangles stay a few cells across instead of spanning the model, so a ray
// from below meets a handful of tree boxes, not thousands.
//
// Merged tops. Edge-connected plain level cells of one top height (not tilted,
// not dimpled, not drawn by a face) form a region whose top is one planar
// polygon (with holes). A lattice vertex whose three cells all lie in one
// region carries nothing but that top, so it is left out, except on the
// sparse sublattice; the region's boundary keeps every vertex the walls use,
// so there is no T-junction. A region with no vertex left out keeps its
// per-cell hexagons (the same triangle count, better shaped). The polygon is
// triangulated like the flat bottom. Only the tops merge: mirrored bottoms
// stay per cell.
//
// Faces. Cells touched by an orientation mark are drawn through the Scene's
// planar faces (gen/model/features/marks.h) instead of as hexagons: the same rules with the
// face's own triangulation, rings and what lies across each ring edge. Their
// extra vertices (where a mark's edge crosses a hex edge) have planar ids after
// the lattice's, so everything above holds for them unchanged.
//
// Shaped tops (gen/model/features/top_shapes.h). A tilted or dimpled cell's top (and
// mirrored bottom) is a fan from its centre vertex over its corners and the
// crossing points on its edges; each corner has the cell's own height there,
// so the heights used at a lattice vertex are its cells' corner heights. A
// wall is the part of the owner's span that the neighbour's does not cover,
// taken at both ends of the edge (the tops are straight lines along it); where
// the two tops cross, the wall is a triangle on each side of the crossing
// point, which has planar id of its own and one height.
#include "gen/mesh/direct_mesher.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <map>
#include <optional>
#include <thread>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "gen/geometry/cdt_parity.h"
#include "gen/util/union_find.h"
#include "gen/util/workers.h"

#include "gen/model/attachments.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/scene_check.h"

namespace tsf {
namespace {

constexpr int kMaxHeightsPerVertex = 12;  // 3 incident cells x (top, bottom), a bottom point, a foot's two, or faces at a mark vertex
// Merged tops and the flat bottom keep the lattice vertices of rows and
// columns that are multiples of this (staggered by half): their triangles are
// at most a few cells long, for about 2 / kSparseStride^2 triangles a cell.
constexpr int32_t kSparseStride = 4;
constexpr uint32_t kNotMerged = UINT32_MAX;
// Below this many kept cells the mesher runs on one thread (a thread costs
// more than meshing a few thousand cells).
constexpr size_t kParallelCells = 20000;
// Triangles a cell of a flat model usually has (top, walls, its share of the
// bottom; 10.4 on a 1000 x 1000 terrain); mirrored, twice as many.
constexpr size_t kTypicalTrianglesPerCell = 12;

using Triangles = std::vector<std::array<uint32_t, 3>>;
// Where tri() appends on this thread: each worker of a parallel pass has its
// own list, joined in row order afterwards, so the mesh is the same for any
// number of threads.
thread_local Triangles* t_sink = nullptr;

// Runs work(part) for part = 0 .. parts-1 on as many threads.
template <class Work>
void runParts(unsigned parts, const Work& work) {
    detail::runOnWorkers(parts, [&](unsigned part, const std::atomic<bool>&) { work(part); });
}

class MeshBuilder {
public:
    MeshBuilder(const Scene& scene, const std::vector<Attachment>& attachments)
        : s_(scene),
          g_(scene.grid),
          flat_(scene.params.bottom == Bottom::Flat),
          lattice_ids_(latticeVertexIdCount(g_)),
          attachments_(attachments),
          holes_(sceneBottomHoles(scene)) {
        const int64_t ids = lattice_ids_ + int64_t(s_.faces.extra.size()) + int64_t(s_.shapes.extra.size());
        first_index_.assign(size_t(ids) + 1, 0);
        const auto& faces = s_.faces.faces;
        for (size_t f = 0; f < faces.size(); ++f)
            for (const auto& ring : faces[f].rings)
                for (int64_t id : ring) {
                    auto& at = faces_at_[id];
                    if (std::find(at.begin(), at.end(), int32_t(f)) == at.end()) at.push_back(int32_t(f));
                }
        // The attachments' feet (gen/model/scene_attachments.h) that stand
        // against pillar walls, each over its z span.
        for (const Attachment& a : attachments_) {
            for (const WallContact& c : a.walls) addFoot(c.kept, c.edge, {c.bottom_units, c.top_units});
            for (const RingContact& c : a.ring_walls) {
                const Span band{c.bottom_units, c.top_units};
                foot_ring_edges_[{c.from, c.to}] = band;
                addFootHeights(c.from, band);
                addFootHeights(c.to, band);
            }
        }
    }

    Mesh build() {
        // The merged tops and (flat) the rim and the bottom's points read the
        // Scene alone and each fills its own members: side by side.
        runBoth([&] { findMergedTops(); },
                [&] {
                    if (!flat_) return;
                    collectRim();
                    findBottomPoints();
                });
        assignVertices();
        addCells();
        for (const PlanarFace& f : s_.faces.faces) addFace(f);
        addPlanarRegions();
        for (const Attachment& a : attachments_) addJoinedBody(a.joined);
        return std::move(mesh_);
    }

private:
    bool drawnByFace(int32_t kept) const { return !s_.drawn_by_face.empty() && s_.drawn_by_face[size_t(kept)]; }

    // A lattice vertex of the sparse sublattice (staggered rows of every
    // kSparseStride-th top corner): kept inside merged tops and the flat bottom.
    bool onSparseLattice(int64_t id) const {
        if ((id & 1) != 0) return false;
        const int64_t cell = id >> 1, stride = kSparseStride;
        const int64_t c = cell % (int64_t(g_.cols) + 2), r = cell / (int64_t(g_.cols) + 2);
        return r % stride == 0 && (c + (r / stride) % 2 * (stride / 2)) % stride == 0;
    }

    // A plain level cell: its top may join a merged region.
    bool mergeable(int32_t k) const { return k >= 0 && !drawnByFace(k) && !isShaped(s_.shapes, size_t(k)); }

    // The merged region (its root cell) of kept cell k whose three cells at
    // lattice vertex id all belong to it, or kNotMerged.
    uint32_t regionAround(int64_t id, uint32_t root) const {
        int32_t cells[3];
        incidentCells(id, cells);
        for (int32_t c : cells)
            if (c < 0 || region_[size_t(c)] != root) return kNotMerged;
        return faces_at_.count(id) ? kNotMerged : root;
    }

    // Regions of equal-height plain level cells, and the lattice vertices
    // inside them that are left out (dropped_top_).
    void findMergedTops() {
        const size_t n = s_.keptCount();
        region_.assign(n, kNotMerged);
        UnionFind uf(n);
        for (size_t k = 0; k < n; ++k) {
            if (!mergeable(int32_t(k))) continue;
            for (int e = 0; e < 3; ++e) {  // east, north-east, north-west: each pair once
                const int32_t o = s_.keptNeighbour(k, e);
                if (mergeable(o) && s_.top[size_t(o)] == s_.top[k]) uf.unite(uint32_t(k), uint32_t(o));
            }
        }
        for (size_t k = 0; k < n; ++k)
            if (mergeable(int32_t(k))) region_[k] = uf.find(uint32_t(k));
        dropped_top_.assign(size_t(lattice_ids_), 0);
        std::vector<uint8_t> has_dropped(n, 0);
        // A lattice vertex whose three cells all lie in one region carries
        // that top alone: left out, unless on the sparse lattice. Decided
        // vertex by vertex on the threads (each vertex by one); the region
        // hears of it by a store of the same 1 from any thread.
        detail::runOnRanges(threads(), size_t(lattice_ids_), [&](unsigned, size_t from, size_t to) {
            for (size_t id = from; id < to; ++id) {
                if (onSparseLattice(int64_t(id))) continue;
                int32_t cells[3];
                incidentCells(int64_t(id), cells);
                if (cells[0] < 0 || region_[size_t(cells[0])] == kNotMerged) continue;
                const uint32_t root = region_[size_t(cells[0])];
                if (regionAround(int64_t(id), root) == kNotMerged) continue;
                dropped_top_[id] = 1;
                std::atomic_ref<uint8_t>(has_dropped[root]).store(1, std::memory_order_relaxed);
            }
        });
        // A region with nothing left out keeps its hexagons.
        for (size_t k = 0; k < n; ++k)
            if (region_[k] != kNotMerged && !has_dropped[region_[k]]) region_[k] = kNotMerged;
    }

    // Flat: the interior lattice vertices of the sparse sublattice at the floor.
    void findBottomPoints() {
        bottom_point_.assign(size_t(lattice_ids_), 0);
        for (size_t k = 0; k < s_.keptCount(); ++k) {
            if (drawnByFace(int32_t(k))) continue;
            for (int e = 0; e < kHexCorners; ++e) {
                const int64_t id = hexCornerId(g_, s_.col[k], s_.row[k], e);
                if (!onSparseLattice(id) || bottom_point_[size_t(id)] || rim_.count(id) || faces_at_.count(id)) continue;
                int32_t cells[3];
                incidentCells(id, cells);
                bool inside = true;
                for (int32_t c : cells) inside = inside && c >= 0 && !drawnByFace(c);
                if (inside) {
                    bottom_point_[size_t(id)] = 1;
                    bottom_points_.push_back(id);
                }
            }
        }
    }

    // The three cells meeting at a lattice vertex (kept indices; -1 = not kept).
    void incidentCells(int64_t id, int32_t out[3]) const {
        int32_t col[3], row[3];
        latticeVertexCells(g_, id, col, row);
        for (int n = 0; n < 3; ++n) out[n] = s_.keptAt(col[n], row[n]);
    }

    // Sorted distinct heights (snap units) of the mesh vertices at planar vertex id.
    int usedHeights(int64_t id, int64_t out[kMaxHeightsPerVertex]) const {
        int n = 0;
        if (!s_.shapes.empty() && id >= s_.shapes.first_id) {
            out[0] = s_.shapes.extra_z[size_t(id - s_.shapes.first_id)];  // a fan centre or a crossing: one height
            return 1;
        }
        // Most models have a handful of face vertices: skip the lookup when there are none.
        const auto faces = faces_at_.empty() ? faces_at_.end() : faces_at_.find(id);
        const bool touched = faces != faces_at_.end();
        bool rim = false;
        if (id < lattice_ids_) {
            int32_t cells[3];
            incidentCells(id, cells);
            rim = touched ? rim_.count(id) > 0 : (cells[0] < 0 || cells[1] < 0 || cells[2] < 0);
            const bool dropped = dropped_top_[size_t(id)] != 0;
            for (int32_t c : cells) {
                if (c < 0 || drawnByFace(c)) continue;
                // A level cell is at its height at every corner (as addCell
                // draws it), found without searching for the corner.
                const bool shaped = isShaped(s_.shapes, size_t(c));
                if (!dropped) out[n++] = shaped ? cornerTopAt(s_, size_t(c), id) : s_.top[size_t(c)];
                if (!flat_ || rim) out[n++] = shaped ? cornerBottomAt(s_, size_t(c), id) : s_.bottom[size_t(c)];
            }
            if (flat_ && bottom_point_[size_t(id)]) out[n++] = 0;
            // A foot (an attachment's contact) meets the wall of a
            // contact cell at its bottom and top (flat: 0, which the rim has,
            // and the floor).
            if (!foot_heights_.empty())
                if (const auto f = foot_heights_.find(id); f != foot_heights_.end())
                    for (const int64_t z : f->second) {
                        assert(n < kMaxHeightsPerVertex && "too many heights meet at a vertex");
                        out[n++] = z;
                    }
        } else {
            rim = rim_.count(id) > 0;
        }
        if (touched)
            for (int32_t f : faces->second) {
                const PlanarFace& face = s_.faces.faces[size_t(f)];
                assert(n + 2 <= kMaxHeightsPerVertex && "too many faces meet at a vertex");
                out[n++] = s_.faceTop(face);
                if (!flat_ || rim) out[n++] = s_.faceBottom(face);
            }
        std::sort(out, out + n);
        return int(std::unique(out, out + n) - out);
    }

    unsigned threads() const {
        if (s_.keptCount() < kParallelCells) return 1;
        return std::max(1u, std::min(8u, std::thread::hardware_concurrency()));
    }

    // a() and b(), on two threads when the model is large enough for threads.
    template <class A, class B>
    void runBoth(const A& a, const B& b) const {
        runParts(std::min(2u, threads()), [&](unsigned p) {
            if (p == 0) a();
            if (p == 1 || threads() == 1) b();
        });
    }

    // Vertex indices in id order: each thread lists the heights of a range
    // of ids (counting them), the counts are summed, then each places its
    // range's vertices from its list (one usedHeights a vertex id, not two).
    void assignVertices() {
        const int64_t ids = int64_t(first_index_.size()) - 1;
        const unsigned parts = threads();
        const auto range = [&](unsigned p) { return std::pair(ids * p / parts, ids * (p + 1) / parts); };
        std::vector<std::vector<int64_t>> heights(parts);
        runParts(parts, [&](unsigned p) {
            int64_t z[kMaxHeightsPerVertex];
            std::vector<int64_t>& listed = heights[p];
            auto [id, end] = range(p);
            listed.reserve(size_t(end - id) * 3);  // most lattice vertices carry two or three heights
            for (; id < end; ++id) {
                const int n = usedHeights(id, z);
                first_index_[size_t(id)] = uint32_t(n);
                listed.insert(listed.end(), z, z + n);
            }
        });
        uint32_t next = 0;
        for (int64_t id = 0; id < ids; ++id) next += std::exchange(first_index_[size_t(id)], next);
        first_index_[size_t(ids)] = next;
        // Room for what is appended after the lattice's vertices (the pin
        // holes' and the attachments' own): appending then never moves the
        // vertices (a copy of 125 MB at 1000 x 1000).
        size_t appended = 0;
        for (const BottomHole& h : holes_) appended += 2 * h.ring.size() + 1;
        for (const Attachment& a : attachments_)
            appended += size_t(std::count_if(a.joined.lattice_id.begin(), a.joined.lattice_id.end(),
                                             [](int64_t id) { return id < 0; }));
        mesh_.positions.reserve(size_t(next) + appended);
        mesh_.positions.resize(next);
        runParts(parts, [&](unsigned p) {
            const int64_t* z = heights[p].data();
            for (auto [id, end] = range(p); id < end; ++id) {
                const uint32_t first = first_index_[size_t(id)], n = first_index_[size_t(id) + 1] - first;
                if (n == 0) continue;
                // The place is the id's; the heights differ in z alone.
                Vec3 at = s_.planarPoint(id, *z);
                for (uint32_t h = 0; h < n; ++h, ++z) {
                    at.z = s_.zMm(*z);
                    mesh_.positions[first + h] = at;
                }
            }
        });
    }

    // Every cell not drawn by a face, in blocks of rows on the threads; the
    // blocks' triangles are joined in row order.
    void addCells() {
        const size_t n = s_.keptCount();
        const unsigned parts = threads();
        // Room reserved (address space; only what is written takes memory)
        // for a typical cell's triangles, the first part's for all of them
        // and the planar regions': the parts then rarely grow by copying, and
        // the first becomes the mesh's list, the others appended to it.
        const size_t per_cell = flat_ ? kTypicalTrianglesPerCell : 2 * kTypicalTrianglesPerCell;
        std::vector<Triangles> out(parts);
        runParts(parts, [&](unsigned p) {
            const size_t from = n * p / parts, end = n * (p + 1) / parts;
            out[p].reserve((p == 0 ? n + n / 8 : end - from) * per_cell);
            t_sink = &out[p];
            for (size_t k = from; k < end; ++k)
                if (!drawnByFace(int32_t(k))) addCell(k);
            t_sink = nullptr;
        });
        mesh_.triangles = std::move(out[0]);
        size_t total = mesh_.triangles.size();
        for (const Triangles& t : out) total += t.size();
        mesh_.triangles.reserve(total);
        for (unsigned p = 1; p < parts; ++p) {
            mesh_.triangles.insert(mesh_.triangles.end(), out[p].begin(), out[p].end());
            Triangles().swap(out[p]);
        }
    }

    // The vertex at planar vertex id and height z (units). assignVertices
    // placed the vertex of each height used there, at zMm(height); zMm is
    // one-to-one on the z units (a product by the snap, exact to far below
    // a unit), so the vertex whose z is zMm(z) is the one at that height:
    // found among the few of id without listing its heights again (that
    // listing, for each corner of each triangle, was an eighth of the
    // mesher's time).
    uint32_t vertexIndex(int64_t id, int64_t z) const {
        const double z_mm = s_.zMm(z);
        for (uint32_t v = first_index_[size_t(id)], end = first_index_[size_t(id) + 1]; v < end; ++v)
            if (mesh_.positions[v].z == z_mm) return v;
        assert(false && "height not used at this vertex");
        return first_index_[size_t(id)];
    }

    void tri(uint32_t a, uint32_t b, uint32_t c) { (t_sink ? *t_sink : mesh_.triangles).push_back({a, b, c}); }

    struct Span {
        int64_t bottom, top;  // z units at one end of an edge
    };

    int64_t extraZ(int64_t id) const { return s_.shapes.extra_z[size_t(id - s_.shapes.first_id)]; }

    // Walls along edge v -> w of a cell or face spanning a_v at v and a_w at
    // w, where the neighbour's spans (b_v, b_w) do not cover it (no
    // neighbour: all of it). Where the tops (bottoms) cross, the crossing
    // point xt (xb) splits the wall; -1 where they do not.
    void addWalls(int64_t v, int64_t w, Span a_v, Span a_w, bool has_neighbour, Span b_v, Span b_w, int64_t xt = -1,
                  int64_t xb = -1) {
        if (!has_neighbour) {
            addWall(v, a_v.bottom, a_v.top, w, a_w.bottom, a_w.top);
            return;
        }
        assert(b_v.bottom < a_v.top && a_v.bottom < b_v.top && b_w.bottom < a_w.top && a_w.bottom < b_w.top &&
               "neighbouring pillars must overlap in z");
        // Above the neighbour's top.
        const int64_t dv = a_v.top - b_v.top, dw = a_w.top - b_w.top;
        if (dv >= 0 && dw >= 0) {
            if (dv > 0 || dw > 0) addWall(v, b_v.top, a_v.top, w, b_w.top, a_w.top);
        } else if (dv > 0 || dw > 0) {
            assert(xt >= 0 && "crossing tops need their crossing point");
            const int64_t z = extraZ(xt);
            if (dv > 0) addWall(v, b_v.top, a_v.top, xt, z, z);
            else addWall(xt, z, z, w, b_w.top, a_w.top);
        }
        // Below the neighbour's bottom.
        const int64_t ev = b_v.bottom - a_v.bottom, ew = b_w.bottom - a_w.bottom;
        if (ev >= 0 && ew >= 0) {
            if (ev > 0 || ew > 0) addWall(v, a_v.bottom, b_v.bottom, w, a_w.bottom, b_w.bottom);
        } else if (ev > 0 || ew > 0) {
            assert(xb >= 0 && "crossing bottoms need their crossing point");
            const int64_t z = extraZ(xb);
            if (ev > 0) addWall(v, a_v.bottom, b_v.bottom, xb, z, z);
            else addWall(xb, z, z, w, a_w.bottom, b_w.bottom);
        }
    }

    Span cornerSpan(size_t k, int e) const { return {cornerBottom(s_, k, e), cornerTop(s_, k, e)}; }
    Span spanAt(size_t k, int64_t id) const {
        if (!isShaped(s_.shapes, k)) return {s_.bottom[k], s_.top[k]};  // level: the same at every corner
        return {cornerBottomAt(s_, k, id), cornerTopAt(s_, k, id)};
    }

    // A tilted or dimpled cell: fans from its centre, walls by corner.
    void addShapedCell(size_t k) {
        const int32_t c = s_.col[k], r = s_.row[k];
        const TopShapes& t = s_.shapes;
        int64_t id[kHexCorners];
        for (int e = 0; e < kHexCorners; ++e) id[e] = hexCornerId(g_, c, r, e);
        for (int part = 0; part < (flat_ ? 1 : 2); ++part) {
            const bool top = part == 0;
            const auto& crossing = top ? t.crossing_top : t.crossing_bottom;
            const int64_t centre = top ? t.centre_top_id[k] : t.centre_bottom_id[k];
            const uint32_t cv = vertexIndex(centre, extraZ(centre));
            // The ring, counter-clockwise from above: corners, and crossings on the edges.
            uint32_t ring[2 * kHexCorners];
            int n = 0;
            for (int e = 0; e < kHexCorners; ++e) {
                ring[n++] = vertexIndex(id[e], top ? cornerTop(s_, k, e) : cornerBottom(s_, k, e));
                const int64_t x = crossing[kHexCorners * k + size_t(e)];
                if (x >= 0) ring[n++] = vertexIndex(x, extraZ(x));
            }
            for (int i = 0; i < n; ++i) {
                if (top) tri(cv, ring[i], ring[(i + 1) % n]);  // CCW from above
                else tri(cv, ring[(i + 1) % n], ring[i]);      // CCW from below
            }
        }
        for (int e = 0; e < kHexCorners; ++e) {
            const int32_t other = s_.keptNeighbour(k, e);
            const int e1 = (e + 1) % kHexCorners;
            const bool has = other >= 0;
            const Span none{0, 0};
            if (const auto foot = other < 0 ? footAcross(k, e) : std::nullopt) {
                addWalls(id[e], id[e1], cornerSpan(k, e), cornerSpan(k, e1), true, *foot, *foot);
                continue;
            }
            addWalls(id[e], id[e1], cornerSpan(k, e), cornerSpan(k, e1), has, has ? spanAt(size_t(other), id[e]) : none,
                     has ? spanAt(size_t(other), id[e1]) : none, t.crossing_top[kHexCorners * k + size_t(e)],
                     flat_ ? -1 : t.crossing_bottom[kHexCorners * k + size_t(e)]);
        }
    }

    void addCell(size_t k) {
        const int32_t c = s_.col[k], r = s_.row[k];
        int64_t id[kHexCorners];
        for (int e = 0; e < kHexCorners; ++e) id[e] = hexCornerId(g_, c, r, e);
        const int64_t top = s_.top[k], bottom = s_.bottom[k];
        if (isShaped(s_.shapes, k)) {
            addShapedCell(k);
            return;
        }
        if (region_[k] == kNotMerged) {
            uint32_t t[kHexCorners];
            for (int e = 0; e < kHexCorners; ++e) t[e] = vertexIndex(id[e], top);
            for (int e = 2; e < kHexCorners; ++e) tri(t[0], t[e - 1], t[e]);  // CCW from above
        }
        if (!flat_) {
            uint32_t b[kHexCorners];
            for (int e = 0; e < kHexCorners; ++e) b[e] = vertexIndex(id[e], bottom);
            for (int e = 2; e < kHexCorners; ++e) tri(b[0], b[e], b[e - 1]);  // CCW from below
        }
        for (int e = 0; e < kHexCorners; ++e) {
            int32_t nc, nr;
            hexNeighbour(c, r, e, nc, nr);
            const int32_t other = s_.keptAt(nc, nr);
            const bool has = other >= 0;
            const int64_t v = id[e], w = id[(e + 1) % kHexCorners];
            const Span none{0, 0};
            if (const auto foot = has ? std::nullopt : footAcross(k, e)) {
                addWalls(v, w, {bottom, top}, {bottom, top}, true, *foot, *foot);
                continue;
            }
            // A level cell beside a tilted one meets its corners where they are.
            addWalls(v, w, {bottom, top}, {bottom, top}, has, has ? spanAt(size_t(other), v) : none,
                     has ? spanAt(size_t(other), w) : none);
        }
    }

    void addFace(const PlanarFace& f) {
        const int64_t top = s_.faceTop(f), bottom = s_.faceBottom(f);
        for (const auto& t : f.triangles) {
            tri(vertexIndex(t[0], top), vertexIndex(t[1], top), vertexIndex(t[2], top));
            if (!flat_) tri(vertexIndex(t[0], bottom), vertexIndex(t[2], bottom), vertexIndex(t[1], bottom));
        }
        for (size_t r = 0; r < f.rings.size(); ++r) {
            const auto& ring = f.rings[r];
            for (size_t n = 0; n < ring.size(); ++n) {
                const Across& a = f.across[r][n];
                const int64_t v = ring[n], w = ring[(n + 1) % ring.size()];
                Span ov{0, 0}, ow{0, 0};
                if (a.kind == Across::Kind::Face) {
                    ov = ow = {s_.faceBottom(s_.faces.faces[size_t(a.index)]), s_.faceTop(s_.faces.faces[size_t(a.index)])};
                } else if (a.kind == Across::Kind::Cell) {
                    // A plain cell meets a face along a whole hex edge (lattice corners).
                    ov = spanAt(size_t(a.index), v);
                    ow = spanAt(size_t(a.index), w);
                }
                if (a.kind == Across::Kind::Outside && !foot_ring_edges_.empty())
                    if (const auto foot = foot_ring_edges_.find({v, w}); foot != foot_ring_edges_.end()) {
                        addWalls(v, w, {bottom, top}, {bottom, top}, true, foot->second, foot->second);
                        continue;
                    }
                addWalls(v, w, {bottom, top}, {bottom, top}, a.kind != Across::Kind::Outside, ov, ow);
            }
        }
    }

    // Wall over edge v -> w (counter-clockwise around the cell that owns it,
    // so the outward normal is (w - v) x up) from zv0 to zv1 at v and from
    // zw0 to zw1 at w (one side may be a single point: a crossing).
    void addWall(int64_t v, int64_t zv0, int64_t zv1, int64_t w, int64_t zw0, int64_t zw1) {
        // The vertices of v and of w, lowest first, as assignVertices placed
        // them: their z (mm) orders and finds them as their z units would
        // (zMm is one-to-one and increasing; see vertexIndex).
        const uint32_t lbase = first_index_[size_t(v)], rbase = first_index_[size_t(w)];
        const Vec3* zl = &mesh_.positions[lbase];
        const Vec3* zr = &mesh_.positions[rbase];
        const int nl = int(first_index_[size_t(v) + 1] - lbase), nr = int(first_index_[size_t(w) + 1] - rbase);
        const auto at = [&](const Vec3* p, int n, int64_t z) {
            const double z_mm = s_.zMm(z);
            return int(std::lower_bound(p, p + n, z_mm, [](const Vec3& q, double zz) { return q.z < zz; }) - p);
        };
        int li = at(zl, nl, zv0), ri = at(zr, nr, zw0);
        const int lend = at(zl, nl, zv1), rend = at(zr, nr, zw1);
        assert(li < nl && zl[li].z == s_.zMm(zv0) && ri < nr && zr[ri].z == s_.zMm(zw0));
        assert(lend < nl && zl[lend].z == s_.zMm(zv1) && rend < nr && zr[rend].z == s_.zMm(zw1));
        while (li < lend || ri < rend) {
            // Advance the side whose next point is lower (left on ties): the
            // zipper keeps triangles short and never uses three points of one side.
            const bool advance_left = ri == rend || (li < lend && zl[li + 1].z <= zr[ri + 1].z);
            if (advance_left) {
                tri(lbase + uint32_t(li), rbase + uint32_t(ri), lbase + uint32_t(li + 1));
                ++li;
            } else {
                tri(lbase + uint32_t(li), rbase + uint32_t(ri), rbase + uint32_t(ri + 1));
                ++ri;
            }
        }
    }

    // Rim edges, directed counter-clockwise around the kept region: hex edges
    // of plain cells with no kept neighbour, and face edges with nothing across.
    void collectRim() {
        for (size_t k = 0; k < s_.keptCount(); ++k) {
            if (drawnByFace(int32_t(k))) continue;
            for (int e = 0; e < kHexCorners; ++e) {
                int32_t nc, nr;
                hexNeighbour(s_.col[k], s_.row[k], e, nc, nr);
                if (s_.keptAt(nc, nr) >= 0) continue;
                addRimEdge(hexCornerId(g_, s_.col[k], s_.row[k], e), hexCornerId(g_, s_.col[k], s_.row[k], (e + 1) % kHexCorners));
            }
        }
        for (const PlanarFace& f : s_.faces.faces)
            for (size_t r = 0; r < f.rings.size(); ++r)
                for (size_t n = 0; n < f.rings[r].size(); ++n)
                    if (f.across[r][n].kind == Across::Kind::Outside)
                        addRimEdge(f.rings[r][n], f.rings[r][(n + 1) % f.rings[r].size()]);
    }

    void addRimEdge(int64_t v, int64_t w) {
        [[maybe_unused]] const bool fresh = next_on_rim_.emplace(v, w).second;
        assert(fresh && "the rim passes a vertex twice");
        rim_.insert(v);
        rim_.insert(w);
    }

    struct PlanarRegion {
        std::vector<std::pair<int64_t, int64_t>> edges;  // boundary, planar ids, closed loops
        std::vector<int64_t> inner;                      // interior vertices (planar ids)
        int64_t z = 0;                                   // height, z snap units
    };

    // The merged tops: per region, its boundary edges (counter-clockwise
    // around the region) and its kept interior vertices; regions in the
    // order of their roots (first cells), the same on every run.
    std::vector<PlanarRegion> mergedTops() const {
        std::vector<uint32_t> slot(s_.keptCount(), kNotMerged);
        std::vector<PlanarRegion> regions;
        for (size_t k = 0; k < s_.keptCount(); ++k) {
            const uint32_t root = region_[k];
            if (root == kNotMerged) continue;
            if (slot[root] == kNotMerged) {
                slot[root] = uint32_t(regions.size());
                regions.emplace_back();
                regions.back().z = s_.top[root];
            }
            PlanarRegion& r = regions[slot[root]];
            int64_t id[kHexCorners];
            for (int e = 0; e < kHexCorners; ++e) id[e] = hexCornerId(g_, s_.col[k], s_.row[k], e);
            for (int e = 0; e < kHexCorners; ++e) {
                const int32_t o = s_.keptNeighbour(k, e);
                if (o < 0 || region_[size_t(o)] != root) r.edges.push_back({id[e], id[(e + 1) % kHexCorners]});
                // Each interior vertex once: from the cell whose top or bottom corner it is.
                if (!dropped_top_[size_t(id[e])] && (e == 2 || e == 5) && regionAround(id[e], root) != kNotMerged)
                    r.inner.push_back(id[e]);
            }
        }
        return regions;
    }

    // Flat: the bottom at z 0, bounded by the rim, with the sparse points.
    PlanarRegion flatBottom() {
        PlanarRegion r;
        r.edges.assign(next_on_rim_.begin(), next_on_rim_.end());
        std::sort(r.edges.begin(), r.edges.end());  // the same triangulation on every run
        r.inner = std::move(bottom_points_);
        return r;
    }

    // The merged tops, then (flat) the bottom: each a triangulation of its
    // own, on the threads, the largest (the bottom) first; their triangles
    // are appended in that order whatever thread drew them. A bottom with
    // pin holes adds vertices, so it is drawn after the others, alone.
    void addPlanarRegions() {
        std::vector<PlanarRegion> regions = mergedTops();
        const size_t tops = regions.size();
        const bool bottom = flat_ && !next_on_rim_.empty();
        if (bottom) regions.push_back(flatBottom());
        const size_t together = bottom && !holes_.empty() ? tops : regions.size();
        std::vector<Triangles> drawn(together);
        std::atomic<size_t> next{0};
        runParts(together > 1 ? threads() : 1, [&](unsigned) {
            for (size_t n; (n = next.fetch_add(1)) < together;) {
                // The last (the bottom, when there is one) first.
                const size_t r = (n + together - 1) % together;
                t_sink = &drawn[r];
                addPlanarRegion(regions[r], regions[r].z, /*facing_up=*/r < tops);
                t_sink = nullptr;
            }
        });
        size_t total = mesh_.triangles.size();
        for (const Triangles& t : drawn) total += t.size();
        mesh_.triangles.reserve(total);
        for (Triangles& t : drawn) {
            mesh_.triangles.insert(mesh_.triangles.end(), t.begin(), t.end());
            Triangles().swap(t);
        }
        if (together < regions.size()) addPlanarRegion(regions.back(), 0, /*facing_up=*/false, /*with_holes=*/true);
    }

    // A horizontal polygon with holes at height z, bounded by r.edges, with
    // r.inner as extra vertices: a constrained Delaunay triangulation with
    // exact predicates, faces inside by parity.
    void addPlanarRegion(const PlanarRegion& r, int64_t z, bool facing_up, bool with_holes = false) {
        using K = CGAL::Exact_predicates_inexact_constructions_kernel;
        using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
        using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>;
        using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
        using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
        Cdt cdt;
        const auto point = [&](uint32_t index) {
            const Vec3& p = mesh_.positions[index];
            return K::Point_2(p.x, p.y);
        };
        std::unordered_map<int64_t, Cdt::Vertex_handle> handles;
        handles.reserve(r.edges.size());
        Cdt::Face_handle hint;
        const auto handleOf = [&](int64_t id) {
            auto [at, fresh] = handles.emplace(id, Cdt::Vertex_handle());
            if (fresh) {
                const uint32_t index = vertexIndex(id, z);
                at->second = cdt.insert(point(index), hint);
                at->second->info() = index;
                hint = at->second->face();
            }
            return at->second;
        };
        for (const auto& [v, w] : r.edges) cdt.insert_constraint(handleOf(v), handleOf(w));
        assert(cdt.number_of_vertices() == handles.size() && "two boundary vertices snapped to one point");
        std::vector<std::pair<K::Point_2, uint32_t>> inner;
        inner.reserve(r.inner.size());
        for (int64_t id : r.inner) {
            const uint32_t index = vertexIndex(id, z);
            inner.push_back({point(index), index});
        }
        cdt.insert(inner.begin(), inner.end());  // spatially sorted
        assert(cdt.number_of_vertices() == handles.size() + inner.size() && "an inner vertex on the boundary");
        // The cuts into the flat bottom (a half's pin holes), in it only: each
        // ring is one more loop of constraints, so the parity below leaves
        // the hole open. A hole lies inside one cell, so no inner (corner)
        // vertex falls in it.
        for (size_t h = 0; with_holes && h < holes_.size(); ++h) {
            const std::vector<uint32_t> ring = addHole(holes_[h]);
            std::vector<Cdt::Vertex_handle> hole;
            for (uint32_t index : ring) {
                hole.push_back(cdt.insert(point(index)));
                hole.back()->info() = index;
            }
            for (size_t n = 0; n < hole.size(); ++n) cdt.insert_constraint(hole[n], hole[(n + 1) % hole.size()]);
        }
        markInsideByParity(cdt);
        for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
            if (f->info() % 2 != 1) continue;
            // CGAL faces are counter-clockwise from above.
            if (facing_up) tri(f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info());
            else tri(f->vertex(0)->info(), f->vertex(2)->info(), f->vertex(1)->info());
        }
    }

    // The span of the foot across edge e of kept cell k (an attachment's
    // WallContact), which covers the wall there as a neighbour of that span
    // would; none if no foot.
    std::optional<Span> footAcross(size_t k, int e) const {
        if (foot_span_.empty()) return std::nullopt;
        const auto f = foot_span_.find(int64_t(k) * kHexCorners + e);
        return f == foot_span_.end() ? std::nullopt : std::optional<Span>(f->second);
    }
    void addFootHeights(int64_t id, const Span& span) {
        auto& h = foot_heights_[id];
        for (const int64_t z : {span.bottom, span.top})
            if (std::find(h.begin(), h.end(), z) == h.end()) h.push_back(z);
    }
    void addFoot(int32_t k, int e, const Span& span) {
        foot_span_[int64_t(k) * kHexCorners + e] = span;
        for (const int corner : {e, (e + 1) % kHexCorners})
            addFootHeights(hexCornerId(g_, s_.col[size_t(k)], s_.row[size_t(k)], corner), span);
    }

    // An attachment's body; where it stands on a lattice
    // corner of a contact it uses the pillars' vertex there, so the two share
    // the contact's edges.
    void addJoinedBody(const JoinedBody& joined) {
        const Mesh& body = joined.mesh;
        const std::vector<int64_t>& lattice_id = joined.lattice_id;
        std::vector<uint32_t> index(body.positions.size());
        for (size_t v = 0; v < index.size(); ++v) {
            if (lattice_id[v] >= 0) {
                index[v] = vertexIndex(lattice_id[v], snapUnits(body.positions[v].z, s_.z_snap_mm));
            } else {
                index[v] = uint32_t(mesh_.positions.size());
                mesh_.positions.push_back(body.positions[v]);
            }
        }
        for (const auto& t : body.triangles) tri(index[t[0]], index[t[1]], index[t[2]]);
    }

    // Pin hole h of a half: the ring on the bottom (returned, counter-clockwise
    // from above), the wall up to the hole's depth, and the cone to its tip.
    // Its vertices are its own: the hole lies inside one slab, away from every
    // wall (gen/model/features/halves.h), so nothing else meets them.
    std::vector<uint32_t> addHole(const BottomHole& hole) {
        const std::vector<PlanarPoint>& ring = hole.ring;
        const uint32_t first = uint32_t(mesh_.positions.size());
        const uint32_t n = uint32_t(ring.size());
        for (int64_t z : {int64_t(0), hole.depth_units})
            for (const PlanarPoint& p : ring) mesh_.positions.push_back(s_.point(p, z));
        const uint32_t apex = uint32_t(mesh_.positions.size());
        mesh_.positions.push_back(s_.point(hole.centre, hole.apex_units));
        std::vector<uint32_t> bottom;
        for (uint32_t k = 0; k < n; ++k) {
            const uint32_t a0 = first + k, b0 = first + (k + 1) % n, a1 = a0 + n, b1 = b0 + n;
            // The wall faces the hole's axis (out of the solid), the cone faces down.
            tri(a0, b1, b0);
            tri(a0, a1, b1);
            tri(a1, apex, b1);
            bottom.push_back(a0);
        }
        return bottom;
    }

    const Scene& s_;
    const HexGrid& g_;
    const bool flat_;
    const int64_t lattice_ids_;
    const std::vector<Attachment>& attachments_;  // what stands against the pillars (gen/model/attachments.h)
    const std::vector<BottomHole> holes_;        // holes into the flat bottom
    std::vector<uint32_t> first_index_;  // planar vertex id -> first mesh vertex index
    std::unordered_map<int64_t, std::vector<int32_t>> faces_at_;  // planar vertex id -> faces with it on a ring
    std::unordered_map<int64_t, int64_t> next_on_rim_;            // flat: rim edges
    std::unordered_set<int64_t> rim_;                             // flat: vertices on the rim
    std::vector<uint32_t> region_;          // kept cell -> root cell of its merged top, or kNotMerged
    std::vector<uint8_t> dropped_top_;      // lattice id -> 1: inside a merged top, no vertex
    std::vector<uint8_t> bottom_point_;     // flat, lattice id -> 1: an interior vertex of the bottom
    std::vector<int64_t> bottom_points_;    // flat: those ids
    std::unordered_map<int64_t, Span> foot_span_;                  // kept cell * 6 + edge -> the foot across it
    std::unordered_map<int64_t, std::vector<int64_t>> foot_heights_;  // lattice corner of a foot -> its heights
    std::map<std::pair<int64_t, int64_t>, Span> foot_ring_edges_;  // a face's ring edge (v, w) -> the foot across it
    Mesh mesh_;
};

}  // namespace

Mesh meshScene(const Scene& scene, const std::vector<Attachment>& attachments) {
    checkScene(scene);
    if (scene.keptCount() == 0) return {};
    return MeshBuilder(scene, attachments).build();
}

Mesh meshScene(const Scene& scene, Assembly assembly) {
    checkScene(scene);
    if (scene.keptCount() == 0) return {};
    const std::vector<Attachment> attachments = sceneAttachments(scene, assembly);
    return MeshBuilder(scene, attachments).build();
}

}  // namespace tsf
