// Shared by the libFuzzer targets in this folder (built with clang only:
// cmake -DTSF_BUILD_FUZZERS=ON, see docs/limits.md "Fuzzing").
//
// A parser passes an input when it returns or throws tsf::InputError (a
// clear message for bad input). Anything else is a finding: a crash, a
// sanitizer report, another exception type (libFuzzer reports it as an
// uncaught exception), or a result that breaks its contract (checked by the
// target and ended with __builtin_trap()).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "gen/util/error.h"
#include "gen/geometry/mesh.h"
#include "gen/field/raster.h"

namespace tsf::fuzz {

inline std::string_view bytesOf(const uint8_t* data, size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

/// Runs parse(), treating tsf::InputError as a clean rejection.
template <typename Parse>
void acceptOrInputError(Parse&& parse) {
    try {
        parse();
    } catch (const InputError&) {
    }
}

inline void requireValidRaster(const Raster& r) {
    if (r.cols <= 0 || r.rows <= 0 || r.values.size() != size_t(r.cols) * size_t(r.rows)) __builtin_trap();
    for (double v : r.values)
        if (std::isinf(v)) __builtin_trap();  // NaN is no data; an infinity is never a value
}

inline void requireValidMesh(const Mesh& m) {
    for (const auto& t : m.triangles)
        for (uint32_t v : t)
            if (v >= m.vertexCount()) __builtin_trap();
    for (const Vec3& p : m.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) __builtin_trap();
}

}  // namespace tsf::fuzz
