#include "gen/mesh_io/text_lines.h"

#include <ostream>

#include "gen/mesh_io/number_text.h"

namespace tsf::mesh_io {
namespace {
// Text accumulated before each write() call.
constexpr size_t kChunkChars = size_t{1} << 18;
}  // namespace

void appendPositionLine(std::string& text, const char* prefix, const Vec3& p) {
    text += prefix;
    appendShortest(text, p.x);
    text += ' ';
    appendShortest(text, p.y);
    text += ' ';
    appendShortest(text, p.z);
    text += '\n';
}

void appendTriangleLine(std::string& text, const char* prefix, const std::array<uint32_t, 3>& tri, uint32_t base) {
    text += prefix;
    for (int k = 0; k < 3; ++k) {
        if (k > 0) text += ' ';
        text += std::to_string(uint64_t{tri[k]} + base);
    }
    text += '\n';
}

void flushText(std::string& text, std::ostream& out, bool force) {
    if (!force && text.size() < kChunkChars) return;
    out.write(text.data(), static_cast<std::streamsize>(text.size()));
    text.clear();
}

}  // namespace tsf::mesh_io
