// A picture of a model that shows what will be printed, drawn by tsf itself
// (no OpenSCAD, no display needed): for `tsf gen --preview`.
//
// Each view is an orthographic projection from the south, 50 degrees above
// the horizon, framed so the model fills the view. Surfaces are coloured by
// height (dark blue low -> teal -> green -> yellow high, mesh z range) and lit
// from the north-west, so relief reads. Each view is labelled; the top view
// carries a north arrow, a scale bar in millimetres and the model's size.
// With `underside`, a second view beside the first shows the model from
// below (as seen from below, so east is on the left): the mirrored bottom a
// finger reads from underneath.
#pragma once

#include <functional>
#include <string>

#include "gen/geometry/mesh.h"
#include "gen/util/rgb_image.h"

namespace tsf {

struct MeshPictureOptions {
    int width_px = 1200;   ///< whole picture, both views
    int height_px = 800;
    bool underside = false;  ///< add the view from below
    /// The colour (0xRRGGBB) of an upward-facing surface at (x, y) mm, asked
    /// once per triangle at its centre (a class map's class); false, or no
    /// function: coloured by height.
    std::function<bool(double x_mm, double y_mm, uint32_t& rgb)> top_colour;
    /// > 0: the colours run from the mesh's lowest z to this z (mm), not to
    /// its highest: the pictures of a series share one colour scale, so the
    /// same height is the same colour in each.
    double colour_top_z_mm = 0;
    /// The size text beside the scale bar; "" for the mesh's "model W x D x H mm"
    /// (pieces laid out apart say each piece's size instead).
    std::string size_text;
};

/// Background colour of the picture (0xRRGGBB); the model never uses it.
inline constexpr uint32_t kPictureBackground = 0xffffff;

/// Draws `mesh` (closed, outward triangles, mm). An empty mesh gives a blank picture.
RgbImage drawMeshPicture(const Mesh& mesh, const MeshPictureOptions& opts = {});

/// True when some downward-facing triangle lies above the mesh's lowest z:
/// the underside is not flat (a mirrored bottom), so it is worth a view.
bool hasRaisedUnderside(const Mesh& mesh);

}  // namespace tsf
