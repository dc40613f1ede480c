#include "gen/mesh_io/three_mf_reader.h"

#include <cmath>
#include <vector>

#include "Model/COM/NMR_DLLInterfaces.h"
#include "gen/error.h"
#include "gen/mesh_io/lib3mf_handle.h"
#include "gen/mesh_io/mesh_assembler.h"
#include "gen/util/file_bytes.h"

namespace tsf {

using mesh_io::MeshAssembler;
using mesh_io::Lib3mfHandle;
using mesh_io::Lib3mfObject;
using mesh_io::lib3mfErrorText;
using mesh_io::checkLib3mf;
namespace {

// Deeper nesting than any real package uses; stops a reference cycle.
constexpr int kMaxComponentDepth = 64;
// Reader warnings copied into the report; the rest are counted.
constexpr DWORD kMaxWarningNotes = 5;
constexpr ULONG kWarningChars = 512;

// Row-major 3x4 affine map: p' = M[:, 0..2] * p + M[:, 3]. lib3mf's
// MODELTRANSFORM has the same layout (m_fFields[row][column], column 3 =
// translation), which is the transpose of the 3MF XML "m00 m01 ... m32".
struct Affine {
    double m[3][4] = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}};
};

Affine fromLib3mf(const NMR::MODELTRANSFORM& t) {
    Affine a;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) a.m[r][c] = t.m_fFields[r][c];
    }
    return a;
}

// outer(inner(p)).
Affine compose(const Affine& outer, const Affine& inner) {
    Affine out;
    for (int r = 0; r < 3; ++r) {
        for (int c = 0; c < 4; ++c) {
            double sum = c == 3 ? outer.m[r][3] : 0.0;
            for (int k = 0; k < 3; ++k) sum += outer.m[r][k] * inner.m[k][c];
            out.m[r][c] = sum;
        }
    }
    return out;
}

Vec3 apply(const Affine& a, double x, double y, double z) {
    return {a.m[0][0] * x + a.m[0][1] * y + a.m[0][2] * z + a.m[0][3],
            a.m[1][0] * x + a.m[1][1] * y + a.m[1][2] * z + a.m[1][3],
            a.m[2][0] * x + a.m[2][1] * y + a.m[2][2] * z + a.m[2][3]};
}

struct UnitInfo {
    double mm_per_unit;
    const char* name;
};

UnitInfo unitInfo(DWORD unit) {
    switch (unit) {
        case NMR::MODELUNIT_MICROMETER: return {0.001, "micron"};
        case NMR::MODELUNIT_MILLIMETER: return {1.0, "millimeter"};
        case NMR::MODELUNIT_CENTIMETER: return {10.0, "centimeter"};
        case NMR::MODELUNIT_INCH: return {25.4, "inch"};
        case NMR::MODELUNIT_FOOT: return {304.8, "foot"};
        case NMR::MODELUNIT_METER: return {1000.0, "meter"};
        default: return {0.0, "unknown"};
    }
}

const char* objectTypeName(DWORD type) {
    switch (type) {
        case NMR::MODELOBJECTTYPE_MODEL: return "model";
        case NMR::MODELOBJECTTYPE_SUPPORT: return "support";
        case NMR::MODELOBJECTTYPE_SOLIDSUPPORT: return "solidsupport";
        case NMR::MODELOBJECTTYPE_SURFACE: return "surface";
        default: return "other";
    }
}

class PackageWalker {
public:
    PackageWalker(const std::string& name, MeshAssembler& assembler) : name_(name), assembler_(assembler) {}

    // A lib3mf failure after the package was read still means bad content.
    void check(int result, Lib3mfObject object, const char* what) const {
        if (result != LIB3MF_OK) throw InputError(name_, 0, 0, std::string(what) + ": " + lib3mfErrorText(result, object));
    }

    void addObject(Lib3mfObject object, const Affine& transform, int depth) {
        DWORD id = 0;
        check(NMR::lib3mf_resource_getresourceid(object, &id), object, "reading an object id");
        if (depth > kMaxComponentDepth) {
            throw InputError(name_, 0, 0,
                             "object " + std::to_string(id) + ": components nest deeper than " +
                                 std::to_string(kMaxComponentDepth) + " levels (a reference cycle?)");
        }
        DWORD type = 0;
        check(NMR::lib3mf_object_gettype(object, &type), object, "reading an object type");
        BOOL is_mesh = 0;
        check(NMR::lib3mf_object_ismeshobject(object, &is_mesh), object, "reading an object kind");
        if (is_mesh) {
            if (type != NMR::MODELOBJECTTYPE_MODEL) {
                assembler_.note("object " + std::to_string(id) + " has type '" + objectTypeName(type) +
                                "', not 'model'; included");
            }
            addMesh(object, id, transform);
            return;
        }
        BOOL is_components = 0;
        check(NMR::lib3mf_object_iscomponentsobject(object, &is_components), object, "reading an object kind");
        if (!is_components) {
            assembler_.note("object " + std::to_string(id) + " is neither a mesh nor components; ignored");
            return;
        }
        DWORD count = 0;
        check(NMR::lib3mf_componentsobject_getcomponentcount(object, &count), object, "reading components");
        for (DWORD i = 0; i < count; ++i) {
            Lib3mfHandle component;
            check(NMR::lib3mf_componentsobject_getcomponent(object, i, component.out()), object, "reading a component");
            Lib3mfHandle child;
            check(NMR::lib3mf_component_getobjectresource(component.get(), child.out()), component.get(),
                  "reading a component's object");
            BOOL has_transform = 0;
            check(NMR::lib3mf_component_hastransform(component.get(), &has_transform), component.get(),
                  "reading a component transform");
            Affine child_transform = transform;
            if (has_transform) {
                NMR::MODELTRANSFORM t{};
                check(NMR::lib3mf_component_gettransform(component.get(), &t), component.get(),
                      "reading a component transform");
                child_transform = compose(transform, fromLib3mf(t));
            }
            addObject(child.get(), child_transform, depth + 1);
        }
    }

private:
    void addMesh(Lib3mfObject object, DWORD id, const Affine& transform) {
        DWORD vertex_count = 0, triangle_count = 0;
        check(NMR::lib3mf_meshobject_getvertexcount(object, &vertex_count), object, "reading a vertex count");
        check(NMR::lib3mf_meshobject_gettrianglecount(object, &triangle_count), object, "reading a triangle count");
        std::vector<NMR::MODELMESHVERTEX> vertices(vertex_count);
        std::vector<NMR::MODELMESHTRIANGLE> triangles(triangle_count);
        DWORD got = 0;
        if (vertex_count > 0) {
            check(NMR::lib3mf_meshobject_getvertices(object, vertices.data(), vertex_count, &got), object,
                  "reading vertices");
        }
        if (triangle_count > 0) {
            check(NMR::lib3mf_meshobject_gettriangleindices(object, triangles.data(), triangle_count, &got), object,
                  "reading triangles");
        }
        std::vector<uint32_t> remap(vertex_count);
        for (DWORD v = 0; v < vertex_count; ++v) {
            const float* f = vertices[v].m_fPosition;
            const Vec3 p = apply(transform, f[0], f[1], f[2]);
            if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
                throw InputError(name_, 0, 0,
                                 "object " + std::to_string(id) + " vertex " + std::to_string(v) +
                                     " is not a finite position (after its transform)");
            }
            remap[v] = assembler_.addVertex(p);
        }
        for (DWORD t = 0; t < triangle_count; ++t) {
            const DWORD* idx = triangles[t].m_nIndices;
            for (int k = 0; k < 3; ++k) {
                if (idx[k] >= vertex_count) {
                    throw InputError(name_, 0, 0,
                                     "object " + std::to_string(id) + " triangle " + std::to_string(t) +
                                         " refers to vertex " + std::to_string(idx[k]) + " of " +
                                         std::to_string(vertex_count));
                }
            }
            assembler_.addTriangle(remap[idx[0]], remap[idx[1]], remap[idx[2]]);
        }
    }

    const std::string& name_;
    MeshAssembler& assembler_;
};

}  // namespace

Mesh parse3mf(std::string_view bytes, const std::string& name, MeshReadReport* report) {
    if (bytes.empty()) throw InputError(name, 0, 0, "empty file: a 3MF file is a ZIP package");

    Lib3mfHandle model;
    checkLib3mf(NMR::lib3mf_createmodel(model.out()), nullptr, "lib3mf_createmodel");
    Lib3mfHandle reader;
    checkLib3mf(NMR::lib3mf_model_queryreader(model.get(), "3mf", reader.out()), model.get(), "lib3mf_model_queryreader");
    // lib3mf takes a non-const buffer; give it a copy rather than cast.
    std::vector<BYTE> buffer(bytes.begin(), bytes.end());
    const int read_result = NMR::lib3mf_reader_readfrombuffer(reader.get(), buffer.data(), buffer.size());
    if (read_result != LIB3MF_OK) {
        throw InputError(name, 0, 0, "not a readable 3MF package: " + lib3mfErrorText(read_result, reader.get()));
    }
    buffer = {};

    MeshAssembler assembler(name, 0, 0);
    PackageWalker walker(name, assembler);

    DWORD warning_count = 0;
    walker.check(NMR::lib3mf_reader_getwarningcount(reader.get(), &warning_count), reader.get(), "reading warnings");
    for (DWORD i = 0; i < warning_count && i < kMaxWarningNotes; ++i) {
        DWORD code = 0;
        ULONG needed = 0;
        char text[kWarningChars] = {};
        if (NMR::lib3mf_reader_getwarningutf8(reader.get(), i, &code, text, kWarningChars, &needed) == LIB3MF_OK) {
            assembler.note("lib3mf warning: " + std::string(text));
        }
    }
    if (warning_count > kMaxWarningNotes) {
        assembler.note("and " + std::to_string(warning_count - kMaxWarningNotes) + " more lib3mf warnings");
    }

    DWORD unit = 0;
    walker.check(NMR::lib3mf_model_getunit(model.get(), &unit), model.get(), "reading the unit");
    const UnitInfo unit_info = unitInfo(unit);
    if (unit_info.mm_per_unit == 0.0) throw InputError(name, 0, 0, "unknown 3MF unit code " + std::to_string(unit));
    Affine to_mm;
    for (int r = 0; r < 3; ++r) to_mm.m[r][r] = unit_info.mm_per_unit;
    if (unit != NMR::MODELUNIT_MILLIMETER) {
        assembler.note(std::string("the package unit is ") + unit_info.name + "; converted to millimetres");
    }

    Lib3mfHandle items;
    walker.check(NMR::lib3mf_model_getbuilditems(model.get(), items.out()), model.get(), "reading build items");
    size_t item_count = 0;
    for (;;) {
        BOOL has_next = 0;
        walker.check(NMR::lib3mf_builditemiterator_movenext(items.get(), &has_next), items.get(), "reading build items");
        if (!has_next) break;
        ++item_count;
        Lib3mfHandle item;
        walker.check(NMR::lib3mf_builditemiterator_getcurrent(items.get(), item.out()), items.get(), "reading a build item");
        Lib3mfHandle object;
        walker.check(NMR::lib3mf_builditem_getobjectresource(item.get(), object.out()), item.get(),
                     "reading a build item's object");
        BOOL has_transform = 0;
        walker.check(NMR::lib3mf_builditem_hasobjecttransform(item.get(), &has_transform), item.get(),
                     "reading a build item transform");
        Affine transform = to_mm;
        if (has_transform) {
            NMR::MODELTRANSFORM t{};
            walker.check(NMR::lib3mf_builditem_getobjecttransform(item.get(), &t), item.get(),
                         "reading a build item transform");
            transform = compose(to_mm, fromLib3mf(t));
        }
        walker.addObject(object.get(), transform, 0);
    }
    if (item_count == 0) assembler.note("the package has no build items: nothing would be printed");
    return assembler.finish("3mf", report);
}

Mesh read3mf(const std::string& path, MeshReadReport* report) {
    const std::string bytes = readFileBytes(path, kMaxMeshFileBytes);
    return parse3mf(bytes, path, report);
}

}  // namespace tsf
