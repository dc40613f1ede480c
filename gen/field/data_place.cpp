#include "gen/field/data_place.h"

namespace tsf {

CellPlace pixelCells(const PixelPlace& p) {
    CellPlace c;
    if (!p.known) return c;
    c.known = true;
    c.x0 = p.x_west + 0.5 * p.dx;
    c.x_per_col = p.dx;
    c.y0 = p.y_north - 0.5 * p.dy;
    c.y_per_row = -p.dy;
    c.axes = p.axes;
    return c;
}

}  // namespace tsf
