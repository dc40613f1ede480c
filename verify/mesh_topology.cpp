// analyzeTopology: edge classification by sorting half-edges, vertex fans and
// components by union-find. See mesh_topology.h.
#include "verify/mesh_topology.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <numeric>

#include "verify/detail/concurrent_union_find.h"
#include "gen/util/workers.h"

namespace tsf {
namespace {

double signedTetra6(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& c) {
    const double ax = a.x - o.x, ay = a.y - o.y, az = a.z - o.z;
    const double bx = b.x - o.x, by = b.y - o.y, bz = b.z - o.z;
    const double cx = c.x - o.x, cy = c.y - o.y, cz = c.z - o.z;
    return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}

bool finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// Below this many triangle corners the edges and fans are found on one
// thread: starting the others costs more than they save.
constexpr size_t kMinCornersForThreads = 60000;

}  // namespace

Vec3 edgeMidpoint(const Mesh& mesh, const EdgeUse& e) {
    const Vec3& a = mesh.positions[e.a];
    const Vec3& b = mesh.positions[e.b];
    return {0.5 * (a.x + b.x), 0.5 * (a.y + b.y), 0.5 * (a.z + b.z)};
}

Vec3 triangleCentroid(const Mesh& mesh, uint32_t t) {
    const auto& tri = mesh.triangles[t];
    const size_t n = mesh.positions.size();
    Vec3 c;
    int used = 0;
    for (uint32_t v : tri) {
        if (v >= n) continue;
        c.x += mesh.positions[v].x;
        c.y += mesh.positions[v].y;
        c.z += mesh.positions[v].z;
        ++used;
    }
    if (used) c = {c.x / used, c.y / used, c.z / used};
    return c;
}

VertexCorners cornersByVertex(const Mesh& mesh, const std::vector<uint8_t>* usable) {
    // The same counting sort with the triangles in one run of consecutive
    // triangles per worker: each counts its corners per vertex, each vertex's
    // slots are handed out run by run, and each fills its own slots, so a
    // vertex's corners stand by ascending triangle, as from one thread.
    // (The range overload stays on one thread: the self-intersection test
    // calls it from its own workers.)
    const size_t nt = mesh.triangles.size(), nv = mesh.positions.size();
    const unsigned workers = nt < detail::kMinItemsForThreads ? 1u : detail::workerCount(0);
    if (workers == 1) return cornersByVertex(mesh, usable, 0, uint32_t(nv));
    auto used = [&](size_t t) { return !usable || (*usable)[t]; };
    // at[w][v]: run w's corners at vertex v, then where run w's next one goes.
    std::vector<std::vector<uint32_t>> at(workers);
    detail::runOnRanges(workers, nt, [&](unsigned w, size_t begin, size_t end) {
        at[w].assign(nv, 0);
        for (size_t t = begin; t < end; ++t)
            if (used(t))
                for (uint32_t v : mesh.triangles[t]) ++at[w][v];
    });
    VertexCorners c;
    c.start = detail::slotsByRun(at, nv);
    c.list.resize(c.start[nv]);
    detail::runOnRanges(workers, nt, [&](unsigned w, size_t begin, size_t end) {
        std::vector<uint32_t>& next = at[w];
        for (size_t t = begin; t < end; ++t)
            if (used(t))
                for (uint32_t i = 0; i < 3; ++i) c.list[next[mesh.triangles[t][i]]++] = 3 * uint32_t(t) + i;
    });
    return c;
}

VertexCorners cornersByVertex(const Mesh& mesh, const std::vector<uint8_t>* usable, uint32_t first, uint32_t last) {
    const size_t nt = mesh.triangles.size();
    auto used = [&](size_t t) { return !usable || (*usable)[t]; };
    VertexCorners c;
    c.start.assign(size_t(last - first) + 1, 0);
    for (size_t t = 0; t < nt; ++t)
        if (used(t))
            for (uint32_t v : mesh.triangles[t])
                if (v >= first && v < last) ++c.start[v - first + 1];
    std::partial_sum(c.start.begin(), c.start.end(), c.start.begin());
    c.list.resize(c.start.back());
    std::vector<uint32_t> fill(c.start.begin(), c.start.end() - 1);
    for (size_t t = 0; t < nt; ++t)
        if (used(t))
            for (uint32_t i = 0; i < 3; ++i) {
                const uint32_t v = mesh.triangles[t][i];
                if (v >= first && v < last) c.list[fill[v - first]++] = 3 * uint32_t(t) + i;
            }
    return c;
}

MeshTopology analyzeTopology(const Mesh& mesh) {
    MeshTopology topo;
    const size_t nv = mesh.positions.size();
    const size_t nt = mesh.triangles.size();
    topo.vertex_count = nv;
    topo.triangle_count = nt;

    for (size_t v = 0; v < nv; ++v)
        if (!finite(mesh.positions[v])) topo.nonfinite_vertices.push_back(uint32_t(v));

    // Usable triangles: indices in range and pairwise distinct.
    std::vector<uint8_t> usable(nt, 0);
    std::vector<uint8_t> referenced(nv, 0);
    for (size_t t = 0; t < nt; ++t) {
        const auto& tri = mesh.triangles[t];
        if (tri[0] >= nv || tri[1] >= nv || tri[2] >= nv) {
            topo.out_of_range_triangles.push_back(uint32_t(t));
            continue;
        }
        for (uint32_t v : tri) referenced[v] = 1;
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
            topo.index_degenerate_triangles.push_back(uint32_t(t));
            continue;
        }
        usable[t] = 1;
    }
    topo.unreferenced_vertices = size_t(std::count(referenced.begin(), referenced.end(), uint8_t(0)));

    // Every question about edges and fans is answered around one vertex at a
    // time, from the triangles at that vertex (cornersByVertex): the edges
    // (v, w) are the other corners w of those triangles, each edge's uses are
    // the triangles naming w, and the fans are those triangles joined across
    // two-use edges. All of it reads a few dozen consecutive entries, where a
    // half-edge table and a union-find over all corners read memory at
    // random (and took 64 bytes a triangle more).
    const VertexCorners at = cornersByVertex(mesh, &usable);

    // The vertices in one run of consecutive vertices per worker, of about
    // as many corners each; each run's findings are kept apart and joined in
    // vertex order, so the lists come out as from one thread. The triangles'
    // components are joined in one union-find the workers share.
    detail::ConcurrentUnionFind faces(nt);
    struct Findings {
        size_t edge_count = 0;
        std::vector<EdgeUse> border, nonmanifold, misoriented;
        std::vector<uint32_t> nonmanifold_vertices;
    };
    const unsigned workers = at.list.size() < kMinCornersForThreads ? 1u : detail::workerCount(0);
    std::vector<Findings> found(workers);
    std::vector<size_t> run_start(workers + 1, nv);
    for (unsigned w = 0; w < workers; ++w)
        run_start[w] = size_t(std::lower_bound(at.start.begin(), at.start.end() - 1,
                                               uint32_t(at.list.size() * w / workers)) -
                              at.start.begin());
    run_start[0] = 0;
    detail::runOnWorkers(workers, [&](unsigned worker, const std::atomic<bool>&) {
        Findings& out = found[worker];
        struct Spoke {
            uint32_t w;       // the other end of the edge
            uint32_t tri;     // a triangle using the edge v-w
            uint32_t local;   // that triangle's place among v's triangles
            bool outgoing;    // the triangle runs v -> w
        };
        std::vector<Spoke> spokes;
        std::vector<uint32_t> fan;  // union-find over v's triangles
        auto fanRoot = [&](uint32_t x) {
            while (fan[x] != x) x = fan[x] = fan[fan[x]];
            return x;
        };
        for (size_t v = run_start[worker]; v < run_start[worker + 1]; ++v) {
            const uint32_t first = at.start[v], count = at.start[v + 1] - first;
            if (count == 0) continue;
            spokes.clear();
            for (uint32_t k = 0; k < count; ++k) {
                const uint32_t c = at.list[first + k], t = c / 3, i = c % 3;
                const auto& tri = mesh.triangles[t];
                spokes.push_back({tri[(i + 1) % 3], t, k, true});
                spokes.push_back({tri[(i + 2) % 3], t, k, false});
            }
            std::sort(spokes.begin(), spokes.end(),
                      [](const Spoke& a, const Spoke& b) { return a.w != b.w ? a.w < b.w : a.tri < b.tri; });
            fan.resize(count);
            std::iota(fan.begin(), fan.end(), 0u);
            size_t fans = count;
            auto edgeUse = [&](size_t lo, size_t hi) {
                EdgeUse e;
                e.a = uint32_t(v);
                e.b = spokes[lo].w;
                for (size_t i = lo; i < hi; ++i) e.triangles.push_back(spokes[i].tri);
                return e;
            };
            for (size_t lo = 0; lo < spokes.size();) {
                size_t hi = lo + 1;
                while (hi < spokes.size() && spokes[hi].w == spokes[lo].w) ++hi;
                const size_t uses = hi - lo;
                if (uses == 2) {  // a two-triangle edge joins the fan at v
                    const uint32_t x = fanRoot(spokes[lo].local), y = fanRoot(spokes[lo + 1].local);
                    if (x != y) {
                        fan[x] = y;
                        --fans;
                    }
                }
                if (spokes[lo].w > v) {  // each edge once, from its lower end
                    ++out.edge_count;
                    for (size_t i = lo + 1; i < hi; ++i) faces.unite(spokes[lo].tri, spokes[i].tri);
                    if (uses == 1) out.border.push_back(edgeUse(lo, hi));
                    else if (uses > 2) out.nonmanifold.push_back(edgeUse(lo, hi));
                    else if (spokes[lo].outgoing == spokes[lo + 1].outgoing) out.misoriented.push_back(edgeUse(lo, hi));
                }
                lo = hi;
            }
            if (fans > 1) out.nonmanifold_vertices.push_back(uint32_t(v));
        }
    });
    for (Findings& f : found) {
        topo.edge_count += f.edge_count;
        auto join = [](auto& to, auto& from) { to.insert(to.end(), std::make_move_iterator(from.begin()), std::make_move_iterator(from.end())); };
        join(topo.border_edges, f.border);
        join(topo.nonmanifold_edges, f.nonmanifold);
        join(topo.misoriented_edges, f.misoriented);
        join(topo.nonmanifold_vertices, f.nonmanifold_vertices);
    }

    // Components: each triangle's root (its set's smallest member) found on
    // the workers, then the sets numbered in triangle order on one thread. A
    // root comes before the rest of its set, so its entry already holds the
    // set's number when the others look it up.
    std::vector<uint32_t> set_of(nt);
    detail::runOnWorkers(workers, [&](unsigned w, const std::atomic<bool>&) {
        for (size_t t = nt * w / workers; t < nt * (w + 1) / workers; ++t) set_of[t] = faces.find(uint32_t(t));
    });
    std::vector<size_t> sizes;  // triangles per component, so each list is sized once
    for (size_t t = 0; t < nt; ++t) {
        if (!usable[t]) continue;
        const uint32_t root = set_of[t];
        if (root == t) {
            set_of[t] = uint32_t(sizes.size());
            sizes.push_back(0);
        } else {
            set_of[t] = set_of[root];
        }
        ++sizes[set_of[t]];
    }
    topo.components.resize(sizes.size());
    for (size_t c = 0; c < sizes.size(); ++c) topo.components[c].triangles.reserve(sizes[c]);
    for (size_t t = 0; t < nt; ++t)
        if (usable[t]) topo.components[set_of[t]].triangles.push_back(uint32_t(t));
    set_of = {};
    // Each component's volume (summed in triangle order, the same bits on
    // any machine) on one thread while its box is taken on another.
    const double inf = std::numeric_limits<double>::infinity();
    detail::runOnWorkers(std::min(workers, 2u), [&](unsigned w, const std::atomic<bool>&) {
        for (MeshComponent& c : topo.components) {
            if (w == 1 || workers == 1) {
                c.bounds = {{inf, inf, inf}, {-inf, -inf, -inf}};
                for (uint32_t t : c.triangles)
                    for (uint32_t v : mesh.triangles[t]) extendBounds(c.bounds, mesh.positions[v]);
            }
            if (w == 0) {
                const Vec3 o = mesh.positions[mesh.triangles[c.triangles.front()][0]];
                double six_v = 0.0;
                for (uint32_t t : c.triangles) {
                    const auto& tri = mesh.triangles[t];
                    six_v += signedTetra6(o, mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]);
                }
                c.signed_volume_mm3 = six_v / 6.0;
            }
        }
    });
    std::stable_sort(topo.components.begin(), topo.components.end(),
                     [](const MeshComponent& a, const MeshComponent& b) { return a.triangles.size() > b.triangles.size(); });

    // Exact duplicate positions (unmerged vertices): an open-addressing hash
    // set of the finite positions, sized once, filled on the workers (a slot
    // is taken by compare-and-swap). Which of two equal positions is kept
    // depends on the threads' order; how many are turned away (the count)
    // does not. NaN positions are left out of the comparison (they are
    // reported as non-finite); -0 equals +0.
    {
        size_t cap = 16;
        while (cap < 2 * nv) cap *= 2;
        constexpr uint32_t kEmpty = UINT32_MAX;
        std::unique_ptr<std::atomic<uint32_t>[]> table(new std::atomic<uint32_t>[cap]);
        std::vector<size_t> duplicates(workers, 0);
        detail::runOnWorkers(workers, [&](unsigned w, const std::atomic<bool>&) {
            for (size_t i = cap * w / workers; i < cap * (w + 1) / workers; ++i)
                table[i].store(kEmpty, std::memory_order_relaxed);
        });
        auto bits = [](double d) {
            if (d == 0) d = 0;  // one key for -0 and +0
            uint64_t u;
            std::memcpy(&u, &d, sizeof u);
            return u;
        };
        auto slotOf = [&](const Vec3& p) {
            uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull;
            h = (h ^ (h >> 29) ^ bits(p.y)) * 0xBF58476D1CE4E5B9ull;
            h = (h ^ (h >> 32) ^ bits(p.z)) * 0x94D049BB133111EBull;
            h ^= h >> 31;
            return size_t(h & (cap - 1));
        };
        // A slot is a cache miss (the table is far larger than the cache):
        // each vertex's slot is asked for kAhead vertices before it is used.
        constexpr size_t kAhead = 16;
        detail::runOnWorkers(workers, [&](unsigned w, const std::atomic<bool>&) {
            const size_t end = nv * (w + 1) / workers;
            for (size_t v = nv * w / workers; v < end; ++v) {
                if (v + kAhead < end && finite(mesh.positions[v + kAhead]))
                    __builtin_prefetch(&table[slotOf(mesh.positions[v + kAhead])]);
                const Vec3& p = mesh.positions[v];
                if (!finite(p)) continue;
                for (size_t slot = slotOf(p);; slot = (slot + 1) & (cap - 1)) {
                    uint32_t held = kEmpty;
                    if (table[slot].compare_exchange_strong(held, uint32_t(v), std::memory_order_relaxed)) break;
                    if (mesh.positions[held] == p) {
                        ++duplicates[w];
                        break;
                    }
                }
            }
        });
        for (size_t d : duplicates) topo.duplicate_position_vertices += d;
    }
    return topo;
}

}  // namespace tsf
