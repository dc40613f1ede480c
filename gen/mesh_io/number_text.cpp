#include "gen/mesh_io/number_text.h"

#include <charconv>
#include <system_error>

namespace tsf::mesh_io {
namespace {

// Longest shortest-form double, e.g. "-2.2250738585072014e-308" (24 chars).
constexpr size_t kNumberBufferChars = 32;

template <typename T>
void appendImpl(std::string& out, T value) {
    char buffer[kNumberBufferChars];
    const auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    out.append(buffer, result.ptr);
}

}  // namespace

void appendShortest(std::string& out, float value) { appendImpl(out, value); }
void appendShortest(std::string& out, double value) { appendImpl(out, value); }

void appendPoint(std::string& out, double x, double y, double z) {
    out += "[";
    appendShortest(out, x);
    out += ", ";
    appendShortest(out, y);
    out += ", ";
    appendShortest(out, z);
    out += "]";
}

}  // namespace tsf::mesh_io
