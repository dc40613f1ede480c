#include "haptics/field_mapping.h"

#include <algorithm>
#include <cmath>

#include "gen/util/error.h"

namespace tsf::haptics {

FieldMapping mapFieldToWorkspace(int32_t cols, int32_t rows, const WorkspaceBox& box, const FieldLayout& layout) {
    if (cols <= 0 || rows <= 0) throw InputError("the field has no cells to map into the device workspace");
    const Vec3 size = box.max_m - box.min_m;
    if (!(size.x > 0.0 && size.y > 0.0 && size.z > 0.0) || !std::isfinite(size.x + size.y + size.z))
        throw InputError("the device workspace box is empty or not finite");
    const double f = layout.fill_fraction, fl = layout.floor_fraction;
    const double su = layout.surface_fraction, vo = layout.volume_fraction;
    if (!(f > 0.0 && f <= 1.0) || !(fl >= 0.0) || !(su > 0.0) || !(vo >= 0.0) || !(fl + su + vo <= 1.0))
        throw InputError("workspace layout fractions must be positive and the floor, surface and volume "
                         "fractions must add up to at most 1");
    FieldMapping m;
    m.cols = cols;
    m.rows = rows;
    m.cell_m = std::min(f * size.x / cols, f * size.z / rows);
    const double cx = 0.5 * (box.min_m.x + box.max_m.x);
    const double cz = 0.5 * (box.min_m.z + box.max_m.z);
    m.west_x_m = cx - 0.5 * m.cell_m * cols;
    m.south_z_m = cz + 0.5 * m.cell_m * rows;
    m.floor_y_m = box.min_m.y + fl * size.y;
    m.relief_m = su * size.y;
    m.volume_bottom_y_m = m.floor_y_m + m.relief_m;
    m.volume_top_y_m = m.volume_bottom_y_m + vo * size.y;
    return m;
}

FieldMapping mapReliefToWorkspace(int32_t cols, int32_t rows, double sample_mm, double height_mm,
                                  Proportions proportions, const WorkspaceBox& box, const FieldLayout& layout) {
    FieldMapping m = mapFieldToWorkspace(cols, rows, box, layout);
    if (proportions == Proportions::kFitted || !(height_mm > 0.0) || !(sample_mm > 0.0)) return m;
    // Device metres per printed metre: the footprint's fit, unless the
    // relief at that scale would rise above its band.
    const double footprint = m.cell_m / sample_mm;
    const double band = m.relief_m / height_mm;
    const double scale = std::min(footprint, band);
    const double cx = m.west_x_m + 0.5 * m.cell_m * cols;
    const double cz = m.south_z_m - 0.5 * m.cell_m * rows;
    m.cell_m = scale * sample_mm;
    m.west_x_m = cx - 0.5 * m.cell_m * cols;
    m.south_z_m = cz + 0.5 * m.cell_m * rows;
    m.relief_m = scale * height_mm;
    // The volume slab keeps its thickness and sits on the highest surface.
    const double slab = m.volume_top_y_m - m.volume_bottom_y_m;
    m.volume_bottom_y_m = m.floor_y_m + m.relief_m;
    m.volume_top_y_m = m.volume_bottom_y_m + slab;
    return m;
}

MappingScale mappingScale(const FieldMapping& m, double sample_mm, double height_mm) noexcept {
    MappingScale s;
    if (sample_mm > 0.0) s.xy = 1000.0 * m.cell_m / sample_mm;  // m per mm -> mm per mm
    if (height_mm > 0.0) s.z = 1000.0 * m.relief_m / height_mm;
    return s;
}

GridPoint deviceToGrid(const FieldMapping& m, const Vec3& p_m) noexcept {
    return {(p_m.x - m.west_x_m) / m.cell_m - 0.5, (m.south_z_m - p_m.z) / m.cell_m - 0.5};
}

Vec3 gridToDevice(const FieldMapping& m, double gi, double gj, double h) noexcept {
    return {m.west_x_m + (gi + 0.5) * m.cell_m, m.floor_y_m + h * m.relief_m, m.south_z_m - (gj + 0.5) * m.cell_m};
}

bool isOverField(const FieldMapping& m, const Vec3& p_m) noexcept {
    return p_m.x >= m.west_x_m && p_m.x <= m.eastX() && p_m.z <= m.south_z_m && p_m.z >= m.northZ();
}

}  // namespace tsf::haptics
