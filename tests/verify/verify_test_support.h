// Fixtures of the verifier tests: small real tsf models (buildScene +
// meshScene), finding checks and offenders in a report. Meshes, parameters,
// files and running the tsf binary come from the shared test support
// (tests/support/).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "gen/mesh/direct_mesher.h"
#include "gen/field/hex_field.h"
#include "gen/geometry/mesh.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "tests/support/files.h"
#include "tests/support/meshes.h"
#include "tests/support/run.h"
#include "verify/report.h"

namespace tsf::vtest {

using test::append;
using test::box;
using test::readText;
using test::RunResult;
using test::runTsf;
using test::scratchDir;
using test::smallParams;
using test::writeText;

/// The pairs `index.forEachOverlappingPair` visits on two workers that
/// `keep(a, b)` accepts, each as (smaller, larger), in ascending order; a
/// pair visited twice is listed twice.
template <class Index, class Keep>
std::vector<std::pair<uint32_t, uint32_t>> visitedPairs(const Index& index, Keep keep) {
    std::vector<std::vector<std::pair<uint32_t, uint32_t>>> per_worker(2);
    index.forEachOverlappingPair(
        [&](unsigned w, uint32_t a, uint32_t b) {
            if (keep(a, b)) per_worker[w].emplace_back(std::min(a, b), std::max(a, b));
        },
        2);
    std::vector<std::pair<uint32_t, uint32_t>> pairs = per_worker[0];
    pairs.insert(pairs.end(), per_worker[1].begin(), per_worker[1].end());
    std::sort(pairs.begin(), pairs.end());
    return pairs;
}

template <class Index>
std::vector<std::pair<uint32_t, uint32_t>> visitedPairs(const Index& index) {
    return visitedPairs(index, [](uint32_t, uint32_t) { return true; });
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

struct Model {
    Scene scene;
    Mesh mesh;
};

/// smallField() with smallParams(bottom) and the given height snap.
inline SceneParams smallFieldParams(Bottom bottom = Bottom::Flat, double snap_mm = 0.001) {
    SceneParams p = smallParams(bottom);
    p.z_snap_mm = snap_mm;
    return p;
}

inline Model smallModel(Bottom bottom = Bottom::Flat, double snap_mm = 0.001) {
    Model m;
    m.scene = buildScene(smallField(), smallFieldParams(bottom, snap_mm));
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

/// Kept cell k's centre and its six corners at z = 0 (mm): where vertical
/// rays meet a top's diagonals and the walls' edges.
inline std::vector<Vec3> cellCentreAndCorners(const Scene& s, size_t k) {
    std::vector<Vec3> out{s.point(hexCentre(s.grid, s.col[k], s.row[k]), 0)};
    for (int c = 0; c < kHexCorners; ++c) out.push_back(s.point(hexCorner(s.grid, s.col[k], s.row[k], c), 0));
    return out;
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
