// The desktop engine passes --backend=manifold exactly when the binary offers
// it (detected from --help, never assumed). Checked with stand-in binaries,
// since Debian's OpenSCAD 2021.01 has no Manifold backend.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "tests/support/files.h"
#include "runners/openscad/openscad_runner.h"

namespace tsf {
namespace {
namespace fs = std::filesystem;

// A shell script that answers --version and --help like OpenSCAD, records the
// arguments of a render in $TSF_FAKE_ARGS and writes a small file to -o.
fs::path writeFakeOpenScad(const fs::path& dir, bool offers_manifold) {
    const fs::path exe = dir / (offers_manifold ? "openscad-2025" : "openscad-2021");
    std::ofstream out(exe);
    out << "#!/bin/sh\n"
           "case \"$1\" in\n"
           "  --version) echo 'OpenSCAD version 2025.01.19' >&2; exit 0;;\n"
           "  --help) echo 'Usage: openscad [options] file.scad'; echo '  -o arg   output file';\n";
    if (offers_manifold)
        out << "    echo \"  --backend arg   3D rendering backend to use: 'CGAL' (old/slow) [default] or 'Manifold' (new/fast)\";\n";
    out << "    exit 0;;\n"
           "esac\n"
           "echo \"$@\" > \"$TSF_FAKE_ARGS\"\n"
           "o=''; while [ $# -gt 0 ]; do [ \"$1\" = -o ] && o=\"$2\"; shift; done\n"
           "printf 'solid t\\nendsolid t\\n' > \"$o\"\n";
    out.close();
    fs::permissions(exe, fs::perms::owner_all);
    return exe;
}

std::string renderArgs(const fs::path& dir, bool offers_manifold) {
    const fs::path args = dir / (offers_manifold ? "args-2025.txt" : "args-2021.txt");
    setenv("TSF_FAKE_ARGS", args.c_str(), 1);
    test::writeText(dir / "m.scad", "cube(1);\n");
    const auto engine = makeOpenScadEngine(writeFakeOpenScad(dir, offers_manifold).string());
    ScadRenderRequest rq;
    rq.scad_path = (dir / "m.scad").string();
    rq.output_path = (dir / "m.stl").string();
    const ScadRenderResult r = renderScad(*engine, rq);
    EXPECT_TRUE(r.ok()) << r.summary << "\n" << r.output;
    return test::readText(args);
}

TEST(NativeEngine, PassesTheManifoldBackendOnlyWhenTheBinaryOffersIt) {
    const fs::path dir = test::scratchDir("native_manifold");
    EXPECT_NE(renderArgs(dir, true).find("--backend=manifold"), std::string::npos);
    const std::string old_args = renderArgs(dir, false);
    EXPECT_FALSE(old_args.empty());
    EXPECT_EQ(old_args.find("--backend"), std::string::npos) << old_args;
}

}  // namespace
}  // namespace tsf
