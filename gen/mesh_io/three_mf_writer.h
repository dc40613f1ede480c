// 3MF writer (3MF Core, through lib3mf 1.8.1's C API).
//
// write3mf writes one mesh object (type "model", named opts.title) with one build item
// and no transform, unit millimetre, metadata Title = opts.title and
// Application = "tsf <version>". The package is written to the AtomicFile's
// temporary path and renamed over path only when lib3mf reports success.
//
// Precision: 3MF vertices are float32 in lib3mf 1.x, and lib3mf 1.8.1 prints
// them with 6 decimal places through its own float formatting; positions read
// back agree with the float32 input to within about 1e-6 mm + 2 float32 ulps
// (measured: 3e-5 mm at 300 mm), not bit for bit. Use OFF/OBJ for exact
// positions.
//
// 3MF Core requires every triangle to have three distinct vertex indices and
// lib3mf rejects others; such a mesh is refused with an InputError naming the
// first offending triangle. The writer does not check that the mesh is closed
// or manifold (the spec's MUST for "model" objects): that is the verifier's
// job.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/geometry/mesh_parts.h"
#include "gen/mesh_io/mesh_write_options.h"

namespace tsf {

/// Writes mesh to path atomically as a 3MF package. Throws tsf::InputError
/// for an unusable path or a mesh 3MF cannot hold (no triangles, non-finite
/// or beyond float32, a triangle repeating a vertex, more than 2^32-1
/// vertices or triangles), std::invalid_argument for out-of-range indices, and
/// std::runtime_error carrying lib3mf's message if lib3mf fails.
void write3mf(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts = {});

/// Writes parts (gen/geometry/mesh_parts.h) to path atomically, laid out as
/// opts.parts_layout says:
///   Portable (default): a base material group (3MF Materials extension)
///     with one material per part, named as the part, with its display
///     colour (partDisplayColour); each part a mesh object of its own, named
///     as the part, whose default property is its material; one components
///     object named opts.title holding every part (identity transforms); one
///     build item of it. Every 3MF reader sees one object of parts in their
///     colours. PrusaSlicer loads the parts as objects at their places and
///     its window offers to join them as one object of parts.
///   PrusaSlicer: ONE mesh object (named opts.title) whose triangles are the
///     parts' in the order given, each part's vertices after the previous
///     part's (nothing merged), one build item, and the package part
///     Metadata/Slic3r_PE_model.config (three_mf_volumes.h) naming each
///     part's triangle range as a volume of type ModelPart: how PrusaSlicer
///     stores an object made of parts, loaded as one without a question.
///     Each triangle carries its part's material too.
/// read3mfParts reads either back. Throws as write3mf, for every part, and
/// InputError when parts is empty.
void write3mfParts(const std::vector<MeshPart>& parts, const std::string& path, const MeshWriteOptions& opts = {});

/// sRGB display colour of a part: by its name for tsf's parts (pillars light
/// grey, marks red, legend near black, scale blue), else from a palette by
/// its position; no two parts of one model share a colour.
std::array<uint8_t, 3> partDisplayColour(const std::vector<MeshPart>& parts, size_t index);

}  // namespace tsf
