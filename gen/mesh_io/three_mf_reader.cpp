#include "gen/mesh_io/three_mf_reader.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <functional>
#include <memory>
#include <vector>

#include "Model/COM/NMR_DLLInterfaces.h"
#include "gen/util/error.h"
#include "gen/mesh_io/lib3mf_handle.h"
#include "gen/mesh_io/mesh_assembler.h"
#include "gen/mesh_io/three_mf_volumes.h"
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

// Where the walker puts the mesh of an object instance: (object id, object name) -> assembler.
using MeshSink = std::function<MeshAssembler&(DWORD, const std::string&)>;

std::string objectName(Lib3mfObject object) {
    ULONG needed = 0;
    if (NMR::lib3mf_object_getnameutf8(object, nullptr, 0, &needed) != LIB3MF_OK || needed == 0) return "";
    std::string text(size_t(needed) + 1, '\0');
    if (NMR::lib3mf_object_getnameutf8(object, text.data(), ULONG(text.size()), &needed) != LIB3MF_OK) return "";
    text.resize(text.find('\0') == std::string::npos ? text.size() : text.find('\0'));
    return text;
}

class PackageWalker {
public:
    // assembler: receives the notes; sink: the meshes.
    PackageWalker(const std::string& name, MeshAssembler& assembler, MeshSink sink)
        : name_(name), assembler_(assembler), sink_(std::move(sink)) {}

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
        MeshAssembler& out = sink_(id, objectName(object));
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
            remap[v] = out.addVertex(p);
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
            out.addTriangle(remap[idx[0]], remap[idx[1]], remap[idx[2]]);
        }
    }

    const std::string& name_;
    MeshAssembler& assembler_;
    MeshSink sink_;
};

uint32_t le32(std::string_view b, size_t at) {
    return uint32_t(uint8_t(b[at])) | uint32_t(uint8_t(b[at + 1])) << 8 | uint32_t(uint8_t(b[at + 2])) << 16 |
           uint32_t(uint8_t(b[at + 3])) << 24;
}
uint16_t le16(std::string_view b, size_t at) { return uint16_t(uint8_t(b[at]) | uint8_t(b[at + 1]) << 8); }
uint64_t le64(std::string_view b, size_t at) { return uint64_t(le32(b, at)) | uint64_t(le32(b, at + 4)) << 32; }

// Deflate expands at most about 1032 to 1; an entry claiming more than that
// of what it occupies in the file is a lie that would make a reader
// allocate the claim (4 GB for a 2.5 KB file).
constexpr uint64_t kMaxDeflateRatio = 1032;
constexpr uint64_t kClaimSlackBytes = 64 * 1024;

// Checks every size the ZIP central directory claims against the bytes the
// entry occupies, before lib3mf reads anything. A package without a
// directory is left to lib3mf (it reports that itself).
void checkZipClaims(std::string_view b, const std::string& name) {
    constexpr uint32_t kEndSignature = 0x06054b50, kEntrySignature = 0x02014b50;
    constexpr size_t kEndBytes = 22, kEntryBytes = 46;
    if (b.size() < kEndBytes) return;
    size_t end = std::string_view::npos;
    const size_t lowest = b.size() > kEndBytes + 65535 ? b.size() - kEndBytes - 65535 : 0;
    for (size_t at = b.size() - kEndBytes + 1; at-- > lowest;)
        if (le32(b, at) == kEndSignature) {
            end = at;
            break;
        }
    if (end == std::string_view::npos) return;
    const auto damaged = [&](const std::string& what) {
        throw InputError(name, 0, 0, "not a readable 3MF package: its ZIP directory " + what);
    };
    uint64_t entries = le16(b, end + 10), dir_size = le32(b, end + 12), dir_at = le32(b, end + 16);
    size_t dir_end = end;
    if (entries == 0xFFFF || dir_size == 0xFFFFFFFF || dir_at == 0xFFFFFFFF) {
        // ZIP64 (lib3mf writes it): the locator just before the end record
        // points at the ZIP64 end record, which holds the real figures.
        constexpr uint32_t kLocatorSignature = 0x07064b50, kEnd64Signature = 0x06064b50;
        if (end < 20 || le32(b, end - 20) != kLocatorSignature) damaged("is damaged (no ZIP64 locator)");
        const uint64_t end64 = le64(b, end - 20 + 8);
        if (end < 20 + 56 || end64 > end - 20 - 56 || le32(b, size_t(end64)) != kEnd64Signature)
            damaged("is damaged (ZIP64 record)");
        entries = le64(b, size_t(end64) + 32);
        dir_size = le64(b, size_t(end64) + 40);
        dir_at = le64(b, size_t(end64) + 48);
        dir_end = size_t(end64);
    }
    if (dir_at > dir_end || dir_size > dir_end - dir_at) damaged("lies outside the file");
    size_t at = size_t(dir_at);
    const size_t end_of_dir = dir_end;
    for (uint64_t k = 0; k < entries; ++k) {
        if (at + kEntryBytes > end_of_dir || le32(b, at) != kEntrySignature) damaged("is damaged");
        const uint16_t method = le16(b, at + 10);
        uint64_t packed = le32(b, at + 20), unpacked = le32(b, at + 24);
        const size_t name_len = le16(b, at + 28), extra_len = le16(b, at + 30), comment_len = le16(b, at + 32);
        if (at + kEntryBytes + name_len + extra_len > end_of_dir) damaged("is damaged");
        if (unpacked == 0xFFFFFFFF || packed == 0xFFFFFFFF) {
            // The ZIP64 extra field (id 1) holds the sizes that are 0xFFFFFFFF, unpacked first.
            size_t x = at + kEntryBytes + name_len;
            const size_t x_end = x + extra_len;
            bool found = false;
            while (x + 4 <= x_end && !found) {
                const uint16_t id = le16(b, x), len = le16(b, x + 2);
                if (x + 4 + len > x_end) break;
                if (id == 1) {
                    size_t f = x + 4;
                    if (unpacked == 0xFFFFFFFF && f + 8 <= x + 4 + len) unpacked = le64(b, f), f += 8;
                    if (packed == 0xFFFFFFFF && f + 8 <= x + 4 + len) packed = le64(b, f);
                    found = true;
                }
                x += 4 + len;
            }
            if (!found) damaged("is damaged (ZIP64 sizes missing)");
        }
        const std::string entry(b.substr(at + kEntryBytes, std::min<size_t>(name_len, 200)));
        if (packed > b.size()) damaged("says \"" + entry + "\" takes " + std::to_string(packed) +
                                       " bytes of a " + std::to_string(b.size()) + "-byte file");
        const uint64_t most = method == 0 ? packed : packed * kMaxDeflateRatio + kClaimSlackBytes;
        if (unpacked > most)
            damaged("claims \"" + entry + "\" unpacks to " + std::to_string(unpacked) + " bytes from " +
                    std::to_string(packed) + " (more than compression can give)");
        at += kEntryBytes + name_len + extra_len + comment_len;
    }
}

// Reads the package and walks its build items: meshes to sink, notes to assembler.
// model_config (may be null): receives the package's Metadata/Slic3r_PE_model.config ("" if none).
// one_assembly (may be null): set when the package's one build item is an
// object made of two or more components (a model written in parts, portably).
void walkPackage(std::string_view bytes, const std::string& name, MeshAssembler& assembler, const MeshSink& sink,
                 std::string* model_config = nullptr, bool* one_assembly = nullptr) {
    if (bytes.empty()) throw InputError(name, 0, 0, "empty file: a 3MF file is a ZIP package");
    checkZipClaims(bytes, name);

    Lib3mfHandle model;
    checkLib3mf(NMR::lib3mf_createmodel(model.out()), nullptr, "lib3mf_createmodel");
    Lib3mfHandle reader;
    checkLib3mf(NMR::lib3mf_model_queryreader(model.get(), "3mf", reader.out()), model.get(), "lib3mf_model_queryreader");
    if (model_config)
        checkLib3mf(NMR::lib3mf_reader_addrelationtoreadutf8(reader.get(), mesh_io::kSlicerModelConfigRelationship),
                    reader.get(), "lib3mf_reader_addrelationtoreadutf8");
    // lib3mf takes a non-const buffer; give it a copy rather than cast.
    std::vector<BYTE> buffer(bytes.begin(), bytes.end());
    const int read_result = NMR::lib3mf_reader_readfrombuffer(reader.get(), buffer.data(), buffer.size());
    if (read_result != LIB3MF_OK) {
        throw InputError(name, 0, 0, "not a readable 3MF package: " + lib3mfErrorText(read_result, reader.get()));
    }
    buffer = {};

    PackageWalker walker(name, assembler, sink);
    if (model_config) {
        model_config->clear();
        Lib3mfHandle attachment;
        std::string uri = mesh_io::kSlicerModelConfigPath;
        if (NMR::lib3mf_model_findattachmentutf8(model.get(), uri.data(), attachment.out()) == LIB3MF_OK && attachment.get()) {
            ULONG64 size = 0;
            walker.check(NMR::lib3mf_attachment_getstreamsize(attachment.get(), &size), attachment.get(), "reading the model config");
            if (size > 0 && size < (ULONG64(64) << 20)) {
                std::string text(size_t(size), '\0');
                walker.check(NMR::lib3mf_attachment_writetobuffer(attachment.get(), reinterpret_cast<BYTE*>(text.data()), size),
                             attachment.get(), "reading the model config");
                *model_config = std::move(text);
            }
        }
    }

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
        if (one_assembly) {
            BOOL components = 0;
            DWORD count = 0;
            walker.check(NMR::lib3mf_object_iscomponentsobject(object.get(), &components), object.get(),
                         "reading a build item's object");
            if (components)
                walker.check(NMR::lib3mf_componentsobject_getcomponentcount(object.get(), &count), object.get(),
                             "reading components");
            *one_assembly = item_count == 1 && components && count >= 2;
        }
        walker.addObject(object.get(), transform, 0);
    }
    if (one_assembly && item_count != 1) *one_assembly = false;
    if (item_count == 0) assembler.note("the package has no build items: nothing would be printed");
}

}  // namespace

Mesh parse3mf(std::string_view bytes, const std::string& name, MeshReadReport* report) {
    MeshAssembler assembler(name, 0, 0);
    walkPackage(bytes, name, assembler, [&assembler](DWORD, const std::string&) -> MeshAssembler& { return assembler; });
    return assembler.finish("3mf", report);
}

namespace {

// The triangles [first, last] of mesh with the vertices they use, renumbered in order of first use.
Mesh triangleRange(const Mesh& mesh, size_t first, size_t last) {
    Mesh out;
    std::vector<uint32_t> index(mesh.positions.size(), UINT32_MAX);
    for (size_t t = first; t <= last; ++t) {
        std::array<uint32_t, 3> tri{};
        for (int k = 0; k < 3; ++k) {
            uint32_t& at = index[mesh.triangles[t][size_t(k)]];
            if (at == UINT32_MAX) {
                at = uint32_t(out.positions.size());
                out.positions.push_back(mesh.positions[mesh.triangles[t][size_t(k)]]);
            }
            tri[size_t(k)] = at;
        }
        out.triangles.push_back(tri);
    }
    return out;
}

}  // namespace

std::vector<MeshPart> parse3mfParts(std::string_view bytes, const std::string& name, MeshReadReport* report) {
    MeshAssembler notes(name, 0, 0);
    std::vector<std::unique_ptr<MeshAssembler>> assemblers;
    std::vector<MeshPart> objects;
    std::vector<DWORD> ids;
    std::string config;
    bool one_assembly = false;
    walkPackage(
        bytes, name, notes,
        [&](DWORD id, const std::string& object_name) -> MeshAssembler& {
            assemblers.push_back(std::make_unique<MeshAssembler>(name, 0, 0));
            objects.push_back({object_name.empty() ? "object " + std::to_string(id) : object_name, {}});
            ids.push_back(id);
            return *assemblers.back();
        },
        &config, &one_assembly);
    const auto volumes = config.empty() ? std::map<unsigned, std::vector<mesh_io::ThreeMfVolume>>()
                                        : mesh_io::parseSlicerModelConfig(config);
    MeshReadReport total;
    total.format = "3mf";
    total.notes = notes.takeNotes();  // the package's notes; the counts are the parts' below
    std::vector<MeshPart> parts;
    for (size_t k = 0; k < objects.size(); ++k) {
        MeshReadReport r;
        Mesh mesh = assemblers[k]->finish("3mf", &r);
        total.input_triangles += r.input_triangles;
        total.input_vertices += r.input_vertices;
        total.merged_vertices += r.merged_vertices;
        total.degenerate_index_triangles += r.degenerate_index_triangles;
        for (const std::string& n : r.notes) total.notes.push_back(objects[k].name + ": " + n);
        // An object whose volumes the slicer config names is split into them; a
        // range beyond the mesh, overlapping or leaving triangles out keeps the object whole.
        const auto v = volumes.find(unsigned(ids[k]));
        bool split = v != volumes.end() && !v->second.empty();
        if (split) {
            size_t next = 0;
            for (const auto& vol : v->second) {
                split = split && vol.first_triangle == next && vol.last_triangle >= vol.first_triangle &&
                        vol.last_triangle < mesh.triangles.size();
                next = vol.last_triangle + 1;
            }
            split = split && next == mesh.triangles.size();
            if (!split) total.notes.push_back(objects[k].name + ": its volumes in the slicer config do not cover its "
                                                                "triangles once each; read as one part");
        }
        if (!split) {
            parts.push_back({objects[k].name, std::move(mesh)});
            continue;
        }
        total.written_in_parts = true;
        for (size_t n = 0; n < v->second.size(); ++n) {
            const auto& vol = v->second[n];
            parts.push_back({vol.name.empty() ? objects[k].name + " volume " + std::to_string(n + 1) : vol.name,
                             triangleRange(mesh, vol.first_triangle, vol.last_triangle)});
        }
    }
    // The components of the one build item are the parts (tsf gen --parts).
    if (one_assembly && parts.size() >= 2) total.written_in_parts = true;
    if (report) *report = std::move(total);
    return parts;
}

std::vector<MeshPart> read3mfParts(const std::string& path, MeshReadReport* report) {
    const std::string bytes = readFileBytes(path, kMaxMeshFileBytes);
    return parse3mfParts(bytes, path, report);
}

Mesh read3mf(const std::string& path, MeshReadReport* report) {
    const std::string bytes = readFileBytes(path, kMaxMeshFileBytes);
    return parse3mf(bytes, path, report);
}

}  // namespace tsf
