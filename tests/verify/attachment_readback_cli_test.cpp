// tsf verify --scene reads every attachment back from the written model: the
// braille legend (plate and each dot), the tactile scale and the orientation
// marks, from what the sidecar recorded, with no braille table at hand.
// Each planted defect below leaves a closed, valid mesh that only the
// read-back can tell from the model tsf wrote.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <functional>
#include <map>

#include <nlohmann/json.hpp>

#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/stl_writer.h"
#include "tests/support/files.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

using nlohmann::json;

// A layer of a 0.2 mm printer: a tread or a triangle this far off is wrong.
constexpr double kLayerMm = 0.2;

struct MadeModel {
    std::filesystem::path dir;
    std::string model, sidecar;
    json scene;
};

// The bundled airports as tilted bins with every attachment. Made once: the
// tests below only read it and write beside it.
const MadeModel& madeModel() {
    static const MadeModel m = [] {  // once per process
        MadeModel r;
        r.dir = test::scratchDir();  // per test: ctest runs each in a process of its own, side by side
        r.model = (r.dir / "m.stl").string();
        r.sidecar = r.model + ".scene.json";
        const auto g = test::runTsf("gen " + test::sourcePath("examples/airports-europe.csv") +
                                        " --points x=lon,y=lat --project equirect --bins 20 --title Airports --units airports --scale"
                                        " --tilt points --marks-on data -o " + r.model,
                                    r.dir);
        EXPECT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
        r.scene = json::parse(test::readText(r.sidecar));
        return r;
    }();
    return m;
}

// The statuses of `tsf verify MODEL --scene SIDECAR --json`, by check id.
struct Verdict {
    int exit_code = -1;
    std::map<std::string, std::string> status;
    std::string text;
};

Verdict verify(const std::string& model, const std::string& sidecar, const std::filesystem::path& dir) {
    Verdict v;
    const auto r = test::runTsf("verify " + model + " --scene " + sidecar + " --no-printability --json", dir);
    v.exit_code = r.exit_code;
    v.text = r.out + r.err;
    if (r.out.empty()) return v;
    const json j = json::parse(r.out);
    for (const auto& c : j["checks"]) v.status[c["id"]] = c["status"];
    return v;
}

// A copy of the model with every vertex that `pick` selects moved by `move`.
std::string plant(const std::string& name, const std::function<bool(const Vec3&)>& pick,
                  const std::function<void(Vec3&)>& move) {
    const MadeModel& m = madeModel();
    Mesh mesh = readMesh(m.model);
    size_t moved = 0;
    for (Vec3& p : mesh.positions)
        if (pick(p)) {
            move(p);
            ++moved;
        }
    EXPECT_GT(moved, 0u) << name << ": nothing to move";
    const std::string path = (m.dir / name).string();
    writeStl(mesh, path);
    return path;
}

double zOf(const json& scene, int64_t units) { return double(units) * scene["z_snap_mm"].get<double>(); }

TEST(AttachmentReadback, EveryAttachmentIsReadBackWithNoBrailleTableAtHand) {
    const MadeModel& m = madeModel();
    ASSERT_TRUE(m.scene["legend"].is_object());
    ASSERT_TRUE(m.scene["scale"].is_object());
    ASSERT_TRUE(m.scene["marks"]["triangle"].is_object());
    ASSERT_TRUE(m.scene["shapes"].is_object()) << "the model is not tilted";
    // liblouis finds no table at all, and the sidecar names a table that
    // does not exist: verification reads the recorded dots, never a table.
    const auto empty = m.dir / "no-tables";
    std::filesystem::create_directories(empty);
    json changed = m.scene;
    changed["legend"]["table"] = "changed-since.ctb";
    const std::string sidecar = (m.dir / "changed-table.scene.json").string();
    test::writeText(sidecar, changed.dump());
    ::setenv("LOUIS_TABLEPATH", empty.c_str(), 1);
    const Verdict as_written = verify(m.model, m.sidecar, m.dir);
    const Verdict other_table = verify(m.model, sidecar, m.dir);
    ::unsetenv("LOUIS_TABLEPATH");
    for (const Verdict* v : {&as_written, &other_table}) {
        EXPECT_EQ(v->exit_code, test::kExitOk) << v->text;
        EXPECT_EQ(v->status.at("legend_read_back"), "pass") << v->text;
        EXPECT_EQ(v->status.at("scale_read_back"), "pass") << v->text;
        EXPECT_EQ(v->status.at("marks_read_back"), "pass") << v->text;
    }
}

TEST(AttachmentReadback, ABrailleDotPrintedAtAThirdOfItsHeightFails) {
    const MadeModel& m = madeModel();
    const json& l = m.scene["legend"];
    const double plate = zOf(m.scene, l["plate_top_units"]);
    const double x = l["dots"][0][0].get<double>() + l["origin_mm"][0].get<double>();
    const double y = l["dots"][0][1].get<double>() + l["origin_mm"][1].get<double>();
    const double r = 0.5 * l["standard"]["dot_base_mm"].get<double>();
    // The whole dome squashed to 30 % of its height: still a closed dome.
    const std::string planted = plant(
        "low-dot.stl",
        [&](const Vec3& p) { return std::hypot(p.x - x, p.y - y) < r + 1e-4 && p.z > plate + 1e-4; },
        [&](Vec3& p) { p.z = plate + 0.3 * (p.z - plate); });
    Verdict v = verify(planted, m.sidecar, m.dir);
    EXPECT_EQ(v.exit_code, test::kExitCheckFailed) << v.text;
    EXPECT_EQ(v.status["legend_read_back"], "fail") << v.text;
    EXPECT_NE(v.text.find("braille dot 1 of"), std::string::npos) << v.text;
    EXPECT_EQ(v.status["closed"], "pass") << v.text;
}

TEST(AttachmentReadback, AScaleTreadALayerTooHighFails) {
    const MadeModel& m = madeModel();
    const json& sc = m.scene["scale"];
    ASSERT_GE(sc["steps"].size(), 2u);
    const json& step = sc["steps"][1];
    const double tread = zOf(m.scene, step[1]);
    const double xs = sc["x_mm"][1], x1 = sc["x_mm"][2], ys = step[2], yn = step[3];
    const std::string planted = plant(
        "high-tread.stl",
        [&](const Vec3& p) {
            return std::fabs(p.z - tread) < 1e-4 && p.x > xs - 1e-4 && p.x < x1 + 1e-4 && p.y > ys - 1e-4 &&
                   p.y < yn + 1e-4;
        },
        [&](Vec3& p) { p.z += kLayerMm; });
    Verdict v = verify(planted, m.sidecar, m.dir);
    EXPECT_EQ(v.exit_code, test::kExitCheckFailed) << v.text;
    EXPECT_EQ(v.status["scale_read_back"], "fail") << v.text;
}

TEST(AttachmentReadback, TheOrientationTriangleALayerTooLowFails) {
    const MadeModel& m = madeModel();
    const json& t = m.scene["marks"]["triangle"];
    const double pitch = m.scene["pitch_mm"];
    auto mm = [&](const json& p) {
        return std::pair<double, double>{p[0].get<double>() * pitch * 0.5, p[1].get<double>() * pitch / (2 * std::sqrt(3.0))};
    };
    const auto [cx, cy] = mm(t["corner"]);
    const auto [ex, ey] = mm(t["east"]);
    const auto [nx, ny] = mm(t["north"]);
    const int64_t anchor = t["anchor"];
    const double top = zOf(m.scene, m.scene["cells"][size_t(anchor)]["top"].get<int64_t>() + t["raise_units"].get<int64_t>());
    const std::string planted = plant(
        "low-triangle.stl",
        [&](const Vec3& p) {
            return std::fabs(p.z - top) < 1e-4 && p.x > cx - 1e-3 && p.x < ex + 1e-3 && p.y > cy - 1e-3 &&
                   p.y < ny + 1e-3;
        },
        [&](Vec3& p) { p.z -= kLayerMm; });
    (void)ey;
    (void)nx;
    Verdict v = verify(planted, m.sidecar, m.dir);
    EXPECT_EQ(v.exit_code, test::kExitCheckFailed) << v.text;
    EXPECT_EQ(v.status["marks_read_back"], "fail") << v.text;
}

}  // namespace
}  // namespace tsf
