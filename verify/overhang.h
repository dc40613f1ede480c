// Overhang: the downward-facing surface a printer would print in the air.
//
// A triangle overhangs when it faces down more than kMaxOverhangDeg from the
// vertical (outward normal n_z < -sin(kMaxOverhangDeg)), unless it lies on
// the bed (all three corners within kBedToleranceMm of the mesh's lowest z).
// FDM printers build 45 degrees without supports (each layer rests on half of
// the one below); steeper overhangs need supports, which on a tsf model sit
// on the surface a reader feels. The mesh must be closed and consistently
// oriented; an inside-out mesh (negative volume) is read the other way round.
// Units: millimetres, the mesh as it lies on the bed (z up).
#pragma once

#include <cstddef>

#include "gen/geometry/mesh.h"

namespace tsf {

/// Largest printable overhang from the vertical, degrees.
inline constexpr double kMaxOverhangDeg = 45.0;
/// A corner this close to the lowest z lies on the bed (the 1 um grid).
inline constexpr double kBedToleranceMm = 0.001;

struct OverhangFigures {
    double area_mm2 = 0;        ///< area of the overhanging triangles
    double max_height_mm = 0;   ///< highest lowest corner of an overhanging triangle above the bed
    double downward_area_mm2 = 0;  ///< every downward-facing triangle not on the bed (any angle)
    size_t triangles = 0;       ///< overhanging triangles
    Vec3 worst_mm{0, 0, 0};     ///< centroid of the highest overhanging triangle
};

/// Measures the overhang of `mesh` as it lies (z = its lowest point is the bed).
OverhangFigures measureOverhang(const Mesh& mesh);

}  // namespace tsf
