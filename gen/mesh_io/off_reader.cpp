#include "gen/mesh_io/off_reader.h"

#include <algorithm>
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
using mesh_io::equalsIgnoringCase;
namespace {

// Shortest vertex line "0 0 0\n" and face line "3 0 1 2\n": a declared count
// cannot exceed what the file's size can hold, so allocations stay bounded by
// the file even when its counts are absurd.
constexpr size_t kMinVertexBytes = 6;
constexpr size_t kMinFaceBytes = 8;

std::string_view nextToken(TextScanner& scanner, const char* expected) {
    std::string_view token;
    if (!scanner.next(token)) scanner.failHere(std::string("unexpected end of file: ") + expected + " expected");
    return token;
}

// As nextToken, naming item `index` of `count` ("vertex 3 of 8") on failure.
std::string_view nextItemToken(TextScanner& scanner, const char* item, int64_t index, int64_t count) {
    std::string_view token;
    if (!scanner.next(token)) {
        scanner.failHere("unexpected end of file: " + std::string(item) + " " + std::to_string(index) + " of " +
                         std::to_string(count) + " expected (do the counts in the header match the data?)");
    }
    return token;
}

}  // namespace

Mesh parseOff(std::string_view text, const std::string& name, MeshReadReport* report) {
    if (text.empty()) throw InputError(name, 0, 0, "empty file: an OFF file starts with 'OFF'");
    TextScanner scanner(text, name, '#');

    std::string_view header;
    if (!scanner.next(header)) scanner.failHere("'OFF' expected, the file has only comments or blank lines");
    const bool plain = header == "OFF";
    if (!plain && header != "COFF" && header != "NOFF" && header != "CNOFF") {
        if (header.size() > 3 && header.substr(header.size() - 3) == "OFF") {
            scanner.fail("unsupported OFF variant " + quoteForMessage(header) + "; OFF, COFF, NOFF or CNOFF expected");
        }
        scanner.fail("'OFF' expected at the start of the file, found " + quoteForMessage(header));
    }

    std::string_view token = nextToken(scanner, "the vertex count");
    if (equalsIgnoringCase(token, "BINARY")) scanner.fail("binary OFF is not supported; write OFF as text");
    const int64_t vertex_count = integer(scanner, token, "the vertex count");
    const int64_t face_count = integer(scanner, nextToken(scanner, "the face count"), "the face count");
    if (vertex_count < 0 || vertex_count >= int64_t{std::numeric_limits<uint32_t>::max()}) {
        scanner.fail("vertex count " + std::to_string(vertex_count) + " is out of range");
    }
    if (face_count < 0) scanner.fail("face count " + std::to_string(face_count) + " is negative");
    if (scanner.nextOnLine(token)) integer(scanner, token, "the edge count");  // optional, unused

    const size_t vertex_reserve = std::min<size_t>(static_cast<size_t>(vertex_count), text.size() / kMinVertexBytes);
    const size_t face_reserve = std::min<size_t>(static_cast<size_t>(face_count), text.size() / kMinFaceBytes);
    MeshAssembler assembler(name, vertex_reserve, face_reserve);
    std::vector<uint32_t> remap;
    remap.reserve(vertex_reserve);

    bool extra_vertex_values = false;
    for (int64_t v = 0; v < vertex_count; ++v) {
        double xyz[3];
        for (int k = 0; k < 3; ++k) {
            xyz[k] = finiteNumber(scanner, nextItemToken(scanner, "vertex", v, vertex_count), "a vertex coordinate");
        }
        remap.push_back(assembler.addVertex({xyz[0], xyz[1], xyz[2]}));
        if (scanner.nextOnLine(token)) extra_vertex_values = true;
        scanner.skipLine();
    }
    if (extra_vertex_values && plain) assembler.note("ignored values after x y z on vertex lines (colours or normals?)");

    size_t polygons = 0;
    for (int64_t f = 0; f < face_count; ++f) {
        const int64_t corners =
            integer(scanner, nextItemToken(scanner, "face", f, face_count), "the corner count of a face");
        if (corners < 3) {
            scanner.fail("face " + std::to_string(f) + " has " + std::to_string(corners) + " corners; at least 3 expected");
        }
        uint32_t first = 0, previous = 0;
        for (int64_t c = 0; c < corners; ++c) {
            const int64_t index = integer(scanner, nextItemToken(scanner, "corner", c, corners), "a vertex index");
            if (index < 0 || index >= vertex_count) {
                scanner.fail("vertex index " + std::to_string(index) + " is out of range: the file has " +
                             std::to_string(vertex_count) + " vertices (0 to " + std::to_string(vertex_count - 1) + ")");
            }
            const uint32_t vertex = remap[static_cast<size_t>(index)];
            if (c == 0) first = vertex;
            if (c >= 2) assembler.addTriangle(first, previous, vertex);
            previous = vertex;
        }
        if (corners > 3) ++polygons;
        scanner.skipLine();  // the rest of the line may hold a colour
    }
    if (polygons > 0) {
        assembler.note(std::to_string(polygons) + " faces with more than 3 corners were split into triangles fanning "
                                                  "from their first corner (right for convex faces)");
    }
    if (scanner.next(token)) {
        scanner.fail("end of file expected after " + std::to_string(face_count) + " faces, found " + quoteForMessage(token) +
                     " (do the counts in the header match the data?)");
    }
    return assembler.finish("off", report);
}

Mesh readOff(const std::string& path, MeshReadReport* report) {
    const std::string bytes = readFileBytes(path, kMaxMeshFileBytes);
    return parseOff(bytes, path, report);
}

}  // namespace tsf
