#include "gen/mesh_io/stl_writer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cmath>
#include <atomic>
#include <cstdint>
#include <condition_variable>
#include <limits>
#include <mutex>
#include <system_error>
#include <ostream>
#include <thread>
#include <vector>

#include "gen/util/error.h"
#include "gen/util/atomic_file.h"
#include "gen/mesh_io/mesh_write_checks.h"
#include "gen/mesh_io/number_text.h"

namespace tsf {

using mesh_io::appendShortest;
using mesh_io::checkMeshForWriting;
using mesh_io::printableTitle;
namespace {

constexpr size_t kHeaderBytes = 80;
constexpr size_t kFacetBytes = 50;
// Facets serialised per write() call: large enough to amortise the call,
// small enough to stay in cache (~200 KB).
constexpr size_t kFacetsPerChunk = 4096;
// Binary STL: facets converted per block (~800 KB), two blocks a converting
// thread in flight.
constexpr size_t kBinaryFacetsPerBlock = 16384;

struct FloatTriangle {
    std::array<std::array<float, 3>, 3> corners;
    std::array<float, 3> normal;
};

FloatTriangle floatTriangle(const Mesh& mesh, const std::array<uint32_t, 3>& tri) {
    FloatTriangle out{};
    for (int k = 0; k < 3; ++k) {
        const Vec3& p = mesh.positions[tri[k]];
        out.corners[k] = {static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)};
    }
    // Normal of the corners as stored, computed in double.
    const auto& a = out.corners[0];
    const auto& b = out.corners[1];
    const auto& c = out.corners[2];
    const double ux = double(b[0]) - a[0], uy = double(b[1]) - a[1], uz = double(b[2]) - a[2];
    const double vx = double(c[0]) - a[0], vy = double(c[1]) - a[1], vz = double(c[2]) - a[2];
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const double length = std::sqrt(nx * nx + ny * ny + nz * nz);
    if (length > 0 && std::isfinite(length)) {
        out.normal = {static_cast<float>(nx / length), static_cast<float>(ny / length), static_cast<float>(nz / length)};
    } else {
        out.normal = {0.0f, 0.0f, 0.0f};
    }
    return out;
}

void putUint32(unsigned char* dst, uint32_t value) {
    dst[0] = static_cast<unsigned char>(value);
    dst[1] = static_cast<unsigned char>(value >> 8);
    dst[2] = static_cast<unsigned char>(value >> 16);
    dst[3] = static_cast<unsigned char>(value >> 24);
}

void putFloat(unsigned char* dst, float value) { putUint32(dst, std::bit_cast<uint32_t>(value)); }

bool startsWithSolid(const std::string& text) {
    size_t i = 0;
    while (i < text.size() && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    static const char kSolid[] = "solid";
    for (size_t k = 0; k < 5; ++k) {
        if (i + k >= text.size() || std::tolower(static_cast<unsigned char>(text[i + k])) != kSolid[k]) return false;
    }
    return true;
}

std::array<char, kHeaderBytes> binaryHeader(const std::string& title) {
    static const std::string kUnits = " UNITS=mm";
    std::string text = printableTitle(title);
    if (startsWithSolid(text)) text = "binary " + text;
    text.resize(std::min(text.size(), kHeaderBytes - kUnits.size()));
    text += kUnits;
    std::array<char, kHeaderBytes> header{};
    std::copy(text.begin(), text.end(), header.begin());
    return header;
}

}  // namespace

void writeStlBinary(const Mesh& mesh, std::ostream& out, const std::string& title) {
    const auto header = binaryHeader(title);
    out.write(header.data(), header.size());
    unsigned char count[4];
    putUint32(count, static_cast<uint32_t>(mesh.triangles.size()));
    out.write(reinterpret_cast<const char*>(count), sizeof count);

    // Facets [first, first + count) as STL bytes into dst.
    auto convert = [&mesh](size_t first, size_t count, unsigned char* dst) {
        for (size_t t = first; t < first + count; ++t, dst += kFacetBytes) {
            const FloatTriangle f = floatTriangle(mesh, mesh.triangles[t]);
            for (int k = 0; k < 3; ++k) putFloat(dst + 4 * k, f.normal[k]);
            for (int c = 0; c < 3; ++c)
                for (int k = 0; k < 3; ++k) putFloat(dst + 12 + 12 * c + 4 * k, f.corners[c][k]);
            dst[48] = 0;
            dst[49] = 0;
        }
    };
    const size_t total = mesh.triangles.size();
    const size_t blocks = (total + kBinaryFacetsPerBlock - 1) / kBinaryFacetsPerBlock;
    const auto facetsIn = [&](size_t block) { return std::min(kBinaryFacetsPerBlock, total - block * kBinaryFacetsPerBlock); };
    const auto writeBlock = [&](size_t block, const std::vector<unsigned char>& bytes) {
        out.write(reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(facetsIn(block) * kFacetBytes));
    };
    // The blocks are converted on threads of their own, each taking the next
    // block as it finishes one, while this thread writes the converted blocks
    // in order: the conversion (a square root and three divisions a facet)
    // is the slower half and runs on every core, the kernel's copy beside
    // it. A block goes into slot block % slots, free once the block `slots`
    // before it is written. Each facet's bytes depend on that facet alone, so
    // the file is the same whatever thread converted it.
    const unsigned wanted = blocks <= 2 ? 0u : std::clamp(std::thread::hardware_concurrency(), 1u, 8u);
    const size_t slots = 2 * size_t(std::max(wanted, 1u));
    std::vector<std::vector<unsigned char>> slot(std::min(slots, std::max<size_t>(blocks, 1)),
                                                 std::vector<unsigned char>(std::min(total, kBinaryFacetsPerBlock) * kFacetBytes));
    std::vector<size_t> converted(slot.size(), SIZE_MAX);  // the block each slot holds, converted
    size_t written = 0;                                    // blocks written
    bool done = false;  // the writer is done (the stream failed, or it left): nothing more to convert
    std::atomic<size_t> next{0};
    std::mutex m;
    std::condition_variable changed;
    auto convertBlocks = [&] {
        for (size_t b; (b = next.fetch_add(1)) < blocks;) {
            {
                std::unique_lock lock(m);
                changed.wait(lock, [&] { return done || b < written + slot.size(); });
                if (done) return;
            }
            convert(b * kBinaryFacetsPerBlock, facetsIn(b), slot[b % slot.size()].data());
            {
                const std::lock_guard lock(m);
                converted[b % slot.size()] = b;
            }
            changed.notify_all();
        }
    };
    std::vector<std::thread> converters;
    converters.reserve(wanted);
    try {
        while (converters.size() < wanted) converters.emplace_back(convertBlocks);
    } catch (const std::system_error&) {
        // No more threads to be had: the ones started convert every block
        // (none: this thread converts each before writing it).
    }
    // However the writing ends, the converters are told and joined.
    struct Joiner {
        std::vector<std::thread>& threads;
        std::mutex& m;
        std::condition_variable& changed;
        bool& done;
        ~Joiner() {
            {
                const std::lock_guard lock(m);
                done = true;
            }
            changed.notify_all();
            for (std::thread& t : threads) t.join();
        }
    } joiner{converters, m, changed, done};
    if (converters.empty()) {
        for (size_t b = 0; b < blocks && out; ++b) {
            convert(b * kBinaryFacetsPerBlock, facetsIn(b), slot[0].data());
            writeBlock(b, slot[0]);
        }
        return;
    }
    for (size_t b = 0; b < blocks; ++b) {
        {
            std::unique_lock lock(m);
            changed.wait(lock, [&] { return converted[b % slot.size()] == b; });
        }
        writeBlock(b, slot[b % slot.size()]);
        if (!out) return;  // the joiner stops the converters
        {
            const std::lock_guard lock(m);
            written = b + 1;
        }
        changed.notify_all();
    }
}

void writeStlAscii(const Mesh& mesh, std::ostream& out, const std::string& title) {
    const std::string name = printableTitle(title);
    std::string text = "solid " + name + "\n";
    auto appendTriple = [&text](const std::array<float, 3>& v) {
        for (int k = 0; k < 3; ++k) {
            text += ' ';
            appendShortest(text, v[k]);
        }
        text += '\n';
    };
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        const FloatTriangle f = floatTriangle(mesh, mesh.triangles[t]);
        text += "  facet normal";
        appendTriple(f.normal);
        text += "    outer loop\n";
        for (int c = 0; c < 3; ++c) {
            text += "      vertex";
            appendTriple(f.corners[c]);
        }
        text += "    endloop\n  endfacet\n";
        if (text.size() > kFacetsPerChunk * kFacetBytes) {
            out.write(text.data(), static_cast<std::streamsize>(text.size()));
            text.clear();
        }
    }
    text += "endsolid " + name + "\n";
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
}

void writeStl(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts) {
    checkMeshForWriting(mesh, path, /*float32_format=*/true);
    if (!opts.ascii_stl && mesh.triangles.size() > std::numeric_limits<uint32_t>::max()) {
        throw InputError(path, 0, 0, "cannot write: binary STL holds at most 4294967295 triangles");
    }
    writeFileAtomically(path, [&](std::ostream& out) {
        if (opts.ascii_stl) {
            writeStlAscii(mesh, out, opts.title);
        } else {
            writeStlBinary(mesh, out, opts.title);
        }
    });
}

}  // namespace tsf
