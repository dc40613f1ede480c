// FieldMapping: where the field sits in the device workspace. Fixed for a
// whole session - it is computed once from the device's workspace box and
// the field size, never from where the probe has been (the thesis code grew
// its scale with the largest position seen, so the surface moved under the
// user's hand while they explored).
//
// Layout inside the workspace box (device frame, see frames.h):
//   horizontally  the field's footprint is the largest rectangle with square
//                 cells that fits in fill_fraction of the box's x and z
//                 extents, centred. East edge at +x, north edge at -z.
//   vertically    floor_fraction of the box height is left free at the
//                 bottom; the next surface_fraction holds the relief (height
//                 0 -> floor_y_m, height 1 -> floor_y_m + relief_m); the
//                 next volume_fraction holds the volume-mode slab, which
//                 sits directly on top of the highest possible surface
//                 (thesis section 4.5). The rest is free space above.
// The slab is reserved even when volume mode is off, so switching modes with
// a button never moves the surface.
#pragma once

#include <cstdint>

#include "haptics/frames.h"

namespace tsf::haptics {

struct FieldLayout {
    double fill_fraction = 0.9;      ///< of the box's x and z extents used by the footprint
    double floor_fraction = 0.1;     ///< of the box height below the floor
    double surface_fraction = 0.4;   ///< of the box height for the relief
    double volume_fraction = 0.4;    ///< of the box height for the volume slab
};

struct FieldMapping {
    int32_t cols = 0, rows = 0;  ///< base grid size
    double cell_m = 0.0;         ///< side of one square grid cell in the device
    double west_x_m = 0.0;       ///< device x of the field's west edge (grid gi = -0.5)
    double south_z_m = 0.0;      ///< device z of the field's south edge (grid gj = -0.5)
    double floor_y_m = 0.0;      ///< device y of height 0
    double relief_m = 0.0;       ///< device metres per unit of normalised height
    double volume_bottom_y_m = 0.0;
    double volume_top_y_m = 0.0;

    double eastX() const { return west_x_m + cell_m * cols; }
    double northZ() const { return south_z_m - cell_m * rows; }
};

/// How printed millimetres become device millimetres.
enum class Proportions {
    kFitted,     ///< footprint fitted to the box's floor, relief to its surface band, apart (slopes exaggerated)
    kAsPrinted,  ///< one scale for x, y and z, the largest that fits both: slopes feel as printed
};

/// Validates and computes the mapping. Throws tsf::InputError when the grid
/// is empty, the box is not a proper box, or the fractions are not positive
/// with floor + surface + volume <= 1.
FieldMapping mapFieldToWorkspace(int32_t cols, int32_t rows, const WorkspaceBox& box, const FieldLayout& layout = {});

/// The mapping of a printed relief: samples of sample_mm, heights 0..1
/// meaning 0..height_mm above the floor. kFitted is mapFieldToWorkspace;
/// kAsPrinted takes its footprint scale, or the relief band's if the relief
/// would not fit it (then the footprint shrinks, still centred), for all
/// three axes. Throws as mapFieldToWorkspace; height_mm <= 0 maps as kFitted.
FieldMapping mapReliefToWorkspace(int32_t cols, int32_t rows, double sample_mm, double height_mm,
                                  Proportions proportions, const WorkspaceBox& box, const FieldLayout& layout = {});

/// Device millimetres per printed millimetre of a relief's mapping.
struct MappingScale {
    double xy = 0.0;  ///< across (x, y printed -> x, z device)
    double z = 0.0;   ///< up (printed height -> device y); 0 when height_mm is 0
    /// How much steeper slopes feel than printed (z / xy; 1 = as printed).
    double slopeExaggeration() const { return xy > 0.0 && z > 0.0 ? z / xy : 1.0; }
};
MappingScale mappingScale(const FieldMapping& m, double sample_mm, double height_mm) noexcept;

/// Continuous grid coordinates (height_grid.h) of a device-frame point.
struct GridPoint {
    double gi = 0.0;
    double gj = 0.0;
};
GridPoint deviceToGrid(const FieldMapping& m, const Vec3& p_m) noexcept;

/// Device point above grid coordinates (gi, gj) at normalised height h.
Vec3 gridToDevice(const FieldMapping& m, double gi, double gj, double h) noexcept;

/// True when the device point's x and z lie over the field's footprint.
bool isOverField(const FieldMapping& m, const Vec3& p_m) noexcept;

}  // namespace tsf::haptics
