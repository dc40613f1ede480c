#include "app/preview.h"

#include "gen/mesh/mesh_picture.h"
#include "gen/util/rgb_image.h"

namespace tsf::cli {

void writeModelPreview(const Mesh& mesh, const std::string& png_path, bool underside, int width_px, int height_px) {
    MeshPictureOptions po;
    po.width_px = width_px;
    po.height_px = height_px;
    po.underside = underside;
    writePng(png_path, drawMeshPicture(mesh, po));
}

}  // namespace tsf::cli
