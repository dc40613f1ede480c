// Shared helpers for the OpenSCAD engine tests: the two engines (or why one
// is missing), scratch folders, small fields.
//
// A missing engine makes a test SKIP with the reason. Set
// TSF_REQUIRE_SCAD_ENGINES=1 (the CI machine has both) to make it FAIL instead.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "gen/hex_field.h"
#include "verify/render/openscad_runner.h"
#include "verify/render/wasm_engine.h"
#include "gen/scene.h"

namespace tsf::test {

struct EngineOrReason {
    std::unique_ptr<ScadEngine> engine;
    std::string missing;  ///< why there is no engine
};

inline const EngineOrReason& nativeEngine() {
    static const EngineOrReason e = [] {
        EngineOrReason r;
        try {
            r.engine = makeOpenScadEngine();
        } catch (const ScadEngineMissing& x) {
            r.missing = x.what();
        }
        return r;
    }();
    return e;
}

inline const EngineOrReason& wasmEngine() {
    static const EngineOrReason e = [] {
        EngineOrReason r;
        try {
            r.engine = makeWasmOpenScadEngine();
        } catch (const ScadEngineMissing& x) {
            r.missing = x.what();
        }
        return r;
    }();
    return e;
}

inline bool enginesRequired() {
    const char* v = std::getenv("TSF_REQUIRE_SCAD_ENGINES");
    return v && *v && std::string(v) != "0";
}

/// Use as: TSF_NEED_ENGINE(nativeEngine()); skips (or fails when required) without it.
#define TSF_NEED_ENGINE(e)                                                                                  \
    do {                                                                                                    \
        if (!(e).engine) {                                                                                  \
            if (::tsf::test::enginesRequired()) FAIL() << "engine required but missing: " << (e).missing; \
            GTEST_SKIP() << "engine not installed: " << (e).missing;                                        \
        }                                                                                                   \
    } while (0)

/// A fresh scratch folder for one test.
inline std::filesystem::path scratchDir(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(TSF_TEST_SCRATCH) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline void writeText(const std::filesystem::path& path, const std::string& text) {
    std::ofstream(path, std::ios::binary) << text;
}

inline std::string readText(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

/// Rows listed north to south, as in a file; NaN = no data.
inline HexField fieldFromRows(const std::vector<std::vector<double>>& rows) {
    HexField f;
    f.grid.rows = int32_t(rows.size());
    f.grid.cols = rows.empty() ? 0 : int32_t(rows[0].size());
    for (const auto& r : rows) f.values.insert(f.values.end(), r.begin(), r.end());
    f.source = "test";
    return f;
}

/// A small uneven field with one no-data cell inside and a low corner (hull culling cuts it).
inline HexField smallTerrain() {
    return fieldFromRows({
        {0.0, 1.0, 2.5, 3.0, 1.5},
        {1.0, 4.0, NAN, 2.0, 0.5},
        {2.0, 3.5, 5.0, 4.5, 1.0},
        {0.5, 2.0, 1.0, 3.0, 2.0},
    });
}

inline SceneParams smallParams(Bottom bottom) {
    SceneParams p;
    p.pitch_mm = 5.0;
    p.max_height_mm = 12.0;
    p.base_mm = 2.0;
    p.z_snap_mm = 0.01;
    p.bottom = bottom;
    p.cull = Cull::Hull;
    return p;
}

}  // namespace tsf::test
