// rasteriseTop: consistent edge functions, closed coverage. See height_field.h.
#include "verify/height_field.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gen/util/workers.h"

namespace tsf {
namespace {

struct P2 {
    double x, y;
};

bool before(const P2& a, const P2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); }

// Twice the signed area of (a, b, s): positive when s is left of a -> b.
// Evaluated from the edge's first end (before()), so the edge b -> a gives
// exactly the negation.
double edgeFunction(const P2& a, const P2& b, const P2& s) {
    if (before(b, a)) return -edgeFunction(b, a, s);
    return (b.x - a.x) * (s.y - a.y) - (b.y - a.y) * (s.x - a.x);
}

// The triangles [from, to) into `z` (the field's samples), keeping the highest.
void rasteriseRange(const Mesh& mesh, size_t from, size_t to, const TopHeightField& f, std::vector<double>& z) {
    const size_t nv = mesh.positions.size();
    for (size_t t = from; t < to; ++t) {
        const auto& q = mesh.triangles[t];
        if (q[0] >= nv || q[1] >= nv || q[2] >= nv) continue;
        const Vec3 &a = mesh.positions[q[0]], &b = mesh.positions[q[1]], &c = mesh.positions[q[2]];
        if (!std::isfinite(a.x + a.y + a.z + b.x + b.y + b.z + c.x + c.y + c.z)) continue;
        const P2 pa{a.x, a.y}, pb{b.x, b.y}, pc{c.x, c.y};
        // Two corners over one point (a wall of the lattice): that edge's
        // function is exactly 0 and the other two are exact negations of
        // each other, so no sample is covered with an area; skipped whole.
        const auto same = [](const P2& u, const P2& v) { return u.x == v.x && u.y == v.y; };
        if (same(pa, pb) || same(pb, pc) || same(pc, pa)) continue;
        const double z_lo = std::min({a.z, b.z, c.z}), z_hi = std::max({a.z, b.z, c.z});
        // The samples within the shadow's box.
        const double x_lo = std::min({a.x, b.x, c.x}), x_hi = std::max({a.x, b.x, c.x});
        const double y_lo = std::min({a.y, b.y, c.y}), y_hi = std::max({a.y, b.y, c.y});
        const int i0 = std::max(0, int(std::ceil((x_lo - f.x0) / f.step)) - 1);
        const int i1 = std::min(f.nx - 1, int(std::floor((x_hi - f.x0) / f.step)) + 1);
        const int j0 = std::max(0, int(std::ceil((y_lo - f.y0) / f.step)) - 1);
        const int j1 = std::min(f.ny - 1, int(std::floor((y_hi - f.y0) / f.step)) + 1);
        if (i0 > i1 || j0 > j1) continue;
        for (int j = j0; j <= j1; ++j) {
            const double y = f.y0 + j * f.step;
            if (y < y_lo || y > y_hi) continue;
            for (int i = i0; i <= i1; ++i) {
                const P2 s{f.x0 + i * f.step, y};
                const double wa = edgeFunction(pb, pc, s), wb = edgeFunction(pc, pa, s), wc = edgeFunction(pa, pb, s);
                // Covered: all three on one side or on an edge (either winding).
                if ((wa < 0 || wb < 0 || wc < 0) && (wa > 0 || wb > 0 || wc > 0)) continue;
                const double sum = wa + wb + wc;
                if (sum == 0) continue;  // no area in the shadow, or the sum cancelled
                const double height = std::clamp((wa * a.z + wb * b.z + wc * c.z) / sum, z_lo, z_hi);
                double& cell = z[size_t(j) * size_t(f.nx) + size_t(i)];
                cell = std::max(cell, height);
            }
        }
    }
}

}  // namespace

void rasteriseTop(const Mesh& mesh, TopHeightField& f) {
    const double none = -std::numeric_limits<double>::infinity();
    f.z.assign(size_t(std::max(f.nx, 0)) * size_t(std::max(f.ny, 0)), none);
    if (f.nx <= 0 || f.ny <= 0 || !(f.step > 0)) return;
    // The triangles shared among the verifier's threads, each into a field
    // of its own (8 bytes a sample), then the highest of them.
    const size_t nt = mesh.triangles.size();
    const unsigned workers = nt < 20000 ? 1u : detail::workerCount(0);
    std::vector<std::vector<double>> parts(workers - 1, std::vector<double>(f.z.size(), none));
    detail::runOnWorkers(workers, [&](unsigned w, const auto&) {
        rasteriseRange(mesh, nt * w / workers, nt * (w + 1) / workers, f, w == 0 ? f.z : parts[w - 1]);
    });
    for (const auto& part : parts)
        for (size_t k = 0; k < f.z.size(); ++k) f.z[k] = std::max(f.z[k], part[k]);
}

}  // namespace tsf
