#include "gen/model/joint_walls.h"

#include <algorithm>

#include "gen/field/hex_grid.h"
#include "gen/model/features/top_shapes.h"

namespace tsf {

JointWall jointWall(const Scene& s, const WallContact& w) {
    const size_t k = size_t(w.kept);
    const int e0 = w.edge, e1 = (w.edge + 1) % kHexCorners;
    const int64_t lo = std::max({w.bottom_units, cornerBottom(s, k, e0), cornerBottom(s, k, e1)});
    const int64_t hi = std::min({w.top_units, cornerTop(s, k, e0), cornerTop(s, k, e1)});
    return {s.point(hexCorner(s.grid, s.col[k], s.row[k], e0), 0), s.point(hexCorner(s.grid, s.col[k], s.row[k], e1), 0),
            s.zMm(lo), s.zMm(hi)};
}

}  // namespace tsf
