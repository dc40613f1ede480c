// What is written is what was verified: STL and 3MF store float32, so a z
// grid finer than float32 resolves at the model's height is made coarser
// (with a note) and the written model passes `tsf verify --scene`; OFF keeps
// the grid asked for.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/files.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

TEST(Float32Output, AZGridFinerThanFloat32IsCoarsenedAndTheWrittenModelVerifies) {
    const auto dir = test::scratchDir();
    const std::string volcano = test::sourcePath("examples/volcano.csv");
    for (const char* ext : {".stl", ".3mf"}) {
        SCOPED_TRACE(ext);
        const std::string model = (dir / (std::string("v") + ext)).string();
        const auto g = test::runTsf("gen " + volcano + " --snap 1e-06 --tilt gradient --json -o " + model, dir);
        ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
        const auto scene = nlohmann::json::parse(test::readText(model + ".scene.json"));
        const double snap = scene["z_snap_mm"];
        EXPECT_GT(snap, 1e-06);
        EXPECT_LE(snap, 1e-04);  // coarser only as far as float32 needs at ~22 mm
        EXPECT_NE(g.out.find("float32"), std::string::npos) << "the summary says why the grid changed";
        const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json", dir);
        EXPECT_EQ(v.exit_code, test::kExitOk) << v.out << v.err;
        const auto a = test::runTsf("verify " + model + " --against " + volcano + " --snap 1e-06 --tilt gradient", dir);
        EXPECT_EQ(a.exit_code, test::kExitOk) << a.out << a.err;
    }
    // OFF writes the shortest decimal of every double: the finer grid stays.
    const std::string off = (dir / "v.off").string();
    const auto g = test::runTsf("gen " + volcano + " --snap 1e-06 --tilt gradient -o " + off, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    EXPECT_EQ(nlohmann::json::parse(test::readText(off + ".scene.json"))["z_snap_mm"].get<double>(), 1e-06);
    const auto v = test::runTsf("verify " + off + " --scene " + off + ".scene.json", dir);
    EXPECT_EQ(v.exit_code, test::kExitOk) << v.out << v.err;
}

}  // namespace
}  // namespace tsf
