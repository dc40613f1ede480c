// 3MF reader (3MF Core, through lib3mf 1.8.1's C API).
//
// read3mf reads what a printer would print: every build item, with its transform,
// recursing through components objects (each component's transform applied
// too). All mesh objects end up in one mesh, converted to millimetres from
// the package's unit (micron, cm, inch, foot, metre; noted). Objects whose
// type is not "model" (support, solidsupport, surface, other) are included
// and named in a note; lib3mf's reader warnings become notes.
//
// Coordinates are float32 in the file and transformed in double. Exactly
// equal positions are merged across objects too
// (gen/mesh_io/exact_vertex_index.h); input_vertices counts each instance.
//
// Errors (tsf::InputError naming the file): empty file, anything lib3mf
// cannot read (its message is included: not a ZIP package, malformed XML,
// missing model part, bad index, ...), non-finite coordinates after the
// transform, components nested deeper than 64 levels.
#pragma once

#include <string>
#include <string_view>

#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/geometry/mesh_parts.h"
#include "gen/mesh_io/mesh_read_report.h"

namespace tsf {

/// Reads the 3MF package at path.
Mesh read3mf(const std::string& path, MeshReadReport* report = nullptr);

/// Parses a 3MF package already in memory; name is used in error messages.
Mesh parse3mf(std::string_view bytes, const std::string& name, MeshReadReport* report = nullptr);

/// Reads the package as parts: one MeshPart per mesh object instance that a
/// build item prints (directly or through components, in file order), named
/// after its object ("object <id>" when it has no name), and an object whose
/// volumes Metadata/Slic3r_PE_model.config names (three_mf_volumes.h, as
/// write3mfParts writes it) split into those volumes, each with its own
/// vertices, so parts that touch stay separate bodies (gen/geometry/mesh_parts.h).
/// The report sums the parts' counts; a part's own notes are prefixed with
/// its name. Errors as read3mf.
std::vector<MeshPart> read3mfParts(const std::string& path, MeshReadReport* report = nullptr);
std::vector<MeshPart> parse3mfParts(std::string_view bytes, const std::string& name, MeshReadReport* report = nullptr);

}  // namespace tsf
