// Tests that need an external tool (OpenSCAD, admesh, PrusaSlicer, OpenSCAD's
// bundled examples) skip on a machine without it, and FAIL where the tools
// are required: CI sets TSF_REQUIRE_TOOLS=1 (setup.sh installs every one), so
// a tool that went missing there is a red build, never a silent skip.
// TSF_REQUIRE_SCAD_ENGINES=1 (the older name, for the OpenSCAD engines) is
// honoured too.
#pragma once

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

namespace tsf::test {

inline bool envFlag(const char* name) {
    const char* v = std::getenv(name);
    return v && *v && std::string(v) != "0";
}

/// True when a missing tool must fail its test instead of skipping it.
inline bool toolsRequired() { return envFlag("TSF_REQUIRE_TOOLS") || envFlag("TSF_REQUIRE_SCAD_ENGINES"); }

}  // namespace tsf::test

/// Use as: TSF_NEED_TOOL(haveSlicer(), "prusa-slicer"); skips without the
/// tool, or fails when tools are required.
#define TSF_NEED_TOOL(present, what)                                                                          \
    do {                                                                                                      \
        if (!(present)) {                                                                                     \
            if (::tsf::test::toolsRequired()) FAIL() << (what) << " is required (TSF_REQUIRE_TOOLS) but missing"; \
            GTEST_SKIP() << (what) << " is not installed (setup.sh installs it)";                            \
        }                                                                                                     \
    } while (0)
