// The part of a 3MF package that names an object's volumes: PrusaSlicer's
// Metadata/Slic3r_PE_model.config. Internal to gen/mesh_io/.
//
// An object made of parts is stored as one mesh object; this XML names the
// object (by its 3MF resource id) and, per volume, its first and last
// triangle (0-based, inclusive), its name and its type ("ModelPart"):
//   <config><object id="1" instances_count="1">
//     <metadata type="object" key="name" value="..."/>
//     <volume firstid="0" lastid="11">
//       <metadata type="volume" key="name" value="pillars"/>
//       <metadata type="volume" key="volume_type" value="ModelPart"/>
//     </volume> ...
//   </object></config>
// PrusaSlicer finds the file by its name; lib3mf reads it only through a
// relationship, so the writer adds one of type
// kSlicerModelConfigRelationship and the reader asks for it.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

namespace tsf::mesh_io {

inline constexpr const char* kSlicerModelConfigPath = "/Metadata/Slic3r_PE_model.config";
inline constexpr const char* kSlicerModelConfigRelationship = "urn:tsf:3mf:slicer-model-config";

struct ThreeMfVolume {
    std::string name;
    size_t first_triangle = 0, last_triangle = 0;  ///< inclusive
};

/// The XML above for one object (resource id object_id) named object_name.
std::string slicerModelConfig(unsigned object_id, const std::string& object_name, const std::vector<ThreeMfVolume>& volumes);

/// The volumes of every object in such an XML, by object id. Unreadable
/// parts of the text are skipped (the caller then sees fewer volumes).
std::map<unsigned, std::vector<ThreeMfVolume>> parseSlicerModelConfig(std::string_view xml);

}  // namespace tsf::mesh_io
