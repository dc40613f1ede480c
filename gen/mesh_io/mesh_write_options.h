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
};

}  // namespace tsf
