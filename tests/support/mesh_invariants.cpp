#include "tests/support/mesh_invariants.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <tuple>

#include "gen/util/union_find.h"

namespace tsf::test {
std::string Invariants::describe() const {
    std::ostringstream s;
    s << "V=" << vertices << " E=" << edges << " F=" << faces << " euler=" << euler << " components=" << components
      << " unpaired=" << unpaired_edges << " repeated=" << repeated_edges << " nonmanifold_vertices="
      << nonmanifold_vertices << " degenerate=" << degenerate_faces << " duplicate_positions=" << duplicate_positions
      << " unused=" << unused_vertices << " volume=" << volume;
    return s.str();
}

Invariants checkInvariants(const Mesh& mesh) {
    Invariants inv;
    inv.vertices = mesh.positions.size();
    inv.faces = mesh.triangles.size();
    inv.volume = signedVolume(mesh);

    // Directed edges, sorted: each must appear once, and its reverse once.
    std::vector<uint64_t> directed;
    directed.reserve(mesh.triangles.size() * 3);
    std::vector<uint8_t> used(mesh.positions.size(), 0);
    for (const auto& t : mesh.triangles) {
        for (int e = 0; e < 3; ++e) {
            directed.push_back(uint64_t(t[e]) << 32 | t[(e + 1) % 3]);
            used[t[e]] = 1;
        }
        const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z, vx = c.x - a.x, vy = c.y - a.y, vz = c.z - a.z;
        const double area = 0.5 * std::sqrt(std::pow(uy * vz - uz * vy, 2) + std::pow(uz * vx - ux * vz, 2) +
                                            std::pow(ux * vy - uy * vx, 2));
        if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2] || !(area > kMinArea)) ++inv.degenerate_faces;
    }
    inv.unused_vertices = size_t(std::count(used.begin(), used.end(), 0));
    std::sort(directed.begin(), directed.end());
    for (size_t n = 0; n < directed.size(); ++n) {
        if (n + 1 < directed.size() && directed[n + 1] == directed[n]) ++inv.repeated_edges;
        const uint64_t rev = (directed[n] & 0xffffffffu) << 32 | directed[n] >> 32;
        if (!std::binary_search(directed.begin(), directed.end(), rev)) ++inv.unpaired_edges;
    }
    size_t undirected = 0;
    for (uint64_t d : directed) undirected += (d >> 32) < (d & 0xffffffffu);
    inv.edges = undirected + inv.unpaired_edges / 2;  // unpaired edges counted once per direction
    inv.euler = long(inv.vertices) - long(inv.edges) + long(inv.faces);

    // Components of triangles joined by shared vertices.
    UnionFind uf(mesh.positions.size());
    for (const auto& t : mesh.triangles) { uf.unite(t[0], t[1]); uf.unite(t[1], t[2]); }
    std::vector<uint8_t> root(mesh.positions.size(), 0);
    for (size_t v = 0; v < mesh.positions.size(); ++v)
        if (used[v] && !root[uf.find(uint32_t(v))]) { root[uf.find(uint32_t(v))] = 1; ++inv.components; }

    // Vertex links: the opposite edges around a vertex must form one cycle.
    // Held as one array of (from, to) pairs grouped by vertex (counting
    // sort), so a mesh of millions of vertices needs no map per vertex.
    const size_t nv = mesh.positions.size();
    std::vector<uint32_t> start(nv + 1, 0);
    for (const auto& t : mesh.triangles)
        for (int e = 0; e < 3; ++e) ++start[t[e] + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::pair<uint32_t, uint32_t>> link(start[nv]);
    std::vector<uint32_t> fill(start.begin(), start.end() - 1);
    for (const auto& t : mesh.triangles)
        for (int e = 0; e < 3; ++e) link[fill[t[e]]++] = {t[(e + 1) % 3], t[(e + 2) % 3]};
    for (size_t v = 0; v < nv; ++v) {
        const auto first = link.begin() + start[v], last = link.begin() + start[v + 1];
        const size_t n = size_t(last - first);
        if (n == 0) continue;
        std::sort(first, last);
        bool ok = std::adjacent_find(first, last, [](auto a, auto b) { return a.first == b.first; }) == last;
        if (ok) {
            // Walk from the first edge; each step looks up the edge leaving
            // the current vertex.
            size_t steps = 0;
            uint32_t at = first->first;
            do {
                const auto it = std::lower_bound(first, last, std::pair<uint32_t, uint32_t>{at, 0});
                if (it == last || it->first != at) { ok = false; break; }
                at = it->second;
                ++steps;
            } while (at != first->first && steps <= n);
            ok &= steps == n;
        }
        inv.nonmanifold_vertices += !ok;
    }

    std::vector<std::tuple<double, double, double>> points;
    points.reserve(nv);
    for (const Vec3& p : mesh.positions) points.emplace_back(p.x, p.y, p.z);
    std::sort(points.begin(), points.end());
    for (size_t n = 1; n < points.size(); ++n) inv.duplicate_positions += points[n] == points[n - 1];
    return inv;
}

}  // namespace tsf::test
