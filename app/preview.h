// A preview picture of a generated model, so a sighted helper can check it
// before hours of printing: drawn by tsf from the mesh it writes
// (gen/mesh/mesh_picture.h), framed to fill the picture, coloured by height, with
// north and a scale bar, and the underside beside the top for a mirrored
// model. Needs no OpenSCAD and no display.
#pragma once

#include <string>

#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"

namespace tsf::cli {

/// Draws `mesh` to png_path (width x height pixels); `underside` adds the
/// view from below; colour_top_z_mm and size_text as MeshPictureOptions
/// (a series' shared colour scale; the pieces' sizes). Throws
/// tsf::OutputError when the file cannot be written.
/// `classes` (may be null): the Scene of a class map, whose tops are then
/// coloured by class (a distinct colour per class, commonest first) instead
/// of by height, so classes standing at one height still differ.
void writeModelPreview(const Mesh& mesh, const std::string& png_path, bool underside, double colour_top_z_mm = 0,
                       const std::string& size_text = "", int width_px = 1200, int height_px = 800,
                       const Scene* classes = nullptr);

}  // namespace tsf::cli
