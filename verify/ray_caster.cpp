// RayCaster: a median-split AABB tree and the watertight ray/triangle test.
// See ray_caster.h.
#include "verify/ray_caster.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <limits>
#include <vector>

namespace tsf {
namespace {

// Triangles per leaf: fewer means more boxes to test, more means more
// triangle tests; 4 is the usual balance.
constexpr size_t kLeafSize = 4;
// Boxes are padded by this many units in the last place of their largest
// coordinate, so rounding in the box test cannot reject a ray that the
// triangle test would accept.
constexpr double kBoxPadUlps = 8.0;

using V3 = std::array<double, 3>;

struct Box {
    V3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
          std::numeric_limits<double>::infinity()};
    V3 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(),
          -std::numeric_limits<double>::infinity()};
    void add(const V3& p) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    void add(const Box& b) {
        add(b.lo);
        add(b.hi);
    }
};

struct Node {
    Box box;
    uint32_t first = 0;  // leaf: first triangle slot; inner: index of the left child (right = left + 1)
    uint32_t count = 0;  // leaf: number of triangles; inner: 0
};

struct Tri {
    V3 a, b, c;
    uint32_t mesh_index;
};

bool finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

double halfArea(const Box& b) {
    const double dx = b.hi[0] - b.lo[0], dy = b.hi[1] - b.lo[1], dz = b.hi[2] - b.lo[2];
    return dx * dy + dy * dz + dz * dx;
}

// Surface-area heuristic over kSahBins bins of the centroids on each axis:
// the split minimising area(left) * n_left + area(right) * n_right. Large
// triangles (a flat bottom triangulated without interior vertices spans the
// whole model) end up in small subtrees of their own instead of inflating the
// boxes of everything near them. Reorders order[begin, end) and returns the
// split point; begin or end means "do not split".
constexpr int kSahBins = 16;
uint32_t splitSah(std::vector<uint32_t>& order, uint32_t begin, uint32_t end, const std::vector<V3>& centroid,
                  const std::vector<Box>& box, const Box& cb) {
    const uint32_t n = end - begin;
    double best_cost = std::numeric_limits<double>::infinity();
    int best_axis = -1, best_bin = 0;
    for (int axis = 0; axis < 3; ++axis) {
        const double extent = cb.hi[axis] - cb.lo[axis];
        if (!(extent > 0)) continue;
        Box bins[kSahBins];
        uint32_t counts[kSahBins] = {};
        const double scale = kSahBins / extent;
        for (uint32_t i = begin; i < end; ++i) {
            const int b = std::min(kSahBins - 1, int((centroid[order[i]][axis] - cb.lo[axis]) * scale));
            bins[b].add(box[order[i]]);
            ++counts[b];
        }
        double right_area[kSahBins];
        uint32_t right_count[kSahBins];
        Box acc;
        uint32_t cnt = 0;
        for (int b = kSahBins - 1; b > 0; --b) {
            if (counts[b]) acc.add(bins[b]);
            cnt += counts[b];
            right_area[b] = cnt ? halfArea(acc) : 0.0;
            right_count[b] = cnt;
        }
        acc = Box{};
        cnt = 0;
        for (int b = 0; b < kSahBins - 1; ++b) {
            if (counts[b]) acc.add(bins[b]);
            cnt += counts[b];
            if (cnt == 0 || right_count[b + 1] == 0) continue;
            const double cost = halfArea(acc) * cnt + right_area[b + 1] * right_count[b + 1];
            if (cost < best_cost) {
                best_cost = cost;
                best_axis = axis;
                best_bin = b;
            }
        }
    }
    if (best_axis < 0) {
        // All centroids coincide: split in the middle so leaves stay small.
        return n > kLeafSize ? begin + n / 2 : begin;
    }
    const double scale = kSahBins / (cb.hi[best_axis] - cb.lo[best_axis]);
    const auto mid = std::partition(order.begin() + begin, order.begin() + end, [&](uint32_t t) {
        return std::min(kSahBins - 1, int((centroid[t][best_axis] - cb.lo[best_axis]) * scale)) <= best_bin;
    });
    return uint32_t(mid - order.begin());
}

}  // namespace

struct RayCaster::Impl {
    std::vector<Tri> tris;
    std::vector<Node> nodes;
    std::vector<int64_t> slot_of;  // mesh triangle -> slot in tris, -1 if absent
    double build_ms = 0;

    void build() {
        if (tris.empty()) return;
        std::vector<V3> centroid(tris.size());
        std::vector<Box> box(tris.size());
        for (size_t i = 0; i < tris.size(); ++i) {
            box[i].add(tris[i].a);
            box[i].add(tris[i].b);
            box[i].add(tris[i].c);
            for (int k = 0; k < 3; ++k) centroid[i][k] = (tris[i].a[k] + tris[i].b[k] + tris[i].c[k]) / 3.0;
        }
        std::vector<uint32_t> order(tris.size());
        for (uint32_t i = 0; i < order.size(); ++i) order[i] = i;
        nodes.reserve(2 * tris.size() / kLeafSize + 2);
        nodes.push_back({});
        struct Job {
            uint32_t node, begin, end;
        };
        std::vector<Job> jobs{{0, 0, uint32_t(tris.size())}};
        while (!jobs.empty()) {
            const Job j = jobs.back();
            jobs.pop_back();
            Box b, cb;
            for (uint32_t i = j.begin; i < j.end; ++i) {
                b.add(box[order[i]]);
                cb.add(centroid[order[i]]);
            }
            nodes[j.node].box = b;
            if (j.end - j.begin <= kLeafSize) {
                nodes[j.node].first = j.begin;
                nodes[j.node].count = j.end - j.begin;
                continue;
            }
            const uint32_t mid = splitSah(order, j.begin, j.end, centroid, box, cb);
            if (mid == j.begin || mid == j.end) {  // nothing to gain: keep as a (large) leaf
                nodes[j.node].first = j.begin;
                nodes[j.node].count = j.end - j.begin;
                continue;
            }
            const uint32_t left = uint32_t(nodes.size());
            nodes.push_back({});
            nodes.push_back({});
            nodes[j.node].first = left;
            nodes[j.node].count = 0;
            jobs.push_back({left, j.begin, mid});
            jobs.push_back({left + 1, mid, j.end});
        }
        // Leaves refer to slots in `order`; store the triangles in that order.
        std::vector<Tri> sorted(tris.size());
        for (size_t i = 0; i < order.size(); ++i) sorted[i] = tris[order[i]];
        tris.swap(sorted);
        for (size_t i = 0; i < tris.size(); ++i) slot_of[tris[i].mesh_index] = int64_t(i);
        // Pad every box (see kBoxPadUlps).
        for (Node& n : nodes) {
            for (int k = 0; k < 3; ++k) {
                const double scale = std::max({std::fabs(n.box.lo[k]), std::fabs(n.box.hi[k]), 1.0});
                const double pad = kBoxPadUlps * scale * std::numeric_limits<double>::epsilon();
                n.box.lo[k] -= pad;
                n.box.hi[k] += pad;
            }
        }
    }
};

namespace {

// Parameter interval [t0, t1] of the ray inside the box, or false.
bool rayBox(const V3& o, const V3& d, const Box& b, double t_max, double& t_enter) {
    double t0 = 0.0, t1 = t_max;
    for (int k = 0; k < 3; ++k) {
        if (d[k] == 0.0) {
            if (o[k] < b.lo[k] || o[k] > b.hi[k]) return false;
            continue;
        }
        double ta = (b.lo[k] - o[k]) / d[k];
        double tb = (b.hi[k] - o[k]) / d[k];
        if (ta > tb) std::swap(ta, tb);
        t0 = std::max(t0, ta);
        t1 = std::min(t1, tb);
        if (t0 > t1) return false;
    }
    t_enter = t0;
    return true;
}

// Watertight ray/triangle test. kx, ky, kz and the shear (sx, sy, sz) are per ray.
struct RaySetup {
    V3 o, d;
    int kx, ky, kz;
    double sx, sy, sz;
};

RaySetup setup(const V3& o, const V3& d) {
    RaySetup r{o, d, 0, 0, 0, 0, 0, 0};
    int kz = 0;
    for (int k = 1; k < 3; ++k)
        if (std::fabs(d[k]) > std::fabs(d[kz])) kz = k;
    int kx = (kz + 1) % 3, ky = (kx + 1) % 3;
    if (d[kz] < 0) std::swap(kx, ky);  // keep the winding of the triangles
    r.kx = kx;
    r.ky = ky;
    r.kz = kz;
    r.sx = d[kx] / d[kz];
    r.sy = d[ky] / d[kz];
    r.sz = 1.0 / d[kz];
    return r;
}

// Ray parameter of the hit, or a negative number for no hit; on a hit, the
// hit point from the triangle's own corners (barycentric), kept inside the
// triangle's bounding box so that a hit on a face parallel to an axis plane
// has exactly that face's coordinate (a top at z = 12.4 reads 12.4, not
// 12.4 plus the rounding of origin + t * direction).
double hitTriangle(const RaySetup& r, const Tri& t, double t_max, V3& point) {
    const V3 A{t.a[0] - r.o[0], t.a[1] - r.o[1], t.a[2] - r.o[2]};
    const V3 B{t.b[0] - r.o[0], t.b[1] - r.o[1], t.b[2] - r.o[2]};
    const V3 C{t.c[0] - r.o[0], t.c[1] - r.o[1], t.c[2] - r.o[2]};
    const double Ax = A[r.kx] - r.sx * A[r.kz], Ay = A[r.ky] - r.sy * A[r.kz];
    const double Bx = B[r.kx] - r.sx * B[r.kz], By = B[r.ky] - r.sy * B[r.kz];
    const double Cx = C[r.kx] - r.sx * C[r.kz], Cy = C[r.ky] - r.sy * C[r.kz];
    const double U = Cx * By - Cy * Bx;
    const double V = Ax * Cy - Ay * Cx;
    const double W = Bx * Ay - By * Ax;
    if ((U < 0 || V < 0 || W < 0) && (U > 0 || V > 0 || W > 0)) return -1.0;
    const double det = U + V + W;
    if (det == 0.0) return -1.0;  // the ray lies in the triangle's plane, or the triangle has no area
    const double T = U * (r.sz * A[r.kz]) + V * (r.sz * B[r.kz]) + W * (r.sz * C[r.kz]);
    const double tt = T / det;
    if (!(tt >= 0.0) || tt > t_max) return -1.0;
    for (int k = 0; k < 3; ++k) {
        const double p = (U * t.a[k] + V * t.b[k] + W * t.c[k]) / det;
        const double lo = std::min({t.a[k], t.b[k], t.c[k]}), hi = std::max({t.a[k], t.b[k], t.c[k]});
        point[k] = std::clamp(p, lo, hi);
    }
    return tt;
}

}  // namespace

RayCaster::RayCaster(const Mesh& mesh) : impl_(std::make_unique<Impl>()) {
    const auto t0 = std::chrono::steady_clock::now();
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
    im.build_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

RayCaster::~RayCaster() = default;

size_t RayCaster::triangleCount() const { return impl_->tris.size(); }
double RayCaster::buildMs() const { return impl_->build_ms; }

std::optional<RayHit> RayCaster::firstHit(const Vec3& origin, const Vec3& direction, int64_t skip,
                                          double max_distance_mm) const {
    const Impl& im = *impl_;
    if (im.nodes.empty() || !finite(origin) || !finite(direction)) return std::nullopt;
    if (direction.x == 0 && direction.y == 0 && direction.z == 0) return std::nullopt;
    const V3 o{origin.x, origin.y, origin.z}, d{direction.x, direction.y, direction.z};
    const RaySetup r = setup(o, d);
    const int64_t skip_slot = (skip >= 0 && size_t(skip) < im.slot_of.size()) ? im.slot_of[size_t(skip)] : -1;

    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    // Ray parameter limit; a hit exactly at the limit still counts.
    double best_t = max_distance_mm / len;
    int64_t best_slot = -1;
    V3 best_point{};
    // Depth-first, nearer child first; a 64-entry stack holds any tree of a
    // median split (depth ~ log2(triangles / kLeafSize)).
    uint32_t stack[64];
    int top = 0;
    double t_enter = 0;
    if (!rayBox(o, d, im.nodes[0].box, best_t, t_enter)) return std::nullopt;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = im.nodes[stack[--top]];
        if (!rayBox(o, d, n.box, best_t, t_enter)) continue;
        if (n.count > 0) {
            for (uint32_t s = n.first; s < n.first + n.count; ++s) {
                if (int64_t(s) == skip_slot) continue;
                V3 p;
                const double t = hitTriangle(r, im.tris[s], best_t, p);
                if (t >= 0 && (t < best_t || (t == best_t && (best_slot < 0 || s < uint64_t(best_slot))))) {
                    best_t = t;
                    best_slot = int64_t(s);
                    best_point = p;
                }
            }
            continue;
        }
        double tl = 0, tr = 0;
        const bool hl = rayBox(o, d, im.nodes[n.first].box, best_t, tl);
        const bool hr = rayBox(o, d, im.nodes[n.first + 1].box, best_t, tr);
        if (hl && hr) {
            // Push the farther child first so the nearer one is visited first.
            if (tl <= tr) {
                stack[top++] = n.first + 1;
                stack[top++] = n.first;
            } else {
                stack[top++] = n.first;
                stack[top++] = n.first + 1;
            }
        } else if (hl) {
            stack[top++] = n.first;
        } else if (hr) {
            stack[top++] = n.first + 1;
        }
    }
    if (best_slot < 0) return std::nullopt;
    RayHit h;
    h.point_mm = {best_point[0], best_point[1], best_point[2]};
    h.distance_mm = best_t * len;
    h.triangle = im.tris[size_t(best_slot)].mesh_index;
    return h;
}

}  // namespace tsf
