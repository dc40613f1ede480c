// compareSurfaceChains: plane-by-plane boundary sums in exact integer
// arithmetic. See surface_chains.h.
#include "verify/surface_chains.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numeric>
#include <unordered_map>

#include <boost/multiprecision/cpp_int.hpp>

namespace tsf {
namespace {

namespace bmp = boost::multiprecision;
using Int128 = __int128;  // a GCC/Clang built-in: exact products of two 61-bit integers

// Largest magnitude, in bits, of a coordinate on the integer grid for which
// each arithmetic type below is exact:
//  - 61: coordinates int64; edge vectors < 2^62; normals and Pluecker moments
//    (products of two of those, summed twice) < 2^125 in Int128; plane offsets
//    (normal . point, three terms) < 2^188 in int256.
//  - 125: coordinates Int128; edge vectors < 2^126; normals and moments < 2^253
//    in int256; plane offsets < 2^380 in int512.
constexpr int kFastGridBits = 61;
constexpr int kWideGridBits = 125;

struct FastTypes {
    using Coord = int64_t;
    using Wide = Int128;
    using Wider = bmp::int256_t;
};
struct WideTypes {
    using Coord = Int128;
    using Wide = bmp::int256_t;
    using Wider = bmp::int512_t;
};

// --- integer helpers --------------------------------------------------------

Int128 absValue(Int128 v) { return v < 0 ? -v : v; }

int64_t gcdOf(int64_t a, int64_t b) { return std::gcd(a, b); }
bmp::int256_t gcdOf(const bmp::int256_t& a, const bmp::int256_t& b) { return bmp::gcd(a, b); }
// Binary GCD of |a| and |b| (the standard library's std::gcd does not take
// __int128 in strict C++ mode).
Int128 gcdOf(Int128 a, Int128 b) {
    using U = unsigned __int128;
    U x = U(absValue(a)), y = U(absValue(b));
    if (x == 0) return Int128(y);
    if (y == 0) return Int128(x);
    auto ctz = [](U v) {
        const uint64_t lo = uint64_t(v);
        return lo ? std::countr_zero(lo) : 64 + std::countr_zero(uint64_t(v >> 64));
    };
    const int shift = ctz(x | y);
    x >>= ctz(x);
    do {
        y >>= ctz(y);
        if (x > y) std::swap(x, y);
        y -= x;
    } while (y != 0);
    return Int128(x << shift);
}

template <class T>
int signOf(const T& v) {
    return v > 0 ? 1 : (v < 0 ? -1 : 0);
}

// Divides a, b, c by their GCD and makes the first non-zero one positive.
// All zero stays all zero.
template <class T>
void makePrimitive(T& a, T& b, T& c) {
    const T g = gcdOf(gcdOf(a, b), c);
    if (g == 0) return;
    a /= g;
    b /= g;
    c /= g;
    const int s = a != 0 ? signOf(a) : (b != 0 ? signOf(b) : signOf(c));
    if (s < 0) {
        a = -a;
        b = -b;
        c = -c;
    }
}

// Hash of exact integers, word by word: each word goes through the
// splitmix64 finaliser (std::hash of an integer is the identity in libstdc++,
// and small, regular grid coordinates then pile up in few buckets).
inline uint64_t scramble(uint64_t x) {
    x += 0x9e3779b97f4a7c15ULL;
    x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
    x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
    return x ^ (x >> 31);
}
inline void mix(size_t& h, uint64_t w) { h = scramble(h ^ w); }
inline void mixValue(size_t& h, int64_t v) { mix(h, uint64_t(v)); }
inline void mixValue(size_t& h, Int128 v) {
    mix(h, uint64_t(v));
    mix(h, uint64_t(v >> 64));
}
template <class Backend, bmp::expression_template_option E>
void mixValue(size_t& h, const bmp::number<Backend, E>& v) {
    mix(h, uint64_t(v.sign()));
    const auto& be = v.backend();
    for (unsigned i = 0; i < be.size(); ++i) mix(h, uint64_t(be.limbs()[i]));
}

// --- the grid ---------------------------------------------------------------

bool usable(const Mesh& m, const std::array<uint32_t, 3>& t) {
    const size_t n = m.positions.size();
    return t[0] < n && t[1] < n && t[2] < n && t[0] != t[1] && t[1] != t[2] && t[0] != t[2];
}

// The exponent E such that every coordinate is an integer times 2^E, and the
// number of bits of the largest |coordinate| / 2^E. False if a coordinate is
// not finite.
bool gridOf(const Mesh& a, const Mesh& b, int& exponent, int& bits) {
    int low = INT32_MAX, high = INT32_MIN;
    auto add = [&](double v) {
        if (!std::isfinite(v)) return false;
        if (v == 0) return true;
        int e = 0;
        const double f = std::frexp(std::fabs(v), &e);        // |v| = f 2^e, f in [0.5, 1)
        const uint64_t mantissa = uint64_t(std::ldexp(f, 53));  // exact: 53 significant bits
        low = std::min(low, e - 53 + std::countr_zero(mantissa));
        high = std::max(high, e);
        return true;
    };
    for (const Mesh* m : {&a, &b})
        for (const auto& t : m->triangles) {
            if (!usable(*m, t)) continue;
            for (uint32_t i : t) {
                const Vec3& p = m->positions[i];
                if (!add(p.x) || !add(p.y) || !add(p.z)) return false;
            }
        }
    if (low == INT32_MAX) {  // every coordinate is zero (or there are none)
        exponent = 0;
        bits = 0;
        return true;
    }
    exponent = low;
    bits = high - low;  // |v| < 2^high, so |v| / 2^low < 2^bits
    return true;
}

// --- the comparison ---------------------------------------------------------

template <class Types>
struct Comparer {
    using Coord = typename Types::Coord;
    using Wide = typename Types::Wide;
    using Wider = typename Types::Wider;
    using IPoint = std::array<Coord, 3>;

    struct PlaneKey {
        Wide nx, ny, nz;  // primitive normal, first non-zero component positive
        Wider d;          // n . p for any point p of the plane
        bool operator==(const PlaneKey&) const = default;
    };
    struct PlaneHash {
        size_t operator()(const PlaneKey& k) const {
            size_t h = 0;
            mixValue(h, k.nx);
            mixValue(h, k.ny);
            mixValue(h, k.nz);
            mixValue(h, k.d);
            return h;
        }
    };
    // A jump of a line's multiplicity at parameter t, from one directed edge
    // end, within one plane. The line is its primitive direction u (first
    // non-zero component positive) and its moment m = p x u.
    struct Event {
        Coord ux, uy, uz;
        Wide mx, my, mz;
        Coord t;
        int32_t end;      // +1 at the edge's start, -1 at its end
        uint32_t vertex;  // for locating a difference
        uint8_t mesh;     // 0 model, 1 reference
    };
    struct Edge {
        uint32_t p, q;  // directed, vertex indices of `mesh`
        uint8_t mesh;
    };
    struct TriangleRef {
        uint32_t triangle;
        uint8_t mesh;
    };

    const Mesh* meshes[2] = {nullptr, nullptr};
    int exponent = 0;
    std::vector<IPoint> ipoints[2];
    std::vector<int64_t> plane_of_triangle[2];  // -1: ignored or no area
    size_t plane_count = 0;

    Coord toGrid(double v) const { return Coord(std::ldexp(v, -exponent)); }  // exact: an integer below 2^bits

    void scale(int k) {
        const Mesh& m = *meshes[k];
        ipoints[k].resize(m.positions.size());
        std::vector<uint8_t> used(m.positions.size(), 0);
        for (const auto& t : m.triangles)
            if (usable(m, t)) used[t[0]] = used[t[1]] = used[t[2]] = 1;
        for (size_t i = 0; i < m.positions.size(); ++i)
            if (used[i]) ipoints[k][i] = {toGrid(m.positions[i].x), toGrid(m.positions[i].y), toGrid(m.positions[i].z)};
    }

    // Numbers the distinct planes of both meshes' triangles.
    void findPlanes() {
        std::unordered_map<PlaneKey, uint32_t, PlaneHash> planes;
        for (int k = 0; k < 2; ++k) {
            const Mesh& m = *meshes[k];
            plane_of_triangle[k].assign(m.triangles.size(), -1);
            for (size_t ti = 0; ti < m.triangles.size(); ++ti) {
                const auto& t = m.triangles[ti];
                if (!usable(m, t)) continue;
                const IPoint &a = ipoints[k][t[0]], &b = ipoints[k][t[1]], &c = ipoints[k][t[2]];
                const Wide abx = Wide(b[0] - a[0]), aby = Wide(b[1] - a[1]), abz = Wide(b[2] - a[2]);
                const Wide acx = Wide(c[0] - a[0]), acy = Wide(c[1] - a[1]), acz = Wide(c[2] - a[2]);
                PlaneKey key{aby * acz - abz * acy, abz * acx - abx * acz, abx * acy - aby * acx, Wider(0)};
                if (key.nx == 0 && key.ny == 0 && key.nz == 0) continue;  // no area: no plane
                makePrimitive(key.nx, key.ny, key.nz);
                key.d = Wider(key.nx) * Wider(a[0]) + Wider(key.ny) * Wider(a[1]) + Wider(key.nz) * Wider(a[2]);
                plane_of_triangle[k][ti] = planes.try_emplace(key, uint32_t(planes.size())).first->second;
            }
        }
        plane_count = planes.size();
    }

    enum class PlaneVerdict { Same, Opposite, Different };

    // The directed edges of one plane's triangles as events, sorted by line
    // and parameter, and whether the two meshes' parts in the plane are the
    // same, the same facing the other way, or different (then the places
    // that do not cancel are added to `out`).
    PlaneVerdict comparePlane(const std::vector<TriangleRef>& tris, std::vector<Edge>& edges,
                              std::vector<Event>& events, std::vector<Vec3>& misses, ChainComparison& out,
                              size_t max_points) const {
        // An edge that two triangles of the same mesh in this plane share,
        // in opposite directions, cancels (an inside edge of a triangulated
        // region); most edges are such, and they need no line.
        edges.clear();
        for (const TriangleRef& r : tris) {
            const auto& t = meshes[r.mesh]->triangles[r.triangle];
            for (int e = 0; e < 3; ++e) edges.push_back({t[size_t(e)], t[size_t((e + 1) % 3)], r.mesh});
        }
        std::sort(edges.begin(), edges.end(), [](const Edge& x, const Edge& y) {
            const uint32_t xlo = std::min(x.p, x.q), ylo = std::min(y.p, y.q);
            if (x.mesh != y.mesh) return x.mesh < y.mesh;
            if (xlo != ylo) return xlo < ylo;
            return std::max(x.p, x.q) < std::max(y.p, y.q);
        });
        events.clear();
        for (size_t i = 0; i < edges.size(); ++i) {
            if (i + 1 < edges.size() && edges[i + 1].mesh == edges[i].mesh && edges[i + 1].p == edges[i].q &&
                edges[i + 1].q == edges[i].p) {
                ++i;  // the pair cancels
                continue;
            }
            const uint8_t mesh = edges[i].mesh;
            const uint32_t vp = edges[i].p, vq = edges[i].q;
            const IPoint &p = ipoints[mesh][vp], &q = ipoints[mesh][vq];
            Event ev{Coord(q[0] - p[0]), Coord(q[1] - p[1]), Coord(q[2] - p[2]), Wide(0), Wide(0), Wide(0),
                     Coord(0), 1, vp, mesh};
            makePrimitive(ev.ux, ev.uy, ev.uz);
            ev.mx = Wide(p[1]) * Wide(ev.uz) - Wide(p[2]) * Wide(ev.uy);
            ev.my = Wide(p[2]) * Wide(ev.ux) - Wide(p[0]) * Wide(ev.uz);
            ev.mz = Wide(p[0]) * Wide(ev.uy) - Wide(p[1]) * Wide(ev.ux);
            // Parameter along the line: the coordinate of its first axis
            // with a non-zero direction component (strictly monotone along it).
            const size_t axis = ev.ux != 0 ? 0 : (ev.uy != 0 ? 1 : 2);
            ev.t = p[axis];
            events.push_back(ev);
            ev.t = q[axis];
            ev.end = -1;
            ev.vertex = vq;
            events.push_back(ev);
        }
        auto sameLine = [](const Event& x, const Event& y) {
            return x.ux == y.ux && x.uy == y.uy && x.uz == y.uz && x.mx == y.mx && x.my == y.my && x.mz == y.mz;
        };
        std::sort(events.begin(), events.end(), [](const Event& x, const Event& y) {
            if (x.ux != y.ux) return x.ux < y.ux;
            if (x.uy != y.uy) return x.uy < y.uy;
            if (x.uz != y.uz) return x.uz < y.uz;
            if (x.mx != y.mx) return x.mx < y.mx;
            if (x.my != y.my) return x.my < y.my;
            if (x.mz != y.mz) return x.mz < y.mz;
            return x.t < y.t;
        });
        // Per (line, point): the model's jumps minus the reference's (equal
        // surfaces) and plus them (equal surfaces facing opposite ways).
        bool same = true, opposite = true;
        misses.clear();
        for (size_t i = 0; i < events.size();) {
            size_t j = i;
            int64_t minus = 0, plus = 0;
            for (; j < events.size() && events[j].t == events[i].t && sameLine(events[j], events[i]); ++j) {
                minus += events[j].mesh == 0 ? events[j].end : -events[j].end;
                plus += events[j].end;
            }
            if (minus != 0) {
                same = false;
                misses.push_back(meshes[events[i].mesh]->positions[events[i].vertex]);
            }
            if (plus != 0) opposite = false;
            i = j;
        }
        if (same) return PlaneVerdict::Same;
        if (opposite) return PlaneVerdict::Opposite;
        out.difference_point_count += misses.size();
        for (const Vec3& p : misses)
            if (out.difference_points.size() < max_points) out.difference_points.push_back(p);
        return PlaneVerdict::Different;
    }

    void run(ChainComparison& out, size_t max_points) {
        scale(0);
        scale(1);
        findPlanes();
        // Triangles grouped by plane (counting sort), then one plane at a
        // time, so that each plane's events stay in cache.
        std::vector<uint32_t> start(plane_count + 1, 0);
        for (int k = 0; k < 2; ++k)
            for (int64_t p : plane_of_triangle[k])
                if (p >= 0) ++start[size_t(p) + 1];
        for (size_t p = 0; p < plane_count; ++p) start[p + 1] += start[p];
        std::vector<TriangleRef> by_plane(start[plane_count]);
        std::vector<uint32_t> fill(start.begin(), start.end() - 1);
        for (int k = 0; k < 2; ++k)
            for (size_t ti = 0; ti < plane_of_triangle[k].size(); ++ti)
                if (const int64_t p = plane_of_triangle[k][ti]; p >= 0)
                    by_plane[fill[size_t(p)]++] = {uint32_t(ti), uint8_t(k)};
        std::vector<uint8_t> plane_differs(plane_count, 0);
        std::vector<TriangleRef> tris;
        std::vector<Edge> edges;
        std::vector<Event> events;
        std::vector<Vec3> misses;
        for (size_t p = 0; p < plane_count; ++p) {
            tris.assign(by_plane.begin() + start[p], by_plane.begin() + start[p + 1]);
            const PlaneVerdict v = comparePlane(tris, edges, events, misses, out, max_points);
            plane_differs[p] = v == PlaneVerdict::Different;
            out.opposite_planes += v == PlaneVerdict::Opposite;
        }
        out.planes = plane_count;
        out.differing_planes = size_t(std::count(plane_differs.begin(), plane_differs.end(), 1));
        std::vector<uint8_t>* flags[2] = {&out.model_differs, &out.reference_differs};
        for (int k = 0; k < 2; ++k) {
            const Mesh& m = *meshes[k];
            flags[k]->assign(m.triangles.size(), 0);
            for (size_t ti = 0; ti < m.triangles.size(); ++ti) {
                if (!usable(m, m.triangles[ti])) continue;
                const int64_t plane = plane_of_triangle[k][ti];
                (*flags[k])[ti] = plane < 0 || plane_differs[size_t(plane)];
            }
        }
    }
};

}  // namespace

ChainComparison compareSurfaceChains(const Mesh& model, const Mesh& reference, size_t max_points) {
    ChainComparison out;
    int exponent = 0, bits = 0;
    const bool finite = gridOf(model, reference, exponent, bits);
    out.grid_bits = bits;
    if (!finite || bits > kWideGridBits) {
        out.note = finite ? "the coordinates need " + std::to_string(bits) + " bits on a common binary grid (at most " +
                                std::to_string(kWideGridBits) + ")"
                          : "non-finite coordinates";
        out.model_differs.assign(model.triangles.size(), 1);
        out.reference_differs.assign(reference.triangles.size(), 1);
        return out;
    }
    out.compared = true;
    if (bits <= kFastGridBits) {
        Comparer<FastTypes> c;
        c.meshes[0] = &model;
        c.meshes[1] = &reference;
        c.exponent = exponent;
        c.run(out, max_points);
    } else {
        Comparer<WideTypes> c;
        c.meshes[0] = &model;
        c.meshes[1] = &reference;
        c.exponent = exponent;
        c.run(out, max_points);
    }
    return out;
}

}  // namespace tsf
