// MeshWriteOptions: choices shared by the mesh file writers (gen/mesh_io/).
#pragma once

#include <string>

namespace tsf {

struct MeshWriteOptions {
    /// STL only: write the text flavour instead of binary (binary is smaller
    /// and what slicers expect; text is for people and diff tools).
    bool ascii_stl = false;
    /// Name stored in the file: binary STL header, "solid <title>", 3MF
    /// metadata "Title" and object name, OFF/OBJ comment. Control characters
    /// are replaced by spaces.
    std::string title = "tsf";
    /// 3MF of parts only (write3mfParts): how the parts are laid out.
    enum class PartsLayout {
        /// Each part a 3MF core mesh object with its own base material and
        /// display colour (Materials extension), joined as the components of
        /// one object, the one build item: every 3MF reader sees the parts.
        Portable,
        /// One mesh object whose triangles are the parts' in turn, named as
        /// volumes in PrusaSlicer's own config: PrusaSlicer loads one object
        /// of parts without asking; other readers see one part.
        PrusaSlicer,
    };
    PartsLayout parts_layout = PartsLayout::Portable;
};

}  // namespace tsf
