#include "haptics/coverage.h"

#include <vector>

#include "haptics/force_model.h"

namespace tsf::haptics {

Coverage touchedCells(const Scene& scene, const ReliefInfo& relief, const FieldMapping& mapping, const ForceLog& log) {
    Coverage c;
    c.cells = int64_t(scene.keptCount());
    std::vector<uint8_t> touched(scene.keptCount(), 0);
    const double per_pitch = relief.samples_per_pitch;
    for (size_t i = 0; i < log.size(); ++i) {
        const LogRecord& r = log[i];
        if (!(r.flags & kFlagContact)) continue;
        const GridPoint g = deviceToGrid(mapping, r.position_m);
        int32_t col = 0, row = 0;
        if (!hexCellAt(scene.grid, (g.gi - relief.origin_i + 0.5) / per_pitch, (g.gj - relief.origin_j + 0.5) / per_pitch,
                       col, row))
            continue;
        const int32_t k = scene.keptAt(col, row);
        if (k >= 0 && !touched[size_t(k)]) {
            touched[size_t(k)] = 1;
            ++c.touched;
        }
    }
    return c;
}

}  // namespace tsf::haptics
