#include "gen/legend_mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <numbers>

namespace tsf {
namespace {

double snapUm(double mm) { return std::round(mm * 1000.0) / 1000.0; }

// Sorted distinct values, each snapped.
std::vector<double> distinct(std::vector<double> v) {
    for (double& x : v) x = snapUm(x);
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
}

// Grid lines: the plate's edges and the midpoints between neighbouring dot positions.
std::vector<double> cuts(const std::vector<double>& centres, double extent) {
    std::vector<double> c{0.0};
    for (size_t k = 0; k + 1 < centres.size(); ++k) c.push_back(snapUm((centres[k] + centres[k + 1]) / 2));
    c.push_back(snapUm(extent));
    return c;
}

struct Builder {
    Mesh mesh;
    uint32_t add(double x, double y, double z) {
        mesh.positions.push_back({snapUm(x), snapUm(y), snapUm(z)});
        return uint32_t(mesh.positions.size() - 1);
    }
    void tri(uint32_t a, uint32_t b, uint32_t c) { mesh.triangles.push_back({a, b, c}); }
};

}  // namespace

Mesh meshLegendPlate(const LegendLayout& l, double plate_height_mm) {
    assert(plate_height_mm > 0);
    Builder b;
    if (l.dots.empty()) return b.mesh;
    std::vector<double> xs, ys;
    for (const LegendDot& d : l.dots) {
        xs.push_back(d.x_mm);
        ys.push_back(d.y_mm);
    }
    const std::vector<double> dx = distinct(xs), dy = distinct(ys);
    const std::vector<double> cx = cuts(dx, l.width_mm), cy = cuts(dy, l.depth_mm);
    const size_t nx = cx.size(), ny = cy.size();
    const double h = plate_height_mm;

    // Grid vertices, top and bottom.
    std::vector<uint32_t> top(nx * ny), bottom(nx * ny);
    for (size_t j = 0; j < ny; ++j)
        for (size_t i = 0; i < nx; ++i) {
            top[j * nx + i] = b.add(cx[i], cy[j], h);
            bottom[j * nx + i] = b.add(cx[i], cy[j], 0);
        }
    auto T = [&](size_t i, size_t j) { return top[j * nx + i]; };
    auto B = [&](size_t i, size_t j) { return bottom[j * nx + i]; };

    // Which rectangle (i, j) holds which dot: rectangle i spans column dx[i] (cuts i..i+1).
    std::map<std::pair<size_t, size_t>, LegendDot> dot_at;
    for (const LegendDot& d : l.dots) {
        const size_t i = size_t(std::lower_bound(dx.begin(), dx.end(), snapUm(d.x_mm)) - dx.begin());
        const size_t j = size_t(std::lower_bound(dy.begin(), dy.end(), snapUm(d.y_mm)) - dy.begin());
        dot_at[{i, j}] = d;
    }

    // The spherical cap through the base circle (radius r) and the apex (height hd).
    const double r = l.standard.dot_base_mm / 2, hd = l.standard.dot_height_mm;
    const double R = (r * r + hd * hd) / (2 * hd);  // sphere radius
    const double theta_max = std::asin(r / R);      // half-angle of the cap seen from the sphere's centre
    const double zc = h + hd - R;                   // sphere centre

    for (size_t j = 0; j + 1 < ny; ++j)
        for (size_t i = 0; i + 1 < nx; ++i) {
            // Corners counter-clockwise from the north-east: C1 NE, C2 NW, C3 SW, C4 SE.
            const uint32_t c1 = T(i + 1, j + 1), c2 = T(i, j + 1), c3 = T(i, j), c4 = T(i + 1, j);
            b.tri(B(i, j), B(i + 1, j + 1), B(i + 1, j));  // bottom, normal -z
            b.tri(B(i, j), B(i, j + 1), B(i + 1, j + 1));
            const auto found = dot_at.find({i, j});
            if (found == dot_at.end()) {
                b.tri(c3, c4, c1);
                b.tri(c3, c1, c2);
                continue;
            }
            const LegendDot& d = found->second;
            std::vector<std::vector<uint32_t>> rings;
            for (int ring = 0; ring <= kDomeRings; ++ring) {
                const double theta = theta_max * (1.0 - double(ring) / double(kDomeRings + 1));
                const double rr = ring == 0 ? r : R * std::sin(theta);
                const double z = ring == 0 ? h : zc + R * std::cos(theta);
                std::vector<uint32_t> v;
                for (int k = 0; k < kDomeSides; ++k) {
                    const double a = 2 * std::numbers::pi * k / kDomeSides;
                    v.push_back(b.add(d.x_mm + rr * std::cos(a), d.y_mm + rr * std::sin(a), z));
                }
                rings.push_back(v);
            }
            const uint32_t apex = b.add(d.x_mm, d.y_mm, h + hd);
            // The annulus between the rectangle and the base octagon: each corner
            // joins the base vertices of its quadrant, and the next corner the last of them.
            const std::vector<uint32_t>& base = rings[0];
            const uint32_t corner[4] = {c1, c2, c3, c4};
            for (int q = 0; q < 4; ++q) {
                const int k0 = 2 * q;  // base vertices 2q, 2q+1, 2q+2 at 90q, 90q+45, 90q+90 degrees
                b.tri(base[size_t(k0)], corner[q], base[size_t(k0 + 1)]);
                b.tri(base[size_t(k0 + 1)], corner[q], base[size_t((k0 + 2) % kDomeSides)]);
                b.tri(corner[q], corner[(q + 1) % 4], base[size_t((k0 + 2) % kDomeSides)]);
            }
            for (int ring = 0; ring < kDomeRings; ++ring)
                for (int k = 0; k < kDomeSides; ++k) {
                    const size_t k1 = size_t((k + 1) % kDomeSides);
                    const std::vector<uint32_t>&lo = rings[size_t(ring)], &hi = rings[size_t(ring + 1)];
                    b.tri(lo[size_t(k)], lo[k1], hi[k1]);
                    b.tri(lo[size_t(k)], hi[k1], hi[size_t(k)]);
                }
            const std::vector<uint32_t>& last = rings.back();
            for (int k = 0; k < kDomeSides; ++k) b.tri(last[size_t(k)], last[size_t((k + 1) % kDomeSides)], apex);
        }

    // Sides, outward: south (-y), east (+x), north (+y), west (-x).
    for (size_t i = 0; i + 1 < nx; ++i) {
        b.tri(B(i, 0), B(i + 1, 0), T(i + 1, 0));
        b.tri(B(i, 0), T(i + 1, 0), T(i, 0));
        b.tri(B(i + 1, ny - 1), B(i, ny - 1), T(i, ny - 1));
        b.tri(B(i + 1, ny - 1), T(i, ny - 1), T(i + 1, ny - 1));
    }
    for (size_t j = 0; j + 1 < ny; ++j) {
        b.tri(B(nx - 1, j), B(nx - 1, j + 1), T(nx - 1, j + 1));
        b.tri(B(nx - 1, j), T(nx - 1, j + 1), T(nx - 1, j));
        b.tri(B(0, j + 1), B(0, j), T(0, j));
        b.tri(B(0, j + 1), T(0, j), T(0, j + 1));
    }
    return b.mesh;
}

}  // namespace tsf
