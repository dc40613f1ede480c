// TriangleBvh: binned-SAH bounding-volume hierarchy with a bounded depth; the
// watertight ray/triangle test, Ericson's closest point on a triangle, and the
// tree's self-traversal for overlapping boxes. See triangle_bvh.h.
#include "verify/triangle_bvh.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <chrono>
#include <cmath>
#include <exception>
#include <memory>
#include <thread>
#include <type_traits>
#include <vector>

#include "verify/detail/ray_triangle.h"
#include "gen/util/workers.h"

namespace tsf {
namespace {

// Triangles per leaf: fewer means more boxes to test, more means more
// triangle tests; 4 is the usual balance.
constexpr uint32_t kLeafSize = 4;
// Boxes are padded by this many units in the last place of their largest
// coordinate, so rounding in the box tests cannot reject a ray, a point or a
// pair that the triangle tests would accept.
constexpr double kBoxPadUlps = 8.0;
// The surface-area heuristic chooses splits down to this depth; below it
// nodes are halved, so the depth is at most kSahDepth + log2(2^32 / kLeafSize).
constexpr int kSahDepth = 32;
constexpr int kMaxDepth = 64;
// Every traversal pops one node and pushes at most two, so it never holds
// more than one pending node per level plus one.
constexpr int kStackSize = kMaxDepth + 2;
constexpr int kSahBins = 16;
// Below this many triangles a second build thread costs more than it saves
// (starting one takes about 50 us; 10 000 triangles take about 5 ms to build).
constexpr size_t kParallelBuildMin = 10000;
constexpr uint32_t kNone = UINT32_MAX;
constexpr double kInf = std::numeric_limits<double>::infinity();

using detail::hitTriangle;
using detail::RaySetup;
using detail::V3;

struct Box {
    V3 lo{kInf, kInf, kInf};
    V3 hi{-kInf, -kInf, -kInf};
    void add(const V3& p) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    void add(const Box& b) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], b.lo[k]);
            hi[k] = std::max(hi[k], b.hi[k]);
        }
    }
    void pad() {
        for (int k = 0; k < 3; ++k) {
            const double scale = std::max({std::fabs(lo[k]), std::fabs(hi[k]), 1.0});
            const double p = kBoxPadUlps * scale * std::numeric_limits<double>::epsilon();
            lo[k] -= p;
            hi[k] += p;
        }
    }
};

// A padded box rounded outwards to floats: it holds the double box it was
// made from, and a float's step (2^29 doubles' steps) is a wider margin for
// the box tests' rounding than the padding itself. Half the bytes of a
// double box: a node is 32 bytes, two of them a cache line, which is what
// a traversal reads from memory. Coordinates beyond a float's range become
// infinite (a box that holds everything there: slower, never wrong).
struct FBox {
    std::array<float, 3> lo, hi;  // no initialisers: a node buffer is allocated, not written, until built

    static float down(double d) {
        if (d < -double(std::numeric_limits<float>::max())) return -std::numeric_limits<float>::infinity();
        if (d > double(std::numeric_limits<float>::max())) return std::numeric_limits<float>::max();
        float f = float(d);
        if (double(f) > d) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
        return f;
    }
    static float up(double d) {
        if (d > double(std::numeric_limits<float>::max())) return std::numeric_limits<float>::infinity();
        if (d < -double(std::numeric_limits<float>::max())) return -std::numeric_limits<float>::max();
        float f = float(d);
        if (double(f) < d) f = std::nextafter(f, std::numeric_limits<float>::infinity());
        return f;
    }
    static FBox around(const Box& b) {
        FBox f;
        for (int k = 0; k < 3; ++k) {
            f.lo[k] = down(b.lo[k]);
            f.hi[k] = up(b.hi[k]);
        }
        return f;
    }
    static FBox join(const FBox& a, const FBox& b) {
        FBox f;
        for (int k = 0; k < 3; ++k) {
            f.lo[k] = std::min(a.lo[k], b.lo[k]);
            f.hi[k] = std::max(a.hi[k], b.hi[k]);
        }
        return f;
    }
    // Squared distance from p to the box (0 inside).
    double distance2(const V3& p) const {
        double s = 0;
        for (int k = 0; k < 3; ++k) {
            const double d = std::max({double(lo[k]) - p[k], 0.0, p[k] - double(hi[k])});
            s += d * d;
        }
        return s;
    }
};

// Box measures for both kinds of box (doubles, floats).
template <class B>
double halfArea(const B& b) {
    const double dx = double(b.hi[0]) - b.lo[0], dy = double(b.hi[1]) - b.lo[1], dz = double(b.hi[2]) - b.lo[2];
    return dx * dy + dy * dz + dz * dx;
}

template <class B>
bool overlap(const B& a, const B& b) {
    return a.lo[0] <= b.hi[0] && b.lo[0] <= a.hi[0] && a.lo[1] <= b.hi[1] && b.lo[1] <= a.hi[1] &&
           a.lo[2] <= b.hi[2] && b.lo[2] <= a.hi[2];
}

struct Node {
    FBox box;
    uint32_t first;  // leaf: first triangle slot; inner: index of the left child (right = left + 1)
    uint32_t count;  // leaf: number of triangles; inner: 0
};
static_assert(sizeof(Node) == 32);
static_assert(std::is_trivially_default_constructible_v<Node>);

// What the build needs of a triangle, kept together so that the passes over
// a node's triangles read memory in order: its box on a grid of 65 536 steps
// a side over the whole mesh's box (only the choice of splits uses it; the
// tree's boxes come from the exact corners). 16 bytes, where a box of
// doubles took 56: the build streams through these once or twice a level,
// and on 13 M triangles they were 750 MB. The grid is 2.3 um a step on a
// 150 mm model; on a mesh spread over huge ranges many boxes share a step
// and the splits there are worse, never wrong.
struct Item {
    std::array<uint16_t, 3> lo, hi;
    uint32_t tri;  // index into the accepted triangles, before reordering
};
static_assert(sizeof(Item) == 16);

struct ItemGrid {
    V3 origin{0, 0, 0}, step{0, 0, 0}, inv_step{0, 0, 0};

    explicit ItemGrid(const Box& all) {
        for (int k = 0; k < 3; ++k) {
            const double extent = all.hi[k] - all.lo[k];
            origin[k] = all.lo[k];
            if (extent > 0 && std::isfinite(extent)) {
                step[k] = extent / 65535.0;
                inv_step[k] = 65535.0 / extent;
            }
        }
    }
    uint16_t cell(double x, int k, bool up) const {
        const double q = (x - origin[k]) * inv_step[k];
        const double r = up ? std::ceil(q) : std::floor(q);
        if (!(r > 0)) return 0;  // NaN too (an infinite extent times a zero step)
        return r >= 65535.0 ? uint16_t(65535) : uint16_t(r);
    }
    Item item(const Box& b, uint32_t tri) const {
        Item it;
        for (int k = 0; k < 3; ++k) {
            it.lo[k] = cell(b.lo[k], k, false);
            it.hi[k] = cell(b.hi[k], k, true);
        }
        it.tri = tri;
        return it;
    }
};

// Builds the subtree of items[begin, end) into nodes[next, ...), its root
// first; a subtree of m items takes at most 2m - 1 places.
struct SubtreeBuilder {
    std::vector<Item>& items;
    const ItemGrid& grid;
    Node* nodes;
    uint32_t next;  // the next free place
    int depth = 0;  // deepest level reached, counted from the whole tree's root

    // Split point of items[begin, end) (reordered), strictly inside. All in
    // the items' grid steps (integers; a centre is lo + hi, twice the
    // centre), converted to millimetres only for the areas and the axis.
    uint32_t split(uint32_t begin, uint32_t end, int level) {
        uint32_t cmin[3] = {UINT32_MAX, UINT32_MAX, UINT32_MAX}, cmax[3] = {0, 0, 0};  // bounds of the centres
        for (uint32_t i = begin; i < end; ++i)
            for (int k = 0; k < 3; ++k) {
                const uint32_t c = uint32_t(items[i].lo[k]) + items[i].hi[k];
                cmin[k] = std::min(cmin[k], c);
                cmax[k] = std::max(cmax[k], c);
            }
        int axis = 0;
        for (int k = 1; k < 3; ++k)
            if ((cmax[k] - cmin[k]) * grid.step[k] > (cmax[axis] - cmin[axis]) * grid.step[axis]) axis = k;
        auto centre2 = [axis](const Item& it) { return uint32_t(it.lo[axis]) + it.hi[axis]; };
        if (level < kSahDepth && cmax[axis] > cmin[axis]) {
            // Surface-area heuristic over the bins: the split minimising
            // area(left) * n_left + area(right) * n_right.
            struct GridBox {
                uint16_t lo[3] = {UINT16_MAX, UINT16_MAX, UINT16_MAX}, hi[3] = {0, 0, 0};
                void add(const uint16_t* l, const uint16_t* h) {
                    for (int k = 0; k < 3; ++k) {
                        lo[k] = std::min(lo[k], l[k]);
                        hi[k] = std::max(hi[k], h[k]);
                    }
                }
            };
            auto areaMm = [&](const GridBox& b) {
                const double dx = (double(b.hi[0]) - b.lo[0]) * grid.step[0], dy = (double(b.hi[1]) - b.lo[1]) * grid.step[1],
                             dz = (double(b.hi[2]) - b.lo[2]) * grid.step[2];
                return dx * dy + dy * dz + dz * dx;
            };
            const uint64_t lo = cmin[axis], span = uint64_t(cmax[axis]) - lo + 1;
            auto binOf = [&](const Item& it) { return int((uint64_t(centre2(it)) - lo) * kSahBins / span); };
            GridBox bins[kSahBins];
            uint32_t counts[kSahBins] = {};
            for (uint32_t i = begin; i < end; ++i) {
                const int b = binOf(items[i]);
                bins[b].add(items[i].lo.data(), items[i].hi.data());
                ++counts[b];
            }
            double right_area[kSahBins];
            uint32_t right_count[kSahBins];
            GridBox acc;
            uint32_t cnt = 0;
            for (int b = kSahBins - 1; b > 0; --b) {
                acc.add(bins[b].lo, bins[b].hi);
                cnt += counts[b];
                right_area[b] = cnt ? areaMm(acc) : 0.0;
                right_count[b] = cnt;
            }
            acc = GridBox{};
            cnt = 0;
            double best_cost = kInf;
            int best_bin = -1;
            for (int b = 0; b < kSahBins - 1; ++b) {
                acc.add(bins[b].lo, bins[b].hi);
                cnt += counts[b];
                if (cnt == 0 || right_count[b + 1] == 0) continue;
                const double cost = areaMm(acc) * cnt + right_area[b + 1] * right_count[b + 1];
                if (cost < best_cost) {
                    best_cost = cost;
                    best_bin = b;
                }
            }
            if (best_bin >= 0) {
                const auto mid = std::partition(items.begin() + begin, items.begin() + end,
                                                [&](const Item& it) { return binOf(it) <= best_bin; });
                const uint32_t m = uint32_t(mid - items.begin());
                if (m != begin && m != end) return m;
            }
        }
        // Deep, or no useful split: halve at the median.
        const uint32_t mid = begin + (end - begin) / 2;
        std::nth_element(items.begin() + begin, items.begin() + mid, items.begin() + end,
                         [&](const Item& a, const Item& b) { return centre2(a) < centre2(b); });
        return mid;
    }

    void build(uint32_t begin, uint32_t end, int level) {
        struct Job {
            uint32_t node, begin, end;
            int level;
        };
        const uint32_t root = next++;
        std::vector<Job> jobs{{root, begin, end, level}};
        while (!jobs.empty()) {
            const Job j = jobs.back();
            jobs.pop_back();
            depth = std::max(depth, j.level);
            if (j.end - j.begin <= kLeafSize) {
                nodes[j.node].first = j.begin;
                nodes[j.node].count = j.end - j.begin;
                continue;
            }
            const uint32_t mid = split(j.begin, j.end, j.level);
            const uint32_t left = next;
            next += 2;
            nodes[j.node].first = left;
            nodes[j.node].count = 0;
            jobs.push_back({left, j.begin, mid, j.level + 1});
            jobs.push_back({left + 1, mid, j.end, j.level + 1});
        }
    }
};

// A ray as the box test wants it: the reciprocal of each direction
// component (a multiplication per slab instead of a division), and which
// components are zero (those slabs are a comparison of the origin, exact).
// The reciprocal adds an ulp or two to the slab parameters, far inside the
// boxes' padding (kBoxPadUlps).
struct BoxRay {
    V3 o, inv;
    bool zero[3];
};

BoxRay boxRay(const V3& o, const V3& d) {
    BoxRay r{o, {0, 0, 0}, {false, false, false}};
    for (int k = 0; k < 3; ++k) {
        r.zero[k] = d[k] == 0.0;
        r.inv[k] = r.zero[k] ? 0.0 : 1.0 / d[k];
    }
    return r;
}

// Parameter interval of the ray inside the box starts at t_enter <= t_max, or false.
bool rayBox(const BoxRay& r, const FBox& b, double t_max, double& t_enter) {
    double t0 = 0.0, t1 = t_max;
    for (int k = 0; k < 3; ++k) {
        if (r.zero[k]) {
            if (r.o[k] < double(b.lo[k]) || r.o[k] > double(b.hi[k])) return false;
            continue;
        }
        double ta = (double(b.lo[k]) - r.o[k]) * r.inv[k];
        double tb = (double(b.hi[k]) - r.o[k]) * r.inv[k];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    t_enter = t0;
    return true;
}

V3 sub(const V3& a, const V3& b) { return {a[0] - b[0], a[1] - b[1], a[2] - b[2]}; }
V3 addScaled(const V3& a, double s, const V3& b) { return {a[0] + s * b[0], a[1] + s * b[1], a[2] + s * b[2]}; }
double dot(const V3& a, const V3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

V3 closestOnSegment(const V3& p, const V3& a, const V3& b) {
    const V3 ab = sub(b, a);
    const double len2 = dot(ab, ab);
    if (!(len2 > 0)) return a;
    const double t = std::clamp(dot(sub(p, a), ab) / len2, 0.0, 1.0);
    return addScaled(a, t, ab);
}

// Ericson, Real-Time Collision Detection, 5.1.5: the Voronoi region of p
// decides between a corner, an edge and the inside. A triangle without area
// (collinear corners) is the union of its edges.
V3 closestOnTriangle(const V3& p, const V3& a, const V3& b, const V3& c) {
    const V3 ab = sub(b, a), ac = sub(c, a), ap = sub(p, a);
    const double d1 = dot(ab, ap), d2 = dot(ac, ap);
    if (d1 <= 0 && d2 <= 0) return a;
    const V3 bp = sub(p, b);
    const double d3 = dot(ab, bp), d4 = dot(ac, bp);
    if (d3 >= 0 && d4 <= d3) return b;
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0 && d1 >= 0 && d3 <= 0) return addScaled(a, d1 / (d1 - d3), ab);
    const V3 cp = sub(p, c);
    const double d5 = dot(ab, cp), d6 = dot(ac, cp);
    if (d6 >= 0 && d5 <= d6) return c;
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0 && d2 >= 0 && d6 <= 0) return addScaled(a, d2 / (d2 - d6), ac);
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0)
        return addScaled(b, (d4 - d3) / ((d4 - d3) + (d5 - d6)), sub(c, b));
    const double sum = va + vb + vc;
    if (!(sum > 0)) {
        // No area: the nearest of the three edges.
        V3 best = closestOnSegment(p, a, b);
        double best2 = dot(sub(p, best), sub(p, best));
        for (const V3& q : {closestOnSegment(p, b, c), closestOnSegment(p, c, a)}) {
            const double d2q = dot(sub(p, q), sub(p, q));
            if (d2q < best2) {
                best2 = d2q;
                best = q;
            }
        }
        return best;
    }
    return addScaled(addScaled(a, vb / sum, ab), vc / sum, ac);
}

bool finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

struct TriangleBvh::Impl {
    // The mesh's positions and triangles, read in place (copies were 36
    // bytes a triangle, 500 MB on a 1000 x 1000 model).
    const Vec3* positions = nullptr;
    const std::array<uint32_t, 3>* triangles = nullptr;
    std::vector<uint32_t> mesh_index;              // per slot: the mesh triangle
    std::vector<uint32_t> slot_of;                 // per mesh triangle: its slot, or kNone
    // Built in place: the left half of the root from place 3, the right
    // half after the room the left one may take; places neither took are
    // never written (allocated without initialising, they take no memory).
    std::unique_ptr<Node[]> nodes;
    int depth = 0;
    double build_ms = 0;

    V3 corner(uint32_t slot, int i) const {
        const Vec3& p = positions[triangles[mesh_index[slot]][i]];
        return {p.x, p.y, p.z};
    }
    Box triangleBox(uint32_t slot) const {
        Box b;
        for (int i = 0; i < 3; ++i) b.add(corner(slot, i));
        return b;
    }

    void build() {
        const size_t n = mesh_index.size();
        if (n == 0) return;
        Box all;
        for (size_t i = 0; i < n; ++i) all.add(triangleBox(uint32_t(i)));
        const ItemGrid grid(all);
        std::vector<Item> items(n);
        for (size_t i = 0; i < n; ++i) items[i] = grid.item(triangleBox(uint32_t(i)), uint32_t(i));

        // Every range of places the subtrees were built in, children after
        // their parents in each.
        std::vector<std::pair<uint32_t, uint32_t>> ranges;
        uint32_t halves_root = 0;  // built in halves: the right half's root (place 2's original)
        const unsigned threads = workerCount(0);
        if (n >= kParallelBuildMin && threads >= 2) {
            // The root's split here, its two subtrees on two threads, each in
            // its own part of the one buffer: the left from place 3, the right
            // after the 2m - 1 places the left one may take. Their roots are
            // then copied to places 1 and 2 (the root's children are next to
            // each other) once the boxes are known; places 3 and the right's
            // first stay as unreachable copies.
            nodes = std::make_unique_for_overwrite<Node[]>(3 + 2 * n);
            SubtreeBuilder root{items, grid, nullptr, 0, 0};
            const uint32_t mid = root.split(0, uint32_t(n), 0);
            SubtreeBuilder left{items, grid, nodes.get(), 3, 0};
            SubtreeBuilder right{items, grid, nodes.get(), 3 + 2 * mid, 0};
            const uint32_t right_root = right.next;
            std::thread other([&] { right.build(mid, uint32_t(n), 1); });
            left.build(0, mid, 1);
            other.join();
            ranges = {{3, left.next}, {right_root, right.next}};
            nodes[0].first = 1;
            nodes[0].count = 0;
            depth = std::max(left.depth, right.depth);
            halves_root = right_root;
        } else {
            nodes = std::make_unique_for_overwrite<Node[]>(2 * n);
            SubtreeBuilder all{items, grid, nodes.get(), 0, 0};
            all.build(0, uint32_t(n), 0);
            depth = all.depth;
            ranges = {{0, all.next}};
        }
        assert(depth <= kMaxDepth);

        // Store the triangles in leaf order (the items freed first: they
        // are the build's largest array).
        std::vector<uint32_t> order(n);
        for (size_t i = 0; i < n; ++i) order[i] = items[i].tri;
        std::vector<Item>().swap(items);
        for (size_t i = 0; i < n; ++i) order[i] = mesh_index[order[i]];
        mesh_index.swap(order);
        for (size_t i = 0; i < n; ++i) slot_of[mesh_index[i]] = uint32_t(i);

        if (halves_root) {
            // The halves' boxes on two threads (each range is its own subtree).
            std::thread other([&] { computeBoxes(ranges[1]); });
            computeBoxes(ranges[0]);
            other.join();
        } else {
            computeBoxes(ranges[0]);
        }
        if (halves_root) {
            nodes[1] = nodes[3];
            nodes[2] = nodes[halves_root];
            nodes[0].box = FBox::join(nodes[1].box, nodes[2].box);
        }
    }

    // Boxes bottom-up over one subtree's range (children come after their parent): a
    // leaf's from its exact corners, padded and rounded out to floats; an
    // inner node's the union of its children's. Needs the triangles in
    // leaf order.
    void computeBoxes(std::pair<uint32_t, uint32_t> range) {
        for (uint32_t i = range.second; i-- > range.first;) {
            Node& nd = nodes[i];
            if (nd.count > 0) {
                Box b;
                for (uint32_t s = nd.first; s < nd.first + nd.count; ++s) b.add(triangleBox(s));
                b.pad();
                nd.box = FBox::around(b);
            } else {
                nd.box = FBox::join(nodes[nd.first].box, nodes[nd.first + 1].box);
            }
        }
    }

    // Every pair of triangles of the leaves a and b (a == b: within the leaf)
    // whose boxes overlap. A triangle's box is the min and max of its
    // coordinates, exact: it needs no padding.
    template <class Visit>
    void leafPairs(const Node& a, const Node& b, bool same, Visit& visit) const {
        Box ba[kLeafSize], bb[kLeafSize];
        for (uint32_t s = 0; s < a.count; ++s) ba[s] = triangleBox(a.first + s);
        if (!same)
            for (uint32_t t = 0; t < b.count; ++t) bb[t] = triangleBox(b.first + t);
        const Box* other = same ? ba : bb;
        for (uint32_t s = 0; s < a.count; ++s)
            for (uint32_t t = same ? s + 1 : 0; t < b.count; ++t)
                if (overlap(ba[s], other[t])) visit(mesh_index[a.first + s], mesh_index[b.first + t]);
    }

    // Pairs between the subtrees a and b (a != b), or within a (a == b).
    template <class Visit>
    void pairs(uint32_t a, uint32_t b, Visit& visit) const {
        const Node& na = nodes[a];
        const Node& nb = nodes[b];
        if (a == b) {
            if (na.count > 0) return leafPairs(na, na, true, visit);
            pairs(na.first, na.first, visit);
            pairs(na.first + 1, na.first + 1, visit);
            pairs(na.first, na.first + 1, visit);
            return;
        }
        if (!overlap(na.box, nb.box)) return;
        if (na.count > 0 && nb.count > 0) return leafPairs(na, nb, false, visit);
        // Descend the larger (or the only inner) node.
        if (nb.count > 0 || (na.count == 0 && halfArea(na.box) >= halfArea(nb.box))) {
            pairs(na.first, b, visit);
            pairs(na.first + 1, b, visit);
        } else {
            pairs(a, nb.first, visit);
            pairs(a, nb.first + 1, visit);
        }
    }
};

TriangleBvh::TriangleBvh(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
    const auto t0 = std::chrono::steady_clock::now();
    Impl& im = *impl_;
    const size_t nv = mesh.positions.size();
    im.positions = mesh.positions.data();
    im.triangles = mesh.triangles.data();
    im.slot_of.assign(mesh.triangles.size(), kNone);
    im.mesh_index.reserve(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        if (tri[0] >= nv || tri[1] >= nv || tri[2] >= nv) continue;
        if (!finite(mesh.positions[tri[0]]) || !finite(mesh.positions[tri[1]]) || !finite(mesh.positions[tri[2]])) continue;
        im.mesh_index.push_back(uint32_t(t));
    }
    im.build();
    im.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

TriangleBvh::~TriangleBvh() = default;

size_t TriangleBvh::triangleCount() const { return impl_->mesh_index.size(); }
int TriangleBvh::depth() const { return impl_->depth; }
double TriangleBvh::buildMs() const { return impl_->build_ms; }

unsigned TriangleBvh::workerCount(unsigned workers) { return detail::workerCount(workers); }

std::optional<RayHit> TriangleBvh::firstHit(const Vec3& origin, const Vec3& direction, int64_t skip,
                                            double max_distance_mm) const {
    const Impl& im = *impl_;
    if (!im.nodes || !finite(origin) || !finite(direction)) return std::nullopt;
    if (direction.x == 0 && direction.y == 0 && direction.z == 0) return std::nullopt;
    const V3 o{origin.x, origin.y, origin.z}, d{direction.x, direction.y, direction.z};
    const RaySetup r = detail::raySetup(o, d);
    const uint32_t skip_slot = (skip >= 0 && size_t(skip) < im.slot_of.size()) ? im.slot_of[size_t(skip)] : kNone;

    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    // Ray parameter limit; a hit exactly at the limit still counts.
    double best_t = max_distance_mm / len;
    uint32_t best_slot = kNone;
    V3 best_point{};
    // Pending nodes with the parameter where the ray enters them: a node
    // entered beyond the best hit found since it was pushed is dropped
    // without testing its box again.
    struct Pending {
        uint32_t node;
        double t_enter;
    };
    Pending stack[kStackSize];
    int top = 0;
    const BoxRay br = boxRay(o, d);
    double t_root = 0;
    if (!rayBox(br, im.nodes[0].box, best_t, t_root)) return std::nullopt;
    stack[top++] = {0, t_root};
    while (top > 0) {
        const Pending p = stack[--top];
        if (p.t_enter > best_t) continue;
        const Node& n = im.nodes[p.node];
        if (n.count > 0) {
            for (uint32_t s = n.first; s < n.first + n.count; ++s) {
                if (s == skip_slot) continue;
                V3 q;
                const double t = hitTriangle(r, im.corner(s, 0), im.corner(s, 1), im.corner(s, 2), best_t, q);
                // Ties go to the lower mesh index, whatever the tree's order.
                if (t >= 0 && (t < best_t || (t == best_t && (best_slot == kNone || im.mesh_index[s] < im.mesh_index[best_slot])))) {
                    best_t = t;
                    best_slot = s;
                    best_point = q;
                }
            }
            continue;
        }
        double tl = 0, tr = 0;
        const bool hl = rayBox(br, im.nodes[n.first].box, best_t, tl);
        const bool hr = rayBox(br, im.nodes[n.first + 1].box, best_t, tr);
        assert(top + 2 <= kStackSize);
        if (hl && hr) {
            // Push the farther child first so the nearer one is visited first.
            if (tl <= tr) {
                stack[top++] = {n.first + 1, tr};
                stack[top++] = {n.first, tl};
            } else {
                stack[top++] = {n.first, tl};
                stack[top++] = {n.first + 1, tr};
            }
        } else if (hl) {
            stack[top++] = {n.first, tl};
        } else if (hr) {
            stack[top++] = {n.first + 1, tr};
        }
    }
    if (best_slot == kNone) return std::nullopt;
    RayHit h;
    h.point_mm = {best_point[0], best_point[1], best_point[2]};
    h.distance_mm = best_t * len;
    h.triangle = im.mesh_index[best_slot];
    return h;
}

ClosestPoint TriangleBvh::closest(const Vec3& query, int64_t hint, double enough_mm) const {
    const Impl& im = *impl_;
    ClosestPoint out;
    out.distance_mm = kInf;
    if (!im.nodes || !finite(query)) return out;
    const V3 p{query.x, query.y, query.z};
    double best2 = kInf;
    const double enough2 = enough_mm > 0 ? enough_mm * enough_mm : -1.0;
    uint32_t best_slot = kNone;
    V3 best_point{};
    auto visit = [&](uint32_t s) {
        const V3 q = closestOnTriangle(p, im.corner(s, 0), im.corner(s, 1), im.corner(s, 2));
        const double d2 = dot(sub(p, q), sub(p, q));
        if (d2 < best2) {
            best2 = d2;
            best_slot = s;
            best_point = q;
        }
    };
    if (hint >= 0 && size_t(hint) < im.slot_of.size() && im.slot_of[size_t(hint)] != kNone)
        visit(im.slot_of[size_t(hint)]);

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
        assert(top + 2 <= kStackSize);
        if (std::max(dl, dr) < best2) stack[top++] = far;
        if (std::min(dl, dr) < best2) stack[top++] = near;
    }
    out.distance_mm = std::sqrt(best2);
    out.point_mm = {best_point[0], best_point[1], best_point[2]};
    out.triangle = im.mesh_index[best_slot];
    return out;
}

void TriangleBvh::forEachOverlappingPair(const std::function<void(unsigned, uint32_t, uint32_t)>& visit,
                                         unsigned workers) const {
    const Impl& im = *impl_;
    if (!im.nodes) return;
    workers = workerCount(workers);
    // Cut the traversal into tasks: (a, b) node pairs whose pairs are
    // disjoint and together cover all. Splitting the within-subtree tasks
    // of the top levels gives a few hundred tasks for the workers to share.
    struct Task {
        uint32_t a, b;
    };
    std::vector<Task> tasks{{0, 0}};
    for (int level = 0; level < 8 && workers > 1; ++level) {
        std::vector<Task> next;
        for (const Task& t : tasks) {
            const Node& n = im.nodes[t.a];
            if (t.a != t.b || n.count > 0) {
                next.push_back(t);
                continue;
            }
            next.push_back({n.first, n.first});
            next.push_back({n.first + 1, n.first + 1});
            next.push_back({n.first, n.first + 1});
        }
        tasks.swap(next);
    }
    std::atomic<size_t> next_task{0};
    detail::runOnWorkers(workers, [&](unsigned worker, const std::atomic<bool>& stop) {
        auto call = [&](uint32_t a, uint32_t b) { visit(worker, a, b); };
        for (size_t i; !stop.load() && (i = next_task.fetch_add(1)) < tasks.size();) im.pairs(tasks[i].a, tasks[i].b, call);
    });
}

}  // namespace tsf
