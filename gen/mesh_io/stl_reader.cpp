#include "gen/mesh_io/stl_reader.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

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

constexpr size_t kHeaderBytes = 80;
constexpr size_t kCountOffset = 80;
constexpr size_t kFirstFacetOffset = 84;
constexpr size_t kFacetBytes = 50;
constexpr size_t kFacetCornersOffset = 12;  // after the normal
constexpr size_t kFacetAttributeOffset = 48;
// Bytes looked at to decide whether a "solid" file is really text.
constexpr size_t kTextSniffBytes = 1024;
// A closed mesh has about half as many vertices as triangles.
constexpr size_t kVerticesPerTriangleEstimateDivisor = 2;

uint32_t getUint32(const unsigned char* p) {
    return uint32_t{p[0]} | uint32_t{p[1]} << 8 | uint32_t{p[2]} << 16 | uint32_t{p[3]} << 24;
}

float getFloat(const unsigned char* p) { return std::bit_cast<float>(getUint32(p)); }

bool startsWithSolid(std::string_view bytes) {
    size_t i = 0;
    while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n')) ++i;
    return bytes.size() - i >= 5 && equalsIgnoringCase(bytes.substr(i, 5), "solid");
}

bool looksLikeText(std::string_view bytes) {
    const size_t n = std::min(bytes.size(), kTextSniffBytes);
    for (size_t i = 0; i < n; ++i) {
        const auto byte = static_cast<unsigned char>(bytes[i]);
        const bool control = byte < 0x20 && byte != '\t' && byte != '\n' && byte != '\r' && byte != '\f' && byte != '\v';
        if (control || byte == 0x7F) return false;
    }
    return true;
}

const char* axisName(int k) { return k == 0 ? "x" : k == 1 ? "y" : "z"; }

Mesh parseBinary(std::string_view bytes, const std::string& name, uint32_t count, MeshReadReport* report) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    MeshAssembler assembler(name, count / kVerticesPerTriangleEstimateDivisor + 3, count);
    size_t with_attributes = 0;
    // The corners of a few facets at a time go to the vertex index together
    // (MeshAssembler::addVertices), in file order: the same indices.
    constexpr uint32_t kFacetsPerBatch = 16;
    Vec3 corners[3 * kFacetsPerBatch];
    uint32_t index[3 * kFacetsPerBatch];
    for (uint32_t first = 0; first < count; first += kFacetsPerBatch) {
        const uint32_t facets = std::min(kFacetsPerBatch, count - first);
        for (uint32_t f = 0; f < facets; ++f) {
            const uint32_t t = first + f;
            const size_t facet = kFirstFacetOffset + size_t{t} * kFacetBytes;
            for (int c = 0; c < 3; ++c) {
                double xyz[3];
                for (int k = 0; k < 3; ++k) {
                    const size_t offset = facet + kFacetCornersOffset + 12 * c + 4 * k;
                    const float value = getFloat(data + offset);
                    if (!std::isfinite(value)) {
                        throw InputError(name, 0, 0,
                                         "byte " + std::to_string(offset) + ": triangle " + std::to_string(t) + " corner " +
                                             std::to_string(c) + " " + axisName(k) + " is " +
                                             (std::isnan(value) ? "NaN" : "infinite") + "; a finite coordinate is expected");
                    }
                    xyz[k] = value;
                }
                corners[3 * f + uint32_t(c)] = {xyz[0], xyz[1], xyz[2]};
            }
            if (data[facet + kFacetAttributeOffset] != 0 || data[facet + kFacetAttributeOffset + 1] != 0) ++with_attributes;
        }
        assembler.addVertices(corners, 3 * size_t{facets}, index);
        for (uint32_t f = 0; f < facets; ++f) assembler.addTriangle(index[3 * f], index[3 * f + 1], index[3 * f + 2]);
    }
    if (with_attributes > 0) {
        assembler.note(std::to_string(with_attributes) +
                       " facets have nonzero attribute bytes (some programs store colour there); ignored");
    }
    return assembler.finish("stl-binary", report);
}

// Reads the next token and checks it is the keyword.
void expectKeyword(TextScanner& scanner, std::string_view keyword, const char* context) {
    std::string_view token;
    if (!scanner.next(token)) {
        scanner.failHere("unexpected end of file: '" + std::string(keyword) + "' expected " + context);
    }
    if (!equalsIgnoringCase(token, keyword)) {
        scanner.fail("'" + std::string(keyword) + "' expected " + context + ", found " + quoteForMessage(token));
    }
}

double expectNumber(TextScanner& scanner, const char* what, bool finite) {
    std::string_view token;
    if (!scanner.next(token)) scanner.failHere(std::string("unexpected end of file: ") + what + " expected");
    return finite ? finiteNumber(scanner, token, what) : anyNumber(scanner, token, what);
}

Mesh parseAscii(std::string_view bytes, const std::string& name, MeshReadReport* report) {
    TextScanner scanner(bytes, name);
    // An ASCII facet is at least ~100 bytes; only sizes the first allocation.
    constexpr size_t kMinAsciiFacetBytes = 100;
    const size_t estimate = bytes.size() / kMinAsciiFacetBytes;
    MeshAssembler assembler(name, estimate / kVerticesPerTriangleEstimateDivisor + 3, estimate);
    std::string_view token;
    size_t solids = 0;
    while (scanner.next(token)) {
        if (!equalsIgnoringCase(token, "solid")) {
            scanner.fail(std::string(solids == 0 ? "'solid'" : "'solid' or the end of the file") + " expected, found " +
                         quoteForMessage(token));
        }
        ++solids;
        scanner.skipLine();  // the rest of the line is the solid's name
        for (;;) {
            if (!scanner.next(token)) {
                scanner.failHere("unexpected end of file: 'facet' or 'endsolid' expected (is the file truncated?)");
            }
            if (equalsIgnoringCase(token, "endsolid")) {
                scanner.skipLine();
                break;
            }
            if (!equalsIgnoringCase(token, "facet")) {
                scanner.fail("'facet' or 'endsolid' expected, found " + quoteForMessage(token));
            }
            expectKeyword(scanner, "normal", "after 'facet'");
            for (int k = 0; k < 3; ++k) expectNumber(scanner, "a facet normal component", /*finite=*/false);
            expectKeyword(scanner, "outer", "after the facet normal");
            expectKeyword(scanner, "loop", "after 'outer'");
            uint32_t corner_index[3];
            for (int c = 0; c < 3; ++c) {
                expectKeyword(scanner, "vertex", c == 0 ? "after 'outer loop'" : "(a facet has 3 vertices)");
                double xyz[3];
                for (int k = 0; k < 3; ++k) xyz[k] = expectNumber(scanner, "a vertex coordinate", /*finite=*/true);
                corner_index[c] = assembler.addVertex({xyz[0], xyz[1], xyz[2]});
            }
            expectKeyword(scanner, "endloop", "after 3 vertices (only triangles are supported)");
            expectKeyword(scanner, "endfacet", "after 'endloop'");
            assembler.addTriangle(corner_index[0], corner_index[1], corner_index[2]);
        }
    }
    if (solids > 1) assembler.note("the file holds " + std::to_string(solids) + " solids; read as one mesh");
    return assembler.finish("stl-ascii", report);
}

}  // namespace

Mesh parseStl(std::string_view bytes, const std::string& name, MeshReadReport* report) {
    if (bytes.empty()) {
        throw InputError(name, 0, 0, "empty file: an STL file starts with an 80-byte header or with 'solid'");
    }
    const bool solid = startsWithSolid(bytes);
    if (bytes.size() >= kFirstFacetOffset) {
        const uint32_t count = getUint32(reinterpret_cast<const unsigned char*>(bytes.data()) + kCountOffset);
        const uint64_t expected = kFirstFacetOffset + uint64_t{count} * kFacetBytes;
        if (bytes.size() == expected) return parseBinary(bytes, name, count, report);
        if (solid && looksLikeText(bytes)) return parseAscii(bytes, name, report);
        const bool truncated = bytes.size() < expected;
        throw InputError(name, 0, 0,
                         "byte " + std::to_string(kCountOffset) + ": binary STL triangle count " + std::to_string(count) +
                             " needs a file of " + std::to_string(expected) + " bytes (84 + 50 per triangle), but it has " +
                             std::to_string(bytes.size()) +
                             (truncated ? " (truncated, or the count is wrong)"
                                        : " (extra data, or the count is wrong)") +
                             (solid ? "; it starts with 'solid' but is not ASCII STL either" : ""));
    }
    if (solid && looksLikeText(bytes)) return parseAscii(bytes, name, report);
    throw InputError(name, 0, 0,
                     "file of " + std::to_string(bytes.size()) +
                         " bytes is too short for binary STL (at least 84: an " + std::to_string(kHeaderBytes) +
                         "-byte header and a 4-byte triangle count) and is not ASCII STL (which starts with 'solid')");
}

Mesh readStl(const std::string& path, MeshReadReport* report) {
    const std::string bytes = readFileBytes(path, kMaxMeshFileBytes);
    return parseStl(bytes, path, report);
}

}  // namespace tsf
