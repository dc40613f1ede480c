#include "app/preview.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "gen/mesh/mesh_picture.h"
#include "gen/util/rgb_image.h"

namespace tsf::cli {

namespace {

// Colours told apart by most eyes, colour-blind ones included (Okabe and Ito,
// then darker and lighter variants); classes beyond them repeat the list.
constexpr uint32_t kClassColours[] = {0xe69f00, 0x56b4e9, 0x009e73, 0xf0e442, 0x0072b2, 0xd55e00, 0xcc79a7,
                                      0x999999, 0x8c510a, 0x01665e, 0x762a83, 0xb2df8a};

}  // namespace

void writeModelPreview(const Mesh& mesh, const std::string& png_path, bool underside, double colour_top_z_mm,
                       const std::string& size_text, int width_px, int height_px, const Scene* classes) {
    MeshPictureOptions po;
    po.colour_top_z_mm = colour_top_z_mm;
    po.size_text = size_text;
    if (classes) {
        // A colour per class value, the commonest class first.
        std::map<double, int64_t> count;
        for (size_t k = 0; k < classes->keptCount(); ++k)
            if (classes->kind[k] == CellKind::Data && std::isfinite(classes->value[k])) ++count[classes->value[k]];
        std::vector<std::pair<int64_t, double>> by_count;
        for (const auto& [v, n] : count) by_count.push_back({-n, v});
        std::sort(by_count.begin(), by_count.end());
        std::map<double, uint32_t> colour;
        for (size_t k = 0; k < by_count.size(); ++k)
            colour[by_count[k].second] = kClassColours[k % (sizeof kClassColours / sizeof kClassColours[0])];
        const Scene* s = classes;
        po.top_colour = [s, colour](double x_mm, double y_mm, uint32_t& rgb) {
            int32_t c = 0, r = 0;
            if (!hexCellAt(s->grid, x_mm / s->pitch_mm, y_mm / (s->pitch_mm * s->y_scale), c, r)) return false;
            const int32_t k = s->keptAt(c, r);
            if (k < 0 || s->kind[size_t(k)] != CellKind::Data) return false;
            const auto it = colour.find(s->value[size_t(k)]);
            if (it == colour.end()) return false;
            rgb = it->second;
            return true;
        };
    }
    po.width_px = width_px;
    po.height_px = height_px;
    po.underside = underside;
    writePng(png_path, drawMeshPicture(mesh, po));
}

}  // namespace tsf::cli
