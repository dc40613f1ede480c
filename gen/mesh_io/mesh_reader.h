// readMesh: read a triangle mesh from STL, 3MF, OFF or OBJ.
//
// The format follows the extension (case-insensitive: .stl, .3mf, .off,
// .obj); a file with another or no extension is recognised by its content
// (ZIP signature -> 3MF, "OFF" header -> OFF, STL size/"solid" rules) or
// refused. STL binary vs ASCII is always decided by content
// (gen/mesh_io/stl_reader.h).
//
// Vertices are merged only when their coordinates are exactly equal as
// doubles (-0 equals +0); there is no tolerance, so two vertices 1e-9 mm
// apart stay two. Nothing is repaired or dropped silently: triangles that
// repeat a vertex are kept and counted, unused vertices kept and noted, and
// everything of the kind is in the MeshReadReport.
//
// Units: mm (3MF packages in other units are converted; STL/OFF/OBJ carry no
// unit and are taken as mm). Winding is kept as in the file.
//
// Bad files throw tsf::InputError with the path and the line and column (text
// formats) or the byte offset (binary STL) and what was expected: empty file,
// truncated binary STL, triangle count mismatch, NaN or infinite coordinates,
// index out of range, malformed syntax. Arbitrary bytes never crash a reader.
// Per-format readers: stl_reader.h, three_mf_reader.h, off_reader.h,
// obj_reader.h.
#pragma once

#include <string>

#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/geometry/mesh_parts.h"
#include "gen/mesh_io/mesh_read_report.h"

namespace tsf {

/// Reads the mesh at path; fills *report when report is not null.
Mesh readMesh(const std::string& path, MeshReadReport* report = nullptr);

/// Reads the file at path as parts: a 3MF package gives one part per mesh
/// object it prints (gen/mesh_io/three_mf_reader.h read3mfParts); every
/// other format one part named "model". Errors as readMesh.
std::vector<MeshPart> readMeshParts(const std::string& path, MeshReadReport* report = nullptr);

/// The report as lines for people: "format: ...", counts, then the notes.
std::string describeReadReport(const MeshReadReport& report);

}  // namespace tsf
