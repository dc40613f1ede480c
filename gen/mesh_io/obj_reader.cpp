#include "gen/mesh_io/obj_reader.h"

#include <array>
#include <limits>
#include <vector>

#include "gen/util/error.h"
#include "gen/mesh_io/mesh_assembler.h"
#include "gen/mesh_io/mesh_tokens.h"
#include "gen/util/file_bytes.h"

namespace tsf {

using mesh_io::MeshAssembler;
using mesh_io::quoteForMessage;
using mesh_io::anyNumber;
using mesh_io::finiteNumber;
using mesh_io::integer;
namespace {

// Statements that carry nothing tsf uses.
constexpr std::array<std::string_view, 12> kIgnored = {"vt", "vn", "g", "o", "s", "mg", "usemtl", "mtllib",
                                                       "usemap", "maplib", "shadow_obj", "trace_obj"};
// Elements and free-form geometry tsf cannot use; ignored with a note.
constexpr std::array<std::string_view, 23> kIgnoredWithNote = {
    "p",     "l",    "vp",    "cstype", "deg",   "bmat",  "step",     "curv",     "curv2", "surf",  "parm",  "trim",
    "hole",  "scrv", "sp",    "end",    "con",   "bevel", "c_interp", "d_interp", "lod",   "ctech", "stech"};

template <size_t N>
bool isOneOf(std::string_view token, const std::array<std::string_view, N>& list) {
    for (std::string_view k : list) {
        if (token == k) return true;
    }
    return false;
}

// A corner reference whose index was beyond the vertices read so far; OBJ
// allows vertices after the faces using them, so it is checked at the end.
struct ForwardReference {
    int64_t index_1based;
    int line;
    int column;
};

// Parses "v", "v/vt", "v//vn" or "v/vt/vn" and returns v (not yet resolved).
int64_t cornerVertex(const TextScanner& scanner, std::string_view token) {
    const size_t slash = token.find('/');
    const int64_t v = integer(scanner, token.substr(0, slash), "a vertex index");
    if (slash != std::string_view::npos) {
        std::string_view rest = token.substr(slash + 1);
        const size_t second = rest.find('/');
        const std::string_view vt = rest.substr(0, second);
        if (!vt.empty()) integer(scanner, vt, "a texture index after '/'");
        if (second != std::string_view::npos) {
            const std::string_view vn = rest.substr(second + 1);
            if (vn.empty() || vn.find('/') != std::string_view::npos) {
                scanner.fail("a face corner 'v', 'v/vt', 'v//vn' or 'v/vt/vn' expected, found " + quoteForMessage(token));
            }
            integer(scanner, vn, "a normal index after '/'");
        }
    }
    return v;
}

}  // namespace

Mesh parseObj(std::string_view text, const std::string& name, MeshReadReport* report) {
    if (text.empty()) throw InputError(name, 0, 0, "empty file: an OBJ file has 'v' and 'f' lines");
    TextScanner scanner(text, name, '#');

    std::vector<Vec3> positions;
    std::vector<std::array<uint32_t, 3>> triangles;  // 0-based indices into positions
    std::vector<ForwardReference> forward;
    size_t polygons = 0;
    size_t ignored_with_note = 0;
    std::string first_ignored;
    std::vector<uint32_t> corners;  // of the current face, reused

    std::string_view token;
    do {
        if (!scanner.nextOnLine(token)) continue;
        if (token == "v") {
            double xyz[3];
            for (int k = 0; k < 3; ++k) {
                std::string_view value;
                if (!scanner.nextOnLine(value)) scanner.failHere("'v' needs 3 coordinates: x y z");
                xyz[k] = finiteNumber(scanner, value, "a vertex coordinate");
            }
            positions.push_back({xyz[0], xyz[1], xyz[2]});
        } else if (token == "f") {
            const int face_line = scanner.line();
            corners.clear();
            std::string_view corner;
            while (scanner.nextOnLine(corner)) {
                const int64_t v = cornerVertex(scanner, corner);
                const auto count = static_cast<int64_t>(positions.size());
                int64_t index = 0;
                if (v == 0) scanner.fail("vertex index 0 is invalid: OBJ indices start at 1 (or count back from -1)");
                if (v < 0) {
                    index = count + v;
                    if (index < 0) {
                        scanner.fail("relative vertex index " + std::to_string(v) + " reaches before the first vertex (" +
                                     std::to_string(count) + " vertices so far)");
                    }
                } else {
                    index = v - 1;
                    if (index >= int64_t{std::numeric_limits<uint32_t>::max()}) {
                        scanner.fail("vertex index " + std::to_string(v) + " is out of range");
                    }
                    if (index >= count) forward.push_back({v, scanner.line(), scanner.column()});
                }
                corners.push_back(static_cast<uint32_t>(index));
            }
            if (corners.size() < 3) {
                throw InputError(name, face_line, 0,
                                 "a face needs at least 3 corners, found " + std::to_string(corners.size()));
            }
            for (size_t c = 2; c < corners.size(); ++c) triangles.push_back({corners[0], corners[c - 1], corners[c]});
            if (corners.size() > 3) ++polygons;
        } else if (isOneOf(token, kIgnored)) {
            // nothing tsf uses
        } else if (isOneOf(token, kIgnoredWithNote)) {
            if (ignored_with_note++ == 0) {
                first_ignored = "'" + std::string(token) + "' at line " + std::to_string(scanner.line());
            }
        } else {
            scanner.fail("unknown OBJ statement " + quoteForMessage(token) + "; 'v' or 'f' expected");
        }
    } while (scanner.skipLine());

    for (const ForwardReference& ref : forward) {
        if (ref.index_1based > static_cast<int64_t>(positions.size())) {
            throw InputError(name, ref.line, ref.column,
                             "vertex index " + std::to_string(ref.index_1based) + " is out of range: the file has " +
                                 std::to_string(positions.size()) + " vertices (1 to " +
                                 std::to_string(positions.size()) + ")");
        }
    }

    MeshAssembler assembler(name, positions.size(), triangles.size());
    std::vector<uint32_t> remap(positions.size());
    for (size_t i = 0; i < positions.size(); ++i) remap[i] = assembler.addVertex(positions[i]);
    for (const auto& t : triangles) assembler.addTriangle(remap[t[0]], remap[t[1]], remap[t[2]]);
    if (polygons > 0) {
        assembler.note(std::to_string(polygons) + " faces with more than 3 corners were split into triangles fanning "
                                                  "from their first corner (right for convex faces)");
    }
    if (ignored_with_note > 0) {
        assembler.note(std::to_string(ignored_with_note) +
                       " point, line or free-form statements were ignored (first: " + first_ignored + ")");
    }
    return assembler.finish("obj", report);
}

Mesh readObj(const std::string& path, MeshReadReport* report) {
    const std::string bytes = readFileBytes(path, kMaxMeshFileBytes);
    return parseObj(bytes, path, report);
}

}  // namespace tsf
