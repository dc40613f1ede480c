// writeMesh: write a mesh to a file whose format follows its extension.
//
// Extensions (case-insensitive): .stl (binary, or ASCII with
// opts.ascii_stl), .3mf, .off, .obj. Every format is written atomically: a
// temporary file in the target's folder, renamed over the target once
// complete (gen/util/atomic_file.h); on any failure no file appears and an
// existing one is untouched. An empty mesh gives a valid empty STL, OFF or
// OBJ file (it reads back with a "no triangles" note); 3MF refuses it.
//
// Per-format writers, with each format's layout and precision:
// gen/mesh_io/stl_writer.h, three_mf_writer.h, off_writer.h, obj_writer.h.
#pragma once

#include <string>
#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_write_options.h"

namespace tsf {

/// Writes mesh (mm) to path. Throws tsf::InputError for an unknown extension
/// (the message lists the supported ones), an unusable folder, or a mesh the
/// format cannot hold; std::invalid_argument for out-of-range indices;
/// std::runtime_error for I/O or lib3mf failures.
void writeMesh(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts = {});

/// The extensions writeMesh accepts, lower case with the dot: ".stl", ...
const std::vector<std::string>& supportedMeshExtensions();

/// Lower-case extension of path including the dot ("" if none): "A.STL" -> ".stl".
std::string lowerCaseExtension(const std::string& path);

}  // namespace tsf
