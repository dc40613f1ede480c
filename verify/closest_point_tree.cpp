// ClosestPointTree: an AABB tree split by the surface-area heuristic, and
// Ericson's closest point on a triangle. See closest_point_tree.h.
#include "verify/closest_point_tree.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <vector>

namespace tsf {
namespace {

// Triangles per leaf: fewer means more boxes to test, more means more
// triangle tests; 4 is the usual balance.
constexpr size_t kLeafSize = 4;
// The search keeps one pending sibling per level on a fixed stack of
// kStackSize entries. The surface-area heuristic can peel off a few
// triangles at a time, so below kSahDepth levels nodes are halved at the
// median instead: depth <= kSahDepth + log2(triangles), far below the stack
// size for any mesh that fits in memory.
constexpr int kStackSize = 96;
constexpr uint32_t kSahDepth = 40;
constexpr double kInf = std::numeric_limits<double>::infinity();

struct P3 {
    double x, y, z;
};
P3 operator-(const P3& a, const P3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
P3 operator+(const P3& a, const P3& b) { return {a.x + b.x, a.y + b.y, a.z + b.z}; }
P3 operator*(double s, const P3& a) { return {s * a.x, s * a.y, s * a.z}; }
double dot(const P3& a, const P3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

struct Box {
    P3 lo{kInf, kInf, kInf}, hi{-kInf, -kInf, -kInf};
    void add(const P3& p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
    }
    void add(const Box& b) {
        add(b.lo);
        add(b.hi);
    }
    // Squared distance from p to the box (0 inside).
    double distance2(const P3& p) const {
        const double dx = std::max({lo.x - p.x, 0.0, p.x - hi.x});
        const double dy = std::max({lo.y - p.y, 0.0, p.y - hi.y});
        const double dz = std::max({lo.z - p.z, 0.0, p.z - hi.z});
        return dx * dx + dy * dy + dz * dz;
    }
};

struct Node {
    Box box;
    uint32_t first = 0;  // leaf: first triangle slot; inner: index of the left child (right = left + 1)
    uint32_t count = 0;  // leaf: number of triangles; inner: 0
};

struct Tri {
    P3 a, b, c;
    uint32_t mesh_index;
};

P3 closestOnSegment(const P3& p, const P3& a, const P3& b) {
    const P3 ab = b - a;
    const double len2 = dot(ab, ab);
    if (!(len2 > 0)) return a;
    const double t = std::clamp(dot(p - a, ab) / len2, 0.0, 1.0);
    return a + t * ab;
}

// Ericson, Real-Time Collision Detection, 5.1.5: the Voronoi region of p
// decides between a corner, an edge and the inside. A triangle without area
// (collinear corners) is the union of its edges.
P3 closestOnTriangle(const P3& p, const Tri& t) {
    const P3 &a = t.a, &b = t.b, &c = t.c;
    const P3 ab = b - a, ac = c - a, ap = p - a;
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const P3 bp = p - b;
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return a + (d1 / (d1 - d3)) * ab;
    const P3 cp = p - c;
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return a + (d2 / (d2 - d6)) * ac;
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return b + ((d4 - d3) / ((d4 - d3) + (d5 - d6))) * (c - b);
    const double sum = va + vb + vc;
    if (!(sum > 0)) {
        // No area: the nearest of the three edges.
        P3 best = closestOnSegment(p, a, b);
        double best2 = dot(p - best, p - best);
        for (const P3& q : {closestOnSegment(p, b, c), closestOnSegment(p, c, a)}) {
            const double d2q = dot(p - q, p - q);
            if (d2q < best2) {
                best2 = d2q;
                best = q;
            }
        }
        return best;
    }
    return a + (vb / sum) * ab + (vc / sum) * ac;
}

bool finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

double halfArea(const Box& b) {
    const P3 d = b.hi - b.lo;
    return d.x * d.y + d.y * d.z + d.z * d.x;
}

double axisOf(const P3& p, int axis) { return axis == 0 ? p.x : (axis == 1 ? p.y : p.z); }

// What the build needs of a triangle, kept together so that the passes over
// a node's triangles read memory in order.
struct Item {
    Box box;
    P3 centroid;
    uint32_t slot;  // index into Impl::tris
};

// Surface-area heuristic over kSahBins bins of the centroids:
// the split minimising area(left) * n_left + area(right) * n_right. The long
// triangles of a flat bottom triangulated without interior vertices (they
// span the model) end up in subtrees of their own instead of inflating the
// boxes of everything near them, as a median split lets them. Reorders
// items[begin, end) and returns the split point (begin: no useful split).
constexpr int kSahBins = 16;
uint32_t splitSah(std::vector<Item>& items, uint32_t begin, uint32_t end, const Box& cb) {
    Box bins[3][kSahBins];
    uint32_t counts[3][kSahBins] = {};
    double lo[3], scale[3];
    bool usable_axis[3];
    // Only along the longest extent of the centroids: a third of the work of
    // trying all three axes, for trees nearly as good.
    const P3 e = cb.hi - cb.lo;
    const int longest = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
    for (int axis = 0; axis < 3; ++axis) {
        lo[axis] = axisOf(cb.lo, axis);
        const double extent = axisOf(cb.hi, axis) - lo[axis];
        usable_axis[axis] = axis == longest && extent > 0;
        scale[axis] = usable_axis[axis] ? kSahBins / extent : 0.0;
    }
    auto binOf = [&](const P3& c, int axis) { return std::min(kSahBins - 1, int((axisOf(c, axis) - lo[axis]) * scale[axis])); };
    for (uint32_t i = begin; i < end; ++i)
        for (int axis = 0; axis < 3; ++axis) {
            if (!usable_axis[axis]) continue;
            const int b = binOf(items[i].centroid, axis);
            bins[axis][b].add(items[i].box);
            ++counts[axis][b];
        }
    double best_cost = kInf;
    int best_axis = -1, best_bin = 0;
    for (int axis = 0; axis < 3; ++axis) {
        if (!usable_axis[axis]) continue;
        double right_area[kSahBins];
        uint32_t right_count[kSahBins];
        Box acc;
        uint32_t cnt = 0;
        for (int b = kSahBins - 1; b > 0; --b) {
            if (counts[axis][b]) acc.add(bins[axis][b]);
            cnt += counts[axis][b];
            right_area[b] = cnt ? halfArea(acc) : 0.0;
            right_count[b] = cnt;
        }
        acc = Box{};
        cnt = 0;
        for (int b = 0; b < kSahBins - 1; ++b) {
            if (counts[axis][b]) acc.add(bins[axis][b]);
            cnt += counts[axis][b];
            if (cnt == 0 || right_count[b + 1] == 0) continue;
            const double cost = halfArea(acc) * cnt + right_area[b + 1] * right_count[b + 1];
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best_bin = b;
            }
        }
    }
    if (best_axis < 0) return begin;
    const auto mid = std::partition(items.begin() + begin, items.begin() + end,
                                    [&](const Item& it) { return binOf(it.centroid, best_axis) <= best_bin; });
    return uint32_t(mid - items.begin());
}

}  // namespace

struct ClosestPointTree::Impl {
    std::vector<Tri> tris;
    std::vector<Node> nodes;
    std::vector<int64_t> slot_of;  // mesh triangle -> slot in tris, -1 if absent

    void build() {
        if (tris.empty()) return;
        std::vector<Item> items(tris.size());
        for (size_t i = 0; i < tris.size(); ++i) {
            items[i].box.add(tris[i].a);
            items[i].box.add(tris[i].b);
            items[i].box.add(tris[i].c);
            items[i].centroid = (1.0 / 3.0) * (tris[i].a + tris[i].b + tris[i].c);
            items[i].slot = uint32_t(i);
        }
        nodes.reserve(2 * tris.size() / kLeafSize + 2);
        nodes.push_back({});
        struct Job {
            uint32_t node, begin, end, depth;
        };
        std::vector<Job> jobs{{0, 0, uint32_t(tris.size()), 0}};
        while (!jobs.empty()) {
            const Job j = jobs.back();
            jobs.pop_back();
            Box b, cb;
            for (uint32_t i = j.begin; i < j.end; ++i) {
                b.add(items[i].box);
                cb.add(items[i].centroid);
            }
            nodes[j.node].box = b;
            if (j.end - j.begin <= kLeafSize) {
                nodes[j.node].first = j.begin;
                nodes[j.node].count = j.end - j.begin;
                continue;
            }
            uint32_t mid = j.begin;
            if (j.depth < kSahDepth) mid = splitSah(items, j.begin, j.end, cb);
            if (mid == j.begin || mid == j.end) {  // deep, or no useful split: halve at the median
                const P3 e = cb.hi - cb.lo;
                const int axis = e.x >= e.y && e.x >= e.z ? 0 : (e.y >= e.z ? 1 : 2);
                mid = j.begin + (j.end - j.begin) / 2;
                std::nth_element(items.begin() + j.begin, items.begin() + mid, items.begin() + j.end,
                                 [&](const Item& s, const Item& t) {
                                     return axisOf(s.centroid, axis) < axisOf(t.centroid, axis);
                                 });
            }
            const uint32_t left = uint32_t(nodes.size());
            nodes.push_back({});
            nodes.push_back({});
            nodes[j.node].first = left;
            nodes[j.node].count = 0;
            jobs.push_back({left, j.begin, mid, j.depth + 1});
            jobs.push_back({left + 1, mid, j.end, j.depth + 1});
        }
        // Leaves refer to positions in `items`; store the triangles in that order.
        std::vector<Tri> sorted(tris.size());
        for (size_t i = 0; i < items.size(); ++i) sorted[i] = tris[items[i].slot];
        tris.swap(sorted);
        for (size_t i = 0; i < tris.size(); ++i) slot_of[tris[i].mesh_index] = int64_t(i);
    }
};

ClosestPointTree::ClosestPointTree(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
    Impl& im = *impl_;
    const size_t nv = mesh.positions.size();
    im.slot_of.assign(mesh.triangles.size(), -1);
    im.tris.reserve(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        if (tri[0] >= nv || tri[1] >= nv || tri[2] >= nv) continue;
        const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
        if (!finite(a) || !finite(b) || !finite(c)) continue;
        im.tris.push_back({{a.x, a.y, a.z}, {b.x, b.y, b.z}, {c.x, c.y, c.z}, uint32_t(t)});
    }
    im.build();
}

ClosestPointTree::~ClosestPointTree() = default;

size_t ClosestPointTree::triangleCount() const { return impl_->tris.size(); }

ClosestPoint ClosestPointTree::closest(const Vec3& query, int64_t hint, double enough_mm) const {
    const Impl& im = *impl_;
    ClosestPoint out;
    out.distance_mm = kInf;
    if (im.nodes.empty() || !finite(query)) return out;
    const P3 p{query.x, query.y, query.z};
    double best2 = kInf;
    const double enough2 = enough_mm > 0 ? enough_mm * enough_mm : -1.0;
    int64_t best_slot = -1;
    P3 best_point{};
    auto visit = [&](uint32_t s) {
        const P3 q = closestOnTriangle(p, im.tris[s]);
        const double d2 = dot(p - q, p - q);
        if (d2 < best2) {
            best2 = d2;
            best_slot = int64_t(s);
            best_point = q;
        }
    };
    if (hint >= 0 && size_t(hint) < im.slot_of.size() && im.slot_of[size_t(hint)] >= 0)
        visit(uint32_t(im.slot_of[size_t(hint)]));

    // Depth-first, nearer child first (see kStackSize).
    uint32_t stack[kStackSize];
    int top = 0;
    stack[top++] = 0;
    while (top > 0 && !(best2 <= enough2)) {
        const Node& n = im.nodes[stack[--top]];
        if (n.box.distance2(p) >= best2) continue;
        if (n.count > 0) {
            for (uint32_t s = n.first; s < n.first + n.count; ++s) visit(s);
            continue;
        }
        const double dl = im.nodes[n.first].box.distance2(p), dr = im.nodes[n.first + 1].box.distance2(p);
        const uint32_t near = dl <= dr ? n.first : n.first + 1, far = dl <= dr ? n.first + 1 : n.first;
        if (std::max(dl, dr) < best2) stack[top++] = far;
        if (std::min(dl, dr) < best2) stack[top++] = near;
    }
    out.distance_mm = std::sqrt(best2);
    out.point_mm = {best_point.x, best_point.y, best_point.z};
    out.triangle = im.tris[size_t(best_slot)].mesh_index;
    return out;
}

}  // namespace tsf
