// Helpers of the OpenSCAD engine tests: the two engines (or why one is
// missing) and a small terrain. Fields and files come from the shared test
// support (tests/support/).
//
// A missing engine makes a test SKIP with the reason. Set
// TSF_REQUIRE_TOOLS=1 (the CI machine has both) to make it FAIL instead.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "tests/support/files.h"
#include "runners/openscad/openscad_runner.h"
#include "runners/openscad/wasm_engine.h"
#include "tests/support/required_tools.h"

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

inline bool enginesRequired() { return toolsRequired(); }

/// Use as: TSF_NEED_ENGINE(nativeEngine()); skips (or fails when required) without it.
#define TSF_NEED_ENGINE(e)                                                                                  \
    do {                                                                                                    \
        if (!(e).engine) {                                                                                  \
            if (::tsf::test::enginesRequired()) FAIL() << "engine required but missing: " << (e).missing; \
            GTEST_SKIP() << "engine not installed: " << (e).missing;                                        \
        }                                                                                                   \
    } while (0)

/// A small uneven field with one no-data cell inside and a low corner (hull culling cuts it).
inline HexField smallTerrain() {
    return fieldFromRows({
        {0.0, 1.0, 2.5, 3.0, 1.5},
        {1.0, 4.0, NAN, 2.0, 0.5},
        {2.0, 3.5, 5.0, 4.5, 1.0},
        {0.5, 2.0, 1.0, 3.0, 2.0},
    });
}

/// 5 mm cells, 12 mm relief on a 2 mm base, 0.01 mm height snap: for smallTerrain().
inline SceneParams terrainParams(Bottom bottom) {
    SceneParams p;
    p.marks = withoutMarks();  // the pillar rules alone; marks have their own tests
    p.pitch_mm = 5.0;
    p.max_height_mm = 12.0;
    p.base_mm = 2.0;
    p.z_snap_mm = 0.01;
    p.bottom = bottom;
    p.cull = Cull::Hull;
    return p;
}

}  // namespace tsf::test
