#include "gen/mesh_io/three_mf_writer.h"

#include <limits>
#include <vector>

#include "Model/COM/NMR_DLLInterfaces.h"
#include "gen/util/error.h"
#include "gen/util/atomic_file.h"
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

// One build item of object, no transform; the package to file's temporary path, then renamed.
void finishModel(Lib3mfHandle& model, Lib3mfHandle& object, AtomicFile& file, const std::string& path) {
    Lib3mfHandle build_item;
    checkLib3mf(NMR::lib3mf_model_addbuilditem(model.get(), object.get(), nullptr, build_item.out()), model.get(),
                "lib3mf_model_addbuilditem");
    Lib3mfHandle writer;
    checkLib3mf(NMR::lib3mf_model_querywriter(model.get(), "3mf", writer.out()), model.get(), "lib3mf_model_querywriter");
    const int result = NMR::lib3mf_writer_writetofileutf8(writer.get(), file.tempPath().c_str());
    if (result != LIB3MF_OK) {
        throw OutputError(path, "writing failed: " + lib3mfErrorText(result, writer.get()));
    }
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

void write3mfParts(const std::vector<MeshPart>& parts, const std::string& path, const MeshWriteOptions& opts) {
    if (parts.empty()) throw InputError(path, 0, 0, "cannot write 3MF: no parts");
    for (const MeshPart& p : parts) {
        checkMeshForWriting(p.mesh, path, /*float32_format=*/true);
        check3mfLimits(p.mesh, path);
    }
    const Mesh joined = joinParts(parts);
    check3mfLimits(joined, path);
    AtomicFile file(path);
    const std::string title = printableTitle(opts.title);
    Lib3mfHandle model;
    startModel(model, title);
    Lib3mfHandle object;
    addMeshObject(model, joined, title, object);
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

}  // namespace tsf
