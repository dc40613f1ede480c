#include "gen/mesh_io/three_mf_writer.h"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <sys/types.h>
#include <limits>
#include <vector>

#include "Model/COM/NMR_DLLInterfaces.h"
#include "gen/util/error.h"
#include "gen/util/atomic_file.h"
#include "gen/util/file_stamp.h"
#include "gen/mesh_io/lib3mf_handle.h"
#include "gen/mesh_io/mesh_write_checks.h"
#include "gen/mesh_io/three_mf_volumes.h"

#ifndef TSF_VERSION
#define TSF_VERSION "unknown"
#endif

namespace tsf {

using mesh_io::Lib3mfHandle;
using mesh_io::lib3mfErrorText;
using mesh_io::checkLib3mf;
using mesh_io::checkMeshForWriting;
using mesh_io::printableTitle;
using mesh_io::ThreeMfVolume;
using mesh_io::kSlicerModelConfigPath;
using mesh_io::kSlicerModelConfigRelationship;
using mesh_io::slicerModelConfig;
namespace {

void check3mfLimits(const Mesh& mesh, const std::string& path) {
    const size_t dword_max = std::numeric_limits<DWORD>::max();
    if (mesh.positions.size() > dword_max || mesh.triangles.size() > dword_max) {
        throw InputError(path, 0, 0, "cannot write: lib3mf holds at most 4294967295 vertices and triangles");
    }
    if (mesh.triangles.empty()) {
        throw InputError(path, 0, 0, "cannot write 3MF: the mesh has no triangles (a 3MF object needs at least one)");
    }
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        if (tri[0] == tri[1] || tri[1] == tri[2] || tri[0] == tri[2]) {
            throw InputError(path, 0, 0,
                             "cannot write 3MF: triangle " + std::to_string(t) + " uses vertex " +
                                 std::to_string(tri[0] == tri[1] || tri[0] == tri[2] ? tri[0] : tri[1]) +
                                 " twice; 3MF requires three distinct vertices per triangle");
        }
    }
}

// A UUID made from a hash of what the object holds (lib3mf gives each
// object a random one): the same model is written as the same bytes, so a
// run's files carry the same stamp each time (key_stamp.h). RFC 4122
// layout, version 8 (made by the application).
std::string contentUuid(uint64_t a, uint64_t b) {
    char text[40];
    a = (a & ~uint64_t(0xF000)) | 0x8000;                  // version 8 in the third group
    b = (b & ~(uint64_t(0xC) << 60)) | (uint64_t(0x8) << 60);  // variant 10
    std::snprintf(text, sizeof text, "%08x-%04x-%04x-%04x-%012llx", unsigned(a >> 32), unsigned((a >> 16) & 0xFFFF),
                  unsigned(a & 0xFFFF), unsigned(b >> 48), static_cast<unsigned long long>(b & 0xFFFFFFFFFFFFull));
    return text;
}

void setContentUuid(Lib3mfHandle& object, uint64_t hash, const std::string& name) {
    const uint64_t second = xxh3_64(name.data(), name.size(), hash);
    checkLib3mf(NMR::lib3mf_object_setuuidutf8(object.get(), contentUuid(hash, second).c_str()), object.get(),
                "lib3mf_object_setuuidutf8");
}

// A UUID for something made of `object` (its build item, its component):
// a hash of the object's own UUID and of `what`.
std::string derivedUuid(Lib3mfHandle& object, const std::string& what) {
    BOOL has = 0;
    char uuid[64] = {};
    checkLib3mf(NMR::lib3mf_object_getuuidutf8(object.get(), &has, uuid), object.get(), "lib3mf_object_getuuidutf8");
    const std::string key = std::string(uuid) + "/" + what;
    const uint64_t a = xxh3_64(key.data(), key.size());
    return contentUuid(a, xxh3_64(key.data(), key.size(), a));
}

// Adds mesh as a mesh object named name; object receives it.
void addMeshObject(Lib3mfHandle& model, const Mesh& mesh, const std::string& name, Lib3mfHandle& object) {
    std::vector<NMR::MODELMESHVERTEX> vertices(mesh.positions.size());
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3& p = mesh.positions[i];
        vertices[i].m_fPosition[0] = static_cast<float>(p.x);
        vertices[i].m_fPosition[1] = static_cast<float>(p.y);
        vertices[i].m_fPosition[2] = static_cast<float>(p.z);
    }
    std::vector<NMR::MODELMESHTRIANGLE> triangles(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) triangles[t].m_nIndices[k] = mesh.triangles[t][k];
    }
    checkLib3mf(NMR::lib3mf_model_addmeshobject(model.get(), object.out()), model.get(), "lib3mf_model_addmeshobject");
    checkLib3mf(NMR::lib3mf_object_setnameutf8(object.get(), name.c_str()), object.get(), "lib3mf_object_setnameutf8");
    checkLib3mf(NMR::lib3mf_meshobject_setgeometry(object.get(), vertices.data(), static_cast<DWORD>(vertices.size()),
                                                   triangles.data(), static_cast<DWORD>(triangles.size())),
                object.get(), "lib3mf_meshobject_setgeometry");
    const uint64_t hash = xxh3_64(triangles.data(), triangles.size() * sizeof(triangles[0]),
                                  xxh3_64(vertices.data(), vertices.size() * sizeof(vertices[0])));
    setContentUuid(object, hash, name);
}

// A model in millimetres with the Title and Application metadata.
void startModel(Lib3mfHandle& model, const std::string& title) {
    const std::string application = std::string("tsf ") + TSF_VERSION;
    checkLib3mf(NMR::lib3mf_createmodel(model.out()), nullptr, "lib3mf_createmodel");
    checkLib3mf(NMR::lib3mf_model_setunit(model.get(), NMR::MODELUNIT_MILLIMETER), model.get(), "lib3mf_model_setunit");
    checkLib3mf(NMR::lib3mf_model_addmetadatautf8(model.get(), "Title", title.c_str()), model.get(),
                "lib3mf_model_addmetadatautf8(Title)");
    checkLib3mf(NMR::lib3mf_model_addmetadatautf8(model.get(), "Application", application.c_str()), model.get(),
                "lib3mf_model_addmetadatautf8(Application)");
}

// Where lib3mf's package goes: the temporary file, written by us. lib3mf's
// own file writer, when a write fails (a full disk, a file-size limit),
// throws again from a destructor while it unwinds, which ends the process
// (std::terminate). Here a failed write or seek is only recorded and lib3mf
// is told it succeeded, so it finishes normally; the first failure is then
// reported as an OutputError with the OS reason. (A callback's 0 is
// lib3mf's success.)
struct PackageSink {
    std::FILE* file = nullptr;
    int error_number = 0;  ///< errno of the first failed write or seek (0: none)
};

// lib3mf's write callback: a chunk of the package. Returns 0, lib3mf's "done".
uint32_t writePackageChunk(unsigned char* data, uint32_t bytes, void* user) {
    auto* sink = static_cast<PackageSink*>(user);
    if (sink->error_number == 0 && bytes > 0 && std::fwrite(data, 1, bytes, sink->file) != bytes)
        sink->error_number = errno != 0 ? errno : EIO;
    return 0;  // lib3mf's "no error"
}

// lib3mf's seek callback: back to a ZIP header to fill in its sizes.
uint32_t seekPackage(uint64_t position, void* user) {
    auto* sink = static_cast<PackageSink*>(user);
    if (sink->error_number == 0 && ::fseeko(sink->file, off_t(position), SEEK_SET) != 0)
        sink->error_number = errno != 0 ? errno : EIO;
    return 0;  // lib3mf's "no error"
}

// One build item of object, no transform; the package to file's temporary path, then renamed.
void finishModel(Lib3mfHandle& model, Lib3mfHandle& object, AtomicFile& file, const std::string& path) {
    Lib3mfHandle build_item;
    checkLib3mf(NMR::lib3mf_model_addbuilditem(model.get(), object.get(), nullptr, build_item.out()), model.get(),
                "lib3mf_model_addbuilditem");
    checkLib3mf(NMR::lib3mf_builditem_setuuidutf8(build_item.get(), derivedUuid(object, "build item").c_str()),
                build_item.get(), "lib3mf_builditem_setuuidutf8");
    checkLib3mf(NMR::lib3mf_model_setbuilduuidutf8(model.get(), derivedUuid(object, "build").c_str()), model.get(),
                "lib3mf_model_setbuilduuidutf8");
    Lib3mfHandle writer;
    checkLib3mf(NMR::lib3mf_model_querywriter(model.get(), "3mf", writer.out()), model.get(), "lib3mf_model_querywriter");
    PackageSink sink;
    sink.file = std::fopen(file.tempPath().c_str(), "wb");
    if (!sink.file)
        throw OutputError(path, "cannot open '" + file.tempPath() + "' for writing: " + std::strerror(errno));
    errno = 0;
    const int result = NMR::lib3mf_writer_writetocallback(writer.get(), reinterpret_cast<void*>(&writePackageChunk),
                                                          reinterpret_cast<void*>(&seekPackage), &sink);
    if (std::fflush(sink.file) != 0 && sink.error_number == 0) sink.error_number = errno != 0 ? errno : EIO;
    if (std::fclose(sink.file) != 0 && sink.error_number == 0) sink.error_number = errno != 0 ? errno : EIO;
    if (sink.error_number != 0) throw OutputError(path, "writing failed: " + std::string(std::strerror(sink.error_number)));
    if (result != LIB3MF_OK) throw OutputError(path, "writing failed: " + lib3mfErrorText(result, writer.get()));
    file.commit();
}

}  // namespace

void write3mf(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts) {
    checkMeshForWriting(mesh, path, /*float32_format=*/true);
    check3mfLimits(mesh, path);
    AtomicFile file(path);  // fails early on an unusable folder
    const std::string title = printableTitle(opts.title);
    Lib3mfHandle model;
    startModel(model, title);
    Lib3mfHandle object;
    addMeshObject(model, mesh, title, object);
    finishModel(model, object, file, path);
}

std::array<uint8_t, 3> partDisplayColour(const std::vector<MeshPart>& parts, size_t index) {
    struct Named {
        const char* name;
        std::array<uint8_t, 3> rgb;
    };
    // tsf's parts: the body light grey (the data's colour), the orientation
    // marks red, the braille dots near black, the scale blue.
    static constexpr Named kNamed[] = {{"pillars", {0xE6, 0xE6, 0xE6}},
                                       {"marks", {0xD6, 0x27, 0x28}},
                                       {"legend", {0x1F, 0x1F, 0x1F}},
                                       {"scale", {0x1F, 0x77, 0xB4}}};
    // Any other part: the first of these no part of the model has yet.
    static constexpr std::array<uint8_t, 3> kPalette[] = {{0x2C, 0xA0, 0x2C}, {0xFF, 0x7F, 0x0E}, {0x94, 0x67, 0xBD},
                                                          {0x8C, 0x56, 0x4B}, {0xE3, 0x77, 0xC2}, {0x17, 0xBE, 0xCF},
                                                          {0xBC, 0xBD, 0x22}, {0x7F, 0x7F, 0x7F}};
    auto named = [&](size_t k) -> const std::array<uint8_t, 3>* {
        for (const Named& n : kNamed)
            if (parts[k].name == n.name) return &n.rgb;
        return nullptr;
    };
    std::vector<std::array<uint8_t, 3>> taken;
    for (size_t k = 0; k < index; ++k) taken.push_back(partDisplayColour(parts, k));
    if (const auto* rgb = named(index); rgb && std::find(taken.begin(), taken.end(), *rgb) == taken.end()) return *rgb;
    for (const auto& rgb : kPalette) {
        bool used = std::find(taken.begin(), taken.end(), rgb) != taken.end();
        for (size_t k = index + 1; k < parts.size() && !used; ++k) used = named(k) && *named(k) == rgb;
        if (!used) return rgb;
    }
    // More parts than colours: a grey of its own.
    const uint8_t g = uint8_t(0x40 + (index * 37) % 0x80);
    return {g, g, g};
}

namespace {

/// A base material group with one material per part (its name and display
/// colour); the group's resource id.
DWORD addPartMaterials(Lib3mfHandle& model, const std::vector<MeshPart>& parts, Lib3mfHandle& group) {
    checkLib3mf(NMR::lib3mf_model_addbasematerialgroup(model.get(), group.out()), model.get(),
                "lib3mf_model_addbasematerialgroup");
    for (size_t k = 0; k < parts.size(); ++k) {
        const auto rgb = partDisplayColour(parts, k);
        DWORD index = 0;
        checkLib3mf(NMR::lib3mf_basematerial_addmaterialutf8(group.get(), printableTitle(parts[k].name).c_str(), rgb[0],
                                                              rgb[1], rgb[2], &index),
                    group.get(), "lib3mf_basematerial_addmaterialutf8");
        // Opaque (lib3mf 1.8 leaves the alpha of a new material at 0: invisible).
        checkLib3mf(NMR::lib3mf_basematerial_setdisplaycolorrgba(group.get(), index, rgb[0], rgb[1], rgb[2], 0xFF),
                    group.get(), "lib3mf_basematerial_setdisplaycolorrgba");
    }
    DWORD id = 0;
    checkLib3mf(NMR::lib3mf_basematerial_getresourceid(group.get(), &id), group.get(), "lib3mf_basematerial_getresourceid");
    return id;
}

/// The object's default property: material `index` of `group`.
void setDefaultMaterial(Lib3mfHandle& object, DWORD group, DWORD index) {
    Lib3mfHandle property;
    checkLib3mf(NMR::lib3mf_object_createdefaultpropertyhandler(object.get(), property.out()), object.get(),
                "lib3mf_object_createdefaultpropertyhandler");
    checkLib3mf(NMR::lib3mf_defaultpropertyhandler_setbasematerial(property.get(), group, index), property.get(),
                "lib3mf_defaultpropertyhandler_setbasematerial");
}

/// What both parts layouts start with: the model (title, metadata) and the
/// parts' materials.
struct PartsModel {
    std::string title;
    Lib3mfHandle model, group;
    DWORD group_id = 0;
    PartsModel(const std::vector<MeshPart>& parts, const MeshWriteOptions& opts) : title(printableTitle(opts.title)) {
        startModel(model, title);
        group_id = addPartMaterials(model, parts, group);
    }
};

void checkParts(const std::vector<MeshPart>& parts, const std::string& path) {
    if (parts.empty()) throw InputError(path, 0, 0, "cannot write 3MF: no parts");
    for (const MeshPart& p : parts) {
        checkMeshForWriting(p.mesh, path, /*float32_format=*/true);
        check3mfLimits(p.mesh, path);
    }
}

void writePortableParts(const std::vector<MeshPart>& parts, const std::string& path, const MeshWriteOptions& opts) {
    AtomicFile file(path);
    PartsModel pm(parts, opts);
    Lib3mfHandle& model = pm.model;
    const std::string& title = pm.title;
    std::vector<Lib3mfHandle> objects(parts.size());
    for (size_t k = 0; k < parts.size(); ++k) {
        addMeshObject(model, parts[k].mesh, printableTitle(parts[k].name), objects[k]);
        setDefaultMaterial(objects[k], pm.group_id, DWORD(k));
    }
    Lib3mfHandle assembly;
    checkLib3mf(NMR::lib3mf_model_addcomponentsobject(model.get(), assembly.out()), model.get(),
                "lib3mf_model_addcomponentsobject");
    checkLib3mf(NMR::lib3mf_object_setnameutf8(assembly.get(), title.c_str()), assembly.get(),
                "lib3mf_object_setnameutf8");
    uint64_t parts_hash = 0;
    for (const MeshPart& p : parts)
        parts_hash = xxh3_64(p.mesh.triangles.data(), p.mesh.triangles.size() * sizeof(p.mesh.triangles[0]),
                             xxh3_64(p.mesh.positions.data(), p.mesh.positions.size() * sizeof(p.mesh.positions[0]), parts_hash));
    setContentUuid(assembly, parts_hash, title);
    for (Lib3mfHandle& object : objects) {
        Lib3mfHandle component;
        checkLib3mf(NMR::lib3mf_componentsobject_addcomponent(assembly.get(), object.get(), nullptr, component.out()),
                    assembly.get(), "lib3mf_componentsobject_addcomponent");
        checkLib3mf(NMR::lib3mf_component_setuuidutf8(component.get(), derivedUuid(object, "component").c_str()),
                    component.get(), "lib3mf_component_setuuidutf8");
    }
    finishModel(model, assembly, file, path);
}

void writePrusaSlicerParts(const std::vector<MeshPart>& parts, const std::string& path, const MeshWriteOptions& opts) {
    const Mesh joined = joinParts(parts);
    check3mfLimits(joined, path);
    AtomicFile file(path);
    PartsModel pm(parts, opts);
    Lib3mfHandle& model = pm.model;
    const std::string& title = pm.title;
    Lib3mfHandle object;
    addMeshObject(model, joined, title, object);
    // Each triangle its part's material (other readers then see the colours);
    // 3MF wants the object's default too: the first part's.
    setDefaultMaterial(object, pm.group_id, 0);
    std::vector<DWORD> groups(joined.triangles.size(), pm.group_id), indices;
    indices.reserve(joined.triangles.size());
    for (size_t k = 0; k < parts.size(); ++k) indices.insert(indices.end(), parts[k].mesh.triangles.size(), DWORD(k));
    Lib3mfHandle triangle_properties;
    checkLib3mf(NMR::lib3mf_meshobject_createpropertyhandler(object.get(), triangle_properties.out()), object.get(),
                "lib3mf_meshobject_createpropertyhandler");
    checkLib3mf(NMR::lib3mf_propertyhandler_setbasematerialarray(triangle_properties.get(), groups.data(), indices.data()),
                triangle_properties.get(), "lib3mf_propertyhandler_setbasematerialarray");
    DWORD id = 0;
    checkLib3mf(NMR::lib3mf_resource_getresourceid(object.get(), &id), object.get(), "lib3mf_resource_getresourceid");
    std::vector<ThreeMfVolume> volumes;
    size_t first = 0;
    for (const MeshPart& p : parts) {
        volumes.push_back({printableTitle(p.name), first, first + p.mesh.triangles.size() - 1});
        first += p.mesh.triangles.size();
    }
    std::string config = slicerModelConfig(id, title, volumes);
    Lib3mfHandle attachment;
    std::string uri = kSlicerModelConfigPath, type = kSlicerModelConfigRelationship;
    checkLib3mf(NMR::lib3mf_model_addattachmentutf8(model.get(), uri.data(), type.data(), attachment.out()), model.get(),
                "lib3mf_model_addattachmentutf8");
    checkLib3mf(NMR::lib3mf_attachment_readfrombuffer(attachment.get(), reinterpret_cast<BYTE*>(config.data()),
                                                      config.size()),
                attachment.get(), "lib3mf_attachment_readfrombuffer");
    finishModel(model, object, file, path);
}

}  // namespace

void write3mfParts(const std::vector<MeshPart>& parts, const std::string& path, const MeshWriteOptions& opts) {
    checkParts(parts, path);
    if (opts.parts_layout == MeshWriteOptions::PartsLayout::PrusaSlicer) writePrusaSlicerParts(parts, path, opts);
    else writePortableParts(parts, path, opts);
}

}  // namespace tsf
