#include "app/preview.h"

#include "gen/mesh/mesh_picture.h"
#include "gen/util/rgb_image.h"

namespace tsf::cli {

void writeModelPreview(const Mesh& mesh, const std::string& png_path, bool underside, double colour_top_z_mm,
                       const std::string& size_text, int width_px, int height_px) {
    MeshPictureOptions po;
    po.colour_top_z_mm = colour_top_z_mm;
    po.size_text = size_text;
    po.width_px = width_px;
    po.height_px = height_px;
    po.underside = underside;
    writePng(png_path, drawMeshPicture(mesh, po));
}

}  // namespace tsf::cli
