// analyzeTopology: edge classification by sorting half-edges, vertex fans and
// components by union-find. See mesh_topology.h.
#include "verify/mesh_topology.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numeric>

#include "gen/util/union_find.h"

namespace tsf {
namespace {

// One side of a triangle: corner `side` to corner `side + 1`.
struct HalfEdge {
    uint64_t key;    // (min << 32) | max
    uint32_t tri;
    uint8_t side;    // 0..2
    bool forward;    // traversed from min to max
};

double signedTetra6(const Vec3& o, const Vec3& a, const Vec3& b, const Vec3& c) {
    const double ax = a.x - o.x, ay = a.y - o.y, az = a.z - o.z;
    const double bx = b.x - o.x, by = b.y - o.y, bz = b.z - o.z;
    const double cx = c.x - o.x, cy = c.y - o.y, cz = c.z - o.z;
    return ax * (by * cz - bz * cy) - ay * (bx * cz - bz * cx) + az * (bx * cy - by * cx);
}

bool finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

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

    // Half-edges grouped by undirected edge (lo, hi), then triangle: bucketed
    // by their lower vertex (a counting sort, linear), each bucket (a
    // vertex's few edges) sorted by insertion.
    std::vector<uint32_t> bucket(nv + 1, 0);
    for (size_t t = 0; t < nt; ++t) {
        if (!usable[t]) continue;
        const auto& tri = mesh.triangles[t];
        for (int s = 0; s < 3; ++s) ++bucket[std::min(tri[s], tri[(s + 1) % 3]) + 1];
    }
    std::partial_sum(bucket.begin(), bucket.end(), bucket.begin());
    std::vector<HalfEdge> half(bucket.back());
    {
        std::vector<uint32_t> fill(bucket.begin(), bucket.end() - 1);
        for (size_t t = 0; t < nt; ++t) {
            if (!usable[t]) continue;
            const auto& tri = mesh.triangles[t];
            for (uint8_t s = 0; s < 3; ++s) {
                const uint32_t a = tri[s], b = tri[(s + 1) % 3];
                const uint32_t lo = std::min(a, b), hi = std::max(a, b);
                half[fill[lo]++] = {(uint64_t(lo) << 32) | hi, uint32_t(t), s, a < b};
            }
        }
    }
    auto before = [](const HalfEdge& x, const HalfEdge& y) { return x.key != y.key ? x.key < y.key : x.tri < y.tri; };
    for (size_t v = 0; v < nv; ++v)
        for (uint32_t i = bucket[v] + 1; i < bucket[v + 1]; ++i)
            for (uint32_t j = i; j > bucket[v] && before(half[j], half[j - 1]); --j) std::swap(half[j], half[j - 1]);
    std::vector<uint32_t>().swap(bucket);

    UnionFind faces(nt);
    UnionFind corners(3 * nt);  // corner = 3 * triangle + index in triangle
    auto edgeUse = [&](size_t first, size_t last) {
        EdgeUse e;
        e.a = uint32_t(half[first].key >> 32);
        e.b = uint32_t(half[first].key & 0xffffffffu);
        for (size_t i = first; i < last; ++i) e.triangles.push_back(half[i].tri);
        return e;
    };
    for (size_t first = 0; first < half.size();) {
        size_t last = first + 1;
        while (last < half.size() && half[last].key == half[first].key) ++last;
        ++topo.edge_count;
        const size_t uses = last - first;
        for (size_t i = first + 1; i < last; ++i) faces.unite(half[first].tri, half[i].tri);
        if (uses == 1) {
            topo.border_edges.push_back(edgeUse(first, last));
        } else if (uses > 2) {
            topo.nonmanifold_edges.push_back(edgeUse(first, last));
        } else {
            const HalfEdge& x = half[first];
            const HalfEdge& y = half[first + 1];
            if (x.forward == y.forward) topo.misoriented_edges.push_back(edgeUse(first, last));
            // Join the two triangles' corners at each end of the edge: corners
            // joined this way form the fans around a vertex.
            const auto& tx = mesh.triangles[x.tri];
            const auto& ty = mesh.triangles[y.tri];
            for (uint8_t end = 0; end < 2; ++end) {
                const uint32_t v = tx[(x.side + end) % 3];
                const uint32_t cx = 3 * x.tri + uint32_t((x.side + end) % 3);
                uint32_t cy = 3 * y.tri;
                while (ty[cy - 3 * y.tri] != v) ++cy;
                corners.unite(cx, cy);
            }
        }
        first = last;
    }

    // Vertex fans: count distinct corner groups around each vertex.
    std::vector<uint32_t> corner_start(nv + 1, 0);
    for (size_t t = 0; t < nt; ++t)
        if (usable[t])
            for (uint32_t v : mesh.triangles[t]) ++corner_start[v + 1];
    std::partial_sum(corner_start.begin(), corner_start.end(), corner_start.begin());
    std::vector<uint32_t> corner_list(corner_start.back());
    {
        std::vector<uint32_t> fill(corner_start.begin(), corner_start.end() - 1);
        for (size_t t = 0; t < nt; ++t)
            if (usable[t])
                for (uint32_t i = 0; i < 3; ++i) corner_list[fill[mesh.triangles[t][i]]++] = 3 * uint32_t(t) + i;
    }
    std::vector<uint32_t> roots;
    for (size_t v = 0; v < nv; ++v) {
        roots.clear();
        for (uint32_t i = corner_start[v]; i < corner_start[v + 1]; ++i) roots.push_back(corners.find(corner_list[i]));
        std::sort(roots.begin(), roots.end());
        if (std::unique(roots.begin(), roots.end()) - roots.begin() > 1) topo.nonmanifold_vertices.push_back(uint32_t(v));
    }

    // Components of usable triangles.
    std::vector<int64_t> comp_of_root(nt, -1);
    for (size_t t = 0; t < nt; ++t) {
        if (!usable[t]) continue;
        const uint32_t r = faces.find(uint32_t(t));
        if (comp_of_root[r] < 0) {
            comp_of_root[r] = int64_t(topo.components.size());
            topo.components.emplace_back();
        }
        topo.components[size_t(comp_of_root[r])].triangles.push_back(uint32_t(t));
    }
    for (MeshComponent& c : topo.components) {
        const double inf = std::numeric_limits<double>::infinity();
        c.bounds = {{inf, inf, inf}, {-inf, -inf, -inf}};
        const Vec3 o = mesh.positions[mesh.triangles[c.triangles.front()][0]];
        double six_v = 0.0;
        for (uint32_t t : c.triangles) {
            const auto& tri = mesh.triangles[t];
            for (uint32_t v : tri) {
                const Vec3& p = mesh.positions[v];
                c.bounds.min = {std::fmin(c.bounds.min.x, p.x), std::fmin(c.bounds.min.y, p.y), std::fmin(c.bounds.min.z, p.z)};
                c.bounds.max = {std::fmax(c.bounds.max.x, p.x), std::fmax(c.bounds.max.y, p.y), std::fmax(c.bounds.max.z, p.z)};
            }
            six_v += signedTetra6(o, mesh.positions[tri[0]], mesh.positions[tri[1]], mesh.positions[tri[2]]);
        }
        c.signed_volume_mm3 = six_v / 6.0;
    }
    std::stable_sort(topo.components.begin(), topo.components.end(),
                     [](const MeshComponent& a, const MeshComponent& b) { return a.triangles.size() > b.triangles.size(); });

    // Exact duplicate positions (unmerged vertices): an open-addressing hash
    // set of the finite positions, sized once. NaN positions are left out of
    // the comparison (they are reported as non-finite); -0 equals +0.
    {
        size_t cap = 16;
        while (cap < 2 * nv) cap *= 2;
        std::vector<uint32_t> table(cap, UINT32_MAX);
        auto bits = [](double d) {
            if (d == 0) d = 0;  // one key for -0 and +0
            uint64_t u;
            std::memcpy(&u, &d, sizeof u);
            return u;
        };
        for (size_t v = 0; v < nv; ++v) {
            const Vec3& p = mesh.positions[v];
            if (!finite(p)) continue;
            uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull;
            h = (h ^ (h >> 29) ^ bits(p.y)) * 0xBF58476D1CE4E5B9ull;
            h = (h ^ (h >> 32) ^ bits(p.z)) * 0x94D049BB133111EBull;
            h ^= h >> 31;
            for (size_t slot = h & (cap - 1);; slot = (slot + 1) & (cap - 1)) {
                if (table[slot] == UINT32_MAX) {
                    table[slot] = uint32_t(v);
                    break;
                }
                if (mesh.positions[table[slot]] == p) {
                    ++topo.duplicate_position_vertices;
                    break;
                }
            }
        }
    }
    return topo;
}

}  // namespace tsf
