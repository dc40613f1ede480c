#include "gen/mesh/mesh_picture.h"
#include "gen/util/number_format.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kElevationDeg = 50;  // camera above the horizon
constexpr int kMarginPx = 24;
constexpr int kFontScale = 3;         // label glyphs: 9 x 15 px
constexpr uint32_t kInk = 0x202020;

Vec3 unit(const Vec3& v) {
    const double n = std::sqrt(dot(v, v));
    return n > 0 ? Vec3{v.x / n, v.y / n, v.z / n} : v;
}

// Height ramp: dark blue -> teal -> green -> yellow, t in [0, 1].
Vec3 heightColour(double t) {
    static const double kStops[4][3] = {{35, 60, 140}, {30, 140, 150}, {90, 180, 80}, {240, 220, 70}};
    t = std::clamp(t, 0.0, 1.0) * 3.0;
    const int i = std::min(2, int(t));
    t -= i;
    return {kStops[i][0] + (kStops[i + 1][0] - kStops[i][0]) * t, kStops[i][1] + (kStops[i + 1][1] - kStops[i][1]) * t,
            kStops[i][2] + (kStops[i + 1][2] - kStops[i][2]) * t};
}

// An orthographic camera: screen right, screen up, toward the viewer.
struct Camera {
    Vec3 right, up, toward;
};

Camera camera(bool from_below) {
    const double e = kElevationDeg * kPi / 180;
    if (!from_below) return {{1, 0, 0}, {0, std::sin(e), std::cos(e)}, {0, -std::cos(e), std::sin(e)}};
    return {{-1, 0, 0}, {0, std::sin(e), -std::cos(e)}, {0, -std::cos(e), -std::sin(e)}};
}

// A "nice" scale-bar length (1, 2 or 5 times a power of ten) near a fifth of `extent_mm`.
double niceLength(double extent_mm) {
    const double target = extent_mm / 5;
    const double p = std::pow(10.0, std::floor(std::log10(target)));
    for (double m : {5.0, 2.0, 1.0})
        if (m * p <= target) return m * p;
    return p;
}

// Draws one view into the rectangle [x0, x0 + w) x [y0, y0 + h) of img.
void drawView(RgbImage& img, int x0, int y0, int w, int h, const Mesh& mesh, const Bounds& b, bool from_below,
              const MeshPictureOptions& opts) {
    const Camera cam = camera(from_below);
    const std::string title = from_below ? "underside, from below: east left" : "top, seen from the south";
    drawText(img, x0 + kMarginPx, y0 + kMarginPx / 2, title, kFontScale, kInk);
    const int label_h = textHeight(kFontScale) + kMarginPx;  // title above, scale bar below
    // Frame: the projected bounds fill the view inside the margins.
    double lo_x = 1e300, hi_x = -1e300, lo_y = 1e300, hi_y = -1e300;
    for (const Vec3& p : mesh.positions) {
        lo_x = std::min(lo_x, dot(p, cam.right)), hi_x = std::max(hi_x, dot(p, cam.right));
        lo_y = std::min(lo_y, dot(p, cam.up)), hi_y = std::max(hi_y, dot(p, cam.up));
    }
    const int avail_w = w - 2 * kMarginPx, avail_h = h - 2 * label_h - kMarginPx;
    const double scale = std::min(avail_w / std::max(hi_x - lo_x, 1e-9), avail_h / std::max(hi_y - lo_y, 1e-9));
    const double off_x = x0 + kMarginPx + (avail_w - (hi_x - lo_x) * scale) / 2;
    const double off_y = y0 + label_h + (avail_h - (hi_y - lo_y) * scale) / 2;
    auto screen = [&](const Vec3& p, double& sx, double& sy) {
        sx = off_x + (dot(p, cam.right) - lo_x) * scale;
        sy = off_y + (hi_y - dot(p, cam.up)) * scale;
    };
    std::vector<double> depth(size_t(w) * size_t(h), -std::numeric_limits<double>::infinity());
    const Vec3 light = unit({-0.5, 0.6, from_below ? -0.65 : 0.65});  // from the north-west, on the viewed side
    const double z_range = std::max((opts.colour_top_z_mm > 0 ? opts.colour_top_z_mm : b.max.z) - b.min.z, 1e-9);
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = mesh.positions[t[0]], &bb = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        const Vec3 n = unit(cross(sub(bb, a), sub(c, a)));
        if (dot(n, cam.toward) <= 0) continue;  // faces away (the mesh is closed)
        const double shade = 0.45 + 0.55 * std::max(0.0, dot(n, light));
        // A top's own colour (a class), when the caller gives one.
        uint32_t own = 0;
        const bool has_own = opts.top_colour && n.z > 0.5 &&
                             opts.top_colour((a.x + bb.x + c.x) / 3, (a.y + bb.y + c.y) / 3, own);
        const Vec3 own_rgb{double((own >> 16) & 0xff), double((own >> 8) & 0xff), double(own & 0xff)};
        double sx[3], sy[3], d[3], z[3];
        const Vec3* v[3] = {&a, &bb, &c};
        for (int k = 0; k < 3; ++k) {
            screen(*v[k], sx[k], sy[k]);
            d[k] = dot(*v[k], cam.toward);
            z[k] = v[k]->z;
        }
        const double area = (sx[1] - sx[0]) * (sy[2] - sy[0]) - (sx[2] - sx[0]) * (sy[1] - sy[0]);
        if (std::abs(area) < 1e-12) continue;
        const int px0 = std::max(x0, int(std::floor(std::min({sx[0], sx[1], sx[2]}))));
        const int px1 = std::min(x0 + w - 1, int(std::ceil(std::max({sx[0], sx[1], sx[2]}))));
        const int py0 = std::max(y0, int(std::floor(std::min({sy[0], sy[1], sy[2]}))));
        const int py1 = std::min(y0 + h - 1, int(std::ceil(std::max({sy[0], sy[1], sy[2]}))));
        for (int py = py0; py <= py1; ++py)
            for (int px = px0; px <= px1; ++px) {
                const double cx = px + 0.5, cy = py + 0.5;
                const double w0 = ((sx[1] - cx) * (sy[2] - cy) - (sx[2] - cx) * (sy[1] - cy)) / area;
                const double w1 = ((sx[2] - cx) * (sy[0] - cy) - (sx[0] - cx) * (sy[2] - cy)) / area;
                const double w2 = 1 - w0 - w1;
                if (w0 < 0 || w1 < 0 || w2 < 0) continue;
                const double pd = w0 * d[0] + w1 * d[1] + w2 * d[2];
                double& zb = depth[size_t(py - y0) * size_t(w) + size_t(px - x0)];
                if (pd <= zb) continue;
                zb = pd;
                const Vec3 col = has_own ? own_rgb : heightColour((w0 * z[0] + w1 * z[1] + w2 * z[2] - b.min.z) / z_range);
                img.set(px, py,
                        (uint32_t(std::lround(col.x * shade)) << 16) | (uint32_t(std::lround(col.y * shade)) << 8) |
                            uint32_t(std::lround(col.z * shade)));
            }
    }
    // North arrow, top right: north is up on the screen in both views.
    const int ax = x0 + w - kMarginPx - 3 * kFontScale, ay = y0 + label_h;
    img.line(ax, ay + 14 * kFontScale, ax, ay + 3 * kFontScale, 2, kInk);
    img.line(ax, ay + 3 * kFontScale, ax - 2 * kFontScale, ay + 6 * kFontScale, 2, kInk);
    img.line(ax, ay + 3 * kFontScale, ax + 2 * kFontScale, ay + 6 * kFontScale, 2, kInk);
    drawText(img, ax - kFontScale, ay - 4 * kFontScale, "N", kFontScale, kInk);
    if (from_below) return;
    // Scale bar along x (true length in this projection) and the size in mm.
    const double bar_mm = niceLength(b.max.x - b.min.x);
    const int bx = x0 + kMarginPx, by = y0 + h - kMarginPx - textHeight(kFontScale);
    img.fill(bx, by, bx + int(std::lround(bar_mm * scale)), by + kFontScale * 2, kInk);
    const std::string size = formatFixed(bar_mm, 0) + " mm;  " +
                             (!opts.size_text.empty() ? opts.size_text
                                                      : "model " + formatFixed(b.max.x - b.min.x, 0) + " x " +
                                                            formatFixed(b.max.y - b.min.y, 0) + " x " +
                                                            formatFixed(b.max.z - b.min.z, 0) + " mm");
    drawText(img, bx + int(std::lround(bar_mm * scale)) + 2 * kFontScale, by - kFontScale, size, kFontScale, kInk);
}

}  // namespace

bool hasRaisedUnderside(const Mesh& mesh) {
    const double floor_z = meshBounds(mesh).min.z;
    for (const auto& t : mesh.triangles) {
        const Vec3 &a = mesh.positions[t[0]], &b = mesh.positions[t[1]], &c = mesh.positions[t[2]];
        if (cross(sub(b, a), sub(c, a)).z < 0 && std::min({a.z, b.z, c.z}) > floor_z) return true;
    }
    return false;
}

RgbImage drawMeshPicture(const Mesh& mesh, const MeshPictureOptions& opts) {
    RgbImage img(opts.width_px, opts.height_px, kPictureBackground);
    if (mesh.positions.empty() || mesh.triangles.empty()) return img;
    const Bounds b = meshBounds(mesh);
    if (!opts.underside) {
        drawView(img, 0, 0, img.w, img.h, mesh, b, false, opts);
        return img;
    }
    const int half = img.w / 2;
    drawView(img, 0, 0, half, img.h, mesh, b, false, opts);
    drawView(img, half, 0, img.w - half, img.h, mesh, b, true, opts);
    img.line(half, kMarginPx, half, img.h - kMarginPx, 1, 0xc0c0c0);
    return img;
}

}  // namespace tsf
