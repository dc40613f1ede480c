#include "gen/model/features/foot_contacts.h"

#include "gen/field/hex_grid.h"
#include "gen/model/features/top_shapes.h"

namespace tsf {

bool footCanTouch(const Scene& s, int32_t k) {
    if (k < 0) return false;
    if (!s.drawn_by_face.empty() && s.drawn_by_face[size_t(k)]) return false;
    for (int e = 0; e < kHexCorners; ++e)
        if (cornerTop(s, size_t(k), e) < s.floor_units) return false;
    return true;
}

int32_t keptAtCentre(const Scene& s, int64_t i, int64_t j) {
    if ((j - 2) % 3 != 0) return -1;
    const int64_t row = int64_t(s.grid.rows) - 1 - (j - 2) / 3;
    if (row < 0 || row >= s.grid.rows) return -1;
    const int64_t twice = i - 1 - (row % 2);
    if (twice < 0 || twice % 2 != 0) return -1;
    return s.keptAt(int32_t(twice / 2), int32_t(row));
}

}  // namespace tsf
