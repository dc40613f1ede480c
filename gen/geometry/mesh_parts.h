// MeshPart: one body of a model written as several parts (a 3MF object with a
// part per feature, so a slicer can give each its own colour or material).
//
// Every part is a closed, outward-facing, 2-manifold mesh of its own (mm,
// model frame: x east, y north, z up); parts may touch each other (share a
// face or a region of one) and never overlap in volume. Their union is the
// model. The first part is the body the others stand on (the pillars); a
// later part may be several pieces (the braille dots, each on the plate).
#pragma once

#include <string>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf {

struct MeshPart {
    std::string name;  ///< what the part is: "pillars", "marks", "legend", ... (3MF object name)
    Mesh mesh;
};

/// The parts' meshes side by side in one Mesh (positions appended in order,
/// indices shifted; nothing merged): what a printer prints, not a 2-manifold.
Mesh joinParts(const std::vector<MeshPart>& parts);

}  // namespace tsf
