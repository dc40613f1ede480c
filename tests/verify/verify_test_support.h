// Fixtures for the verifier tests: hand-drawn meshes, small real tsf models
// (buildScene + meshScene), defect planting, and running the tsf binary.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "gen/direct_mesher.h"
#include "gen/hex_field.h"
#include "gen/mesh.h"
#include "gen/scene.h"
#include "verify/report.h"

namespace tsf::vtest {

// Axis-aligned box from lo to hi, CCW seen from outside.
//
//        7-------6
//       /|      /|          z
//      4-------5 |          |  y
//      | 3-----|-2          | /
//      |/      |/           |/
//      0-------1            +---- x
inline Mesh box(Vec3 lo, Vec3 hi) {
    Mesh m;
    for (int i = 0; i < 8; ++i) {
        const bool x = i == 1 || i == 2 || i == 5 || i == 6;
        const bool y = i == 2 || i == 3 || i == 6 || i == 7;
        const bool z = i >= 4;
        m.positions.push_back({x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z});
    }
    m.triangles = {{0, 3, 2}, {0, 2, 1},   // bottom, -z
                   {4, 5, 6}, {4, 6, 7},   // top, +z
                   {0, 1, 5}, {0, 5, 4},   // front, -y
                   {1, 2, 6}, {1, 6, 5},   // right, +x
                   {2, 3, 7}, {2, 7, 6},   // back, +y
                   {3, 0, 4}, {3, 4, 7}};  // left, -x
    return m;
}

/// Appends b to a (b's indices shifted); no vertex is shared.
inline Mesh append(Mesh a, const Mesh& b) {
    const uint32_t off = uint32_t(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (auto t : b.triangles) a.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
    return a;
}

inline Vec3 centroid(const Mesh& m, size_t t) {
    const auto& tri = m.triangles[t];
    const Vec3 &a = m.positions[tri[0]], &b = m.positions[tri[1]], &c = m.positions[tri[2]];
    return {(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3};
}

inline double distance(const Vec3& a, const Vec3& b) {
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) + (a.z - b.z) * (a.z - b.z));
}

/// A 7 x 6 field with heights that differ between most neighbours, one cell
/// without data (col 3, row 2) and a low corner, so hull culling drops a cell.
inline HexField smallField() {
    HexField f;
    f.grid = {7, 6};
    f.values.resize(42);
    for (int r = 0; r < 6; ++r)
        for (int c = 0; c < 7; ++c) f.values[size_t(r * 7 + c)] = 1.0 + double((c * 7 + r * 3) % 5) + 0.25 * c;
    f.values[size_t(2 * 7 + 3)] = NAN;
    f.values[0] = 0.0;  // north-west corner: empty, outside the hull of the others
    f.source = "small field";
    return f;
}

inline SceneParams smallParams(Bottom bottom = Bottom::Flat, double snap_mm = 0.001) {
    SceneParams p;
    p.marks = withoutMarks();  // the pillar rules alone; marks have their own tests
    p.pitch_mm = 5.0;
    p.max_height_mm = 10.0;
    p.base_mm = 2.0;
    p.z_snap_mm = snap_mm;
    p.bottom = bottom;
    return p;
}

struct Model {
    Scene scene;
    Mesh mesh;
};

inline Model smallModel(Bottom bottom = Bottom::Flat, double snap_mm = 0.001) {
    Model m;
    m.scene = buildScene(smallField(), smallParams(bottom, snap_mm));
    m.mesh = meshScene(m.scene);
    return m;
}

/// Index of the kept cell (col, row); fails the test if it is not kept.
inline size_t keptIndex(const Scene& s, int32_t col, int32_t row) {
    const int32_t k = s.keptAt(col, row);
    EXPECT_GE(k, 0) << "cell (" << col << ", " << row << ") is not kept";
    return size_t(std::max(k, 0));
}

/// Centre of kept cell k (mm).
inline Vec3 cellCentre(const Scene& s, size_t k, int64_t z_units) {
    return s.point(hexCentre(s.grid, s.col[k], s.row[k]), z_units);
}

/// The check with this id; fails the test if absent.
inline const Check& check(const VerifyReport& r, const std::string& id) {
    const Check* c = r.find(id);
    if (!c) {
        ADD_FAILURE() << "no check '" << id << "' in the report";
        static const Check none;
        return none;
    }
    return *c;
}

/// The ids of the checks that failed, sorted, for readable assertions.
inline std::vector<std::string> failedIds(const VerifyReport& r) {
    std::vector<std::string> ids;
    for (const Check& c : r.checks)
        if (c.status == CheckStatus::Fail) ids.push_back(c.id);
    std::sort(ids.begin(), ids.end());
    return ids;
}

/// Smallest distance (mm) from p to the offenders of a check; +inf if none.
inline double nearestOffender(const Check& c, const Vec3& p) {
    double best = INFINITY;
    for (const Offender& o : c.worst) best = std::min(best, distance(o.at_mm, p));
    return best;
}

// --- files and the tsf binary ----------------------------------------------

struct RunResult {
    int exit_code = -1;
    std::string out;  ///< stdout only
    std::string err;  ///< stderr
};

inline std::filesystem::path scratch(const std::string& name) {
    const std::filesystem::path dir = std::filesystem::path(TSF_TEST_SCRATCH) / name;
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

inline std::string readText(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

inline void writeText(const std::filesystem::path& p, const std::string& text) {
    std::ofstream(p, std::ios::binary) << text;
}

/// Runs `tsf <args>` with stdout and stderr captured separately.
inline RunResult runTsf(const std::string& args, const std::filesystem::path& dir) {
    RunResult r;
    const std::filesystem::path out = dir / "stdout.txt", err = dir / "stderr.txt";
    const std::string cmd = std::string(TSF_BINARY) + " " + args + " >" + out.string() + " 2>" + err.string();
    const int status = std::system(cmd.c_str());
    r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    r.out = readText(out);
    r.err = readText(err);
    return r;
}

/// OFF text of a mesh with coordinates printed exactly (17 significant digits).
inline std::string toOff(const Mesh& m) {
    std::string s = "OFF\n" + std::to_string(m.positions.size()) + " " + std::to_string(m.triangles.size()) + " 0\n";
    char buf[128];
    for (const Vec3& p : m.positions) {
        std::snprintf(buf, sizeof buf, "%.17g %.17g %.17g\n", p.x, p.y, p.z);
        s += buf;
    }
    for (const auto& t : m.triangles) s += "3 " + std::to_string(t[0]) + " " + std::to_string(t[1]) + " " + std::to_string(t[2]) + "\n";
    return s;
}

}  // namespace tsf::vtest
