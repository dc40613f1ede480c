// Agreement with a reference mesh: the same solid passes however it is
// triangulated, proven exactly and without sampling; a raised or missing
// pillar, a shifted copy and an inside-out copy fail, with the distance (or
// volume) measured against values known from how the difference was planted.
#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <utility>

#include <nlohmann/json.hpp>

#include "gen/util/error.h"
#include "gen/field/hex_grid.h"
#include "tests/verify/verify_test_support.h"
#include "verify/agreement.h"
#include "tests/support/required_tools.h"

namespace tsf {
namespace {

const Check& findCheck(const AgreementResult& r, const std::string& id) {
    for (const Check& c : r.checks)
        if (c.id == id) return c;
    ADD_FAILURE() << "no check " << id;
    return r.checks.front();
}

CheckStatus distanceStatus(const AgreementResult& r) { return findCheck(r, "reference_distance").status; }
CheckStatus volumeStatus(const AgreementResult& r) { return findCheck(r, "reference_volume").status; }

double area(const Mesh& m) {
    double a = 0;
    for (const auto& t : m.triangles) {
        const Vec3 &p = m.positions[t[0]], &q = m.positions[t[1]], &r = m.positions[t[2]];
        const Vec3 u{q.x - p.x, q.y - p.y, q.z - p.z}, v{r.x - p.x, r.y - p.y, r.z - p.z};
        a += 0.5 * std::hypot(u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x);
    }
    return a;
}

// xy of a vertex, for recognising wall triangles (their corners stand on the
// two vertical lines through the ends of one hexagon edge).
std::pair<double, double> xy(const Vec3& p) { return {p.x, p.y}; }

// The same surface, triangulated differently without moving a point off it:
//  - every wall rectangle (two triangles whose corners stand on the same two
//    vertical lines) gets its other diagonal;
//  - every vertical edge of a remaining wall triangle gets a vertex halfway up
//    (exactly on the edge: x and y are copied), splitting that triangle only,
//    so the neighbour across the edge keeps it whole (a T-junction, as
//    OpenSCAD leaves them).
Mesh retriangulated(const Mesh& m) {
    Mesh out = m;
    std::map<std::pair<uint32_t, uint32_t>, size_t> edge_owner;  // directed edge -> triangle
    for (size_t t = 0; t < out.triangles.size(); ++t)
        for (int e = 0; e < 3; ++e) edge_owner[{out.triangles[t][size_t(e)], out.triangles[t][size_t((e + 1) % 3)]}] = t;
    auto onTwoLines = [&](const std::array<uint32_t, 3>& t) {
        std::vector<std::pair<double, double>> lines;
        for (uint32_t v : t)
            if (std::find(lines.begin(), lines.end(), xy(out.positions[v])) == lines.end())
                lines.push_back(xy(out.positions[v]));
        return lines.size() == 2 ? lines : std::vector<std::pair<double, double>>{};
    };
    std::vector<uint8_t> done(out.triangles.size(), 0);
    size_t flips = 0;
    for (size_t t1 = 0; t1 < out.triangles.size(); ++t1) {
        if (done[t1]) continue;
        const auto lines1 = onTwoLines(out.triangles[t1]);
        if (lines1.empty()) continue;
        for (int e = 0; e < 3; ++e) {
            const uint32_t p = out.triangles[t1][size_t(e)], q = out.triangles[t1][size_t((e + 1) % 3)];
            const uint32_t r = out.triangles[t1][size_t((e + 2) % 3)];
            if (xy(out.positions[p]) == xy(out.positions[q])) continue;  // a vertical edge is no diagonal
            const auto it = edge_owner.find({q, p});
            if (it == edge_owner.end() || done[it->second]) continue;
            const size_t t2 = it->second;
            auto lines2 = onTwoLines(out.triangles[t2]);
            std::sort(lines2.begin(), lines2.end());
            auto sorted1 = lines1;
            std::sort(sorted1.begin(), sorted1.end());
            if (lines2 != sorted1) continue;  // not the same wall plane
            uint32_t s = 0;
            for (uint32_t v : out.triangles[t2])
                if (v != p && v != q) s = v;
            // A trapezoid with vertical sides (r and s on different lines) is
            // convex, so its other diagonal r-s is inside it.
            if (xy(out.positions[r]) == xy(out.positions[s])) continue;
            out.triangles[t1] = {s, q, r};
            out.triangles[t2] = {r, p, s};
            done[t1] = done[t2] = 1;
            ++flips;
            break;
        }
    }
    EXPECT_GT(flips, 20u) << "the wall rectangles were not found";
    const size_t n = out.triangles.size();
    size_t splits = 0;
    for (size_t t = 0; t < n; ++t) {
        if (done[t] || onTwoLines(out.triangles[t]).empty()) continue;
        const auto tri = out.triangles[t];
        for (int e = 0; e < 3; ++e) {
            const uint32_t p = tri[size_t(e)], q = tri[size_t((e + 1) % 3)], r = tri[size_t((e + 2) % 3)];
            const Vec3 &a = out.positions[p], &b = out.positions[q];
            if (xy(a) != xy(b)) continue;
            out.positions.push_back({a.x, a.y, a.z + (b.z - a.z) / 2});  // between a.z and b.z, on the edge
            const uint32_t mid = uint32_t(out.positions.size() - 1);
            out.triangles[t] = {p, mid, r};
            out.triangles.push_back({mid, q, r});
            ++splits;
            break;
        }
    }
    EXPECT_GT(splits, 20u);
    return out;
}

TEST(Agreement, AToleranceThatIsNotPositiveIsAnInputError) {
    const Mesh m = vtest::box({0, 0, 0}, {1, 1, 1});
    for (double bad : {0.0, -1.0, double(NAN), double(INFINITY)}) {
        AgreementOptions o;
        o.distance_tolerance_mm = bad;
        EXPECT_THROW(compareMeshes(m, m, "same", o), InputError) << bad;
    }
    AgreementOptions o;
    o.error_bound_mm = -0.1;
    EXPECT_THROW(compareMeshes(m, m, "same", o), InputError);
}

TEST(Agreement, ReListedCopyIsProvenIdenticalWithoutSampling) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Mesh other = m.mesh;
    std::reverse(other.triangles.begin(), other.triangles.end());
    for (auto& t : other.triangles) std::rotate(t.begin(), t.begin() + 1, t.end());
    const AgreementResult r = compareMeshes(m.mesh, other, "re-listed", {});
    EXPECT_EQ(distanceStatus(r), CheckStatus::Pass) << findCheck(r, "reference_distance").note;
    EXPECT_EQ(volumeStatus(r), CheckStatus::Pass);
    EXPECT_TRUE(r.figures.surfaces_compared);
    EXPECT_TRUE(r.figures.surfaces_identical);
    EXPECT_EQ(r.figures.differing_planes, 0u);
    EXPECT_EQ(r.figures.samples, 0u);
    EXPECT_EQ(r.figures.hausdorff_to_reference_mm, 0.0);
    EXPECT_EQ(r.figures.hausdorff_from_reference_mm, 0.0);
    EXPECT_EQ(r.figures.hausdorff_error_bound_mm, 0.0);
}

TEST(Agreement, RetriangulatedSurfaceWithTJunctionsIsProvenIdentical) {
    for (Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        const vtest::Model m = vtest::smallModel(bottom);
        const Mesh other = retriangulated(m.mesh);
        ASSERT_GT(other.triangles.size(), m.mesh.triangles.size());
        const AgreementResult r = compareMeshes(other, m.mesh, "direct", {});
        EXPECT_EQ(distanceStatus(r), CheckStatus::Pass) << findCheck(r, "reference_distance").note;
        EXPECT_EQ(volumeStatus(r), CheckStatus::Pass);
        EXPECT_TRUE(r.figures.surfaces_identical);
        EXPECT_EQ(r.figures.samples, 0u);
        EXPECT_EQ(r.figures.hausdorff_error_bound_mm, 0.0);
        // The volumes agree to rounding: an independent sum over other triangles.
        EXPECT_NEAR(r.figures.volume_difference_mm3, 0.0, 1e-9 * r.figures.volume_mm3);
    }
}

Mesh roundedToFloat32(Mesh m) {
    for (Vec3& p : m.positions) p = {double(float(p.x)), double(float(p.y)), double(float(p.z))};
    return m;
}

TEST(Agreement, Float32CopyIsProvenWithinItsRounding) {
    // The direct mesh in doubles against the same mesh as a binary STL
    // stores it: every coordinate rounded to float32. Exactly, nearly every
    // plane differs; rounded to float32 the two are identical, so the
    // distance is at most how far the rounding moved a vertex.
    const vtest::Model m = vtest::smallModel(Bottom::Mirrored);
    const Mesh stl = roundedToFloat32(m.mesh);
    const AgreementResult r = compareMeshes(m.mesh, stl, "float32 copy", {});
    EXPECT_EQ(distanceStatus(r), CheckStatus::Pass) << findCheck(r, "reference_distance").note;
    EXPECT_FALSE(r.figures.surfaces_identical);
    EXPECT_GT(r.figures.differing_planes, 0u);
    EXPECT_EQ(r.figures.rounded_to, "float32");
    EXPECT_EQ(r.figures.samples, 0u);
    // Independent bound: half a float32 ulp per coordinate, |coordinate| < 64 mm.
    const Bounds b = meshBounds(m.mesh);
    ASSERT_LT(std::max({b.max.x, b.max.y, b.max.z}), 64.0);
    const double half_ulp_at_64 = std::ldexp(1.0, 6 - 24);
    EXPECT_GT(r.figures.rounding_bound_mm, 0.0);
    EXPECT_LE(r.figures.rounding_bound_mm, std::sqrt(3.0) * half_ulp_at_64 * 1.000001);
    EXPECT_EQ(r.figures.hausdorff_error_bound_mm, r.figures.rounding_bound_mm);
}

TEST(Agreement, NoiseBelowTheGridIsProvenWithinTheGridRounding) {
    // Every x moved by 2^-18 mm (3.8e-6 mm, one float32 unit in the last place
    // at 32-64 mm): float32 rounding keeps the difference, a power-of-two grid
    // of 2^-12 mm merges it; the distance is proven within what the grid
    // rounding moved the vertices (at most 0.5 um in all).
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    const Mesh a = roundedToFloat32(m.mesh);
    Mesh noisy = a;
    for (Vec3& p : noisy.positions) p.x = double(float(p.x + std::ldexp(1.0, -18)));
    const AgreementResult r = compareMeshes(noisy, a, "float32 mesh", {});
    EXPECT_EQ(distanceStatus(r), CheckStatus::Pass) << findCheck(r, "reference_distance").note;
    EXPECT_TRUE(r.figures.surfaces_compared);
    EXPECT_GT(r.figures.differing_planes, 0u);
    EXPECT_NE(r.figures.rounded_to.find("grid"), std::string::npos) << r.figures.rounded_to;
    EXPECT_LE(r.figures.rounding_bound_mm, 0.5 * kDefaultAgreementToleranceMm);
    EXPECT_LE(r.figures.hausdorff_to_reference_mm, 4e-6);
}

TEST(Agreement, CoordinatesTooFineForTheExactComparisonAreProvenOnTheGrid) {
    // The x = 0 corner lines moved to the smallest float (2^-149): no common
    // integer grid of 125 bits holds 2^-149 and 64, so the exact comparison
    // cannot run; on a 2^-12 mm grid the two meshes are the same.
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    const Mesh a = roundedToFloat32(m.mesh);
    Mesh tiny = a;
    size_t moved = 0;
    for (Vec3& p : tiny.positions)
        if (p.x == 0) {
            p.x = std::ldexp(1.0, -149);
            ++moved;
        }
    ASSERT_GT(moved, 0u);
    const AgreementResult r = compareMeshes(tiny, a, "float32 mesh", {});
    EXPECT_FALSE(r.figures.surfaces_compared);
    EXPECT_EQ(distanceStatus(r), CheckStatus::Pass) << findCheck(r, "reference_distance").note;
    EXPECT_NE(r.figures.rounded_to.find("grid"), std::string::npos);
    EXPECT_EQ(r.figures.samples, 0u);
}

TEST(Agreement, PillarRaisedByTenMicronsFailsThereWithTheRaiseMeasured) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Scene s = m.scene;
    const size_t k = vtest::keptIndex(s, 2, 4);
    s.top[k] += 10;  // 10 snap steps of 1 um = 0.01 mm
    const Mesh raised = meshScene(s);
    const AgreementResult r = compareMeshes(raised, m.mesh, "original", {});
    const Check& d = findCheck(r, "reference_distance");
    ASSERT_EQ(d.status, CheckStatus::Fail) << d.note;
    // Only the planes of the raised cell's top and walls differ (with the
    // other cells' faces in those planes): a small part of the model is sampled.
    EXPECT_TRUE(r.figures.surfaces_compared);
    EXPECT_FALSE(r.figures.surfaces_identical);
    EXPECT_LE(r.figures.differing_planes, 2u + 6u);  // the old and new top, the six wall planes around the cell
    EXPECT_LT(r.figures.differing_area_mm2, 0.1 * area(raised));
    // The raised top is 0.01 mm above where the reference's top is.
    EXPECT_NEAR(r.figures.hausdorff_to_reference_mm, 0.01, 1e-9);
    EXPECT_LE(r.figures.hausdorff_from_reference_mm, 0.01 + 1e-9);
    ASSERT_FALSE(d.worst.empty());
    const Vec3 centre = vtest::cellCentre(s, k, 0);
    for (const Offender& o : d.worst)
        EXPECT_LT(std::hypot(o.at_mm.x - centre.x, o.at_mm.y - centre.y), s.pitch_mm) << o.detail;
    // 0.01 mm times a hexagon is far inside the volume tolerance: only the
    // distance can see this difference.
    // (Corners are snapped to 1 um, so the hexagon's area is right to ~1e-3.)
    EXPECT_NEAR(r.figures.volume_difference_mm3, hexArea(s.pitch_mm, s.y_scale) * 0.01, 1e-3 * hexArea(s.pitch_mm, s.y_scale) * 0.01);
    EXPECT_EQ(volumeStatus(r), CheckStatus::Pass);
}

TEST(Agreement, MissingPillarFailsByItsHeight) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Scene s = m.scene;
    const size_t k = vtest::keptIndex(s, 4, 3);
    const double height_mm = s.zMm(s.top[k] - s.floor_units);
    ASSERT_GT(height_mm, 1.0);
    s.top[k] = s.floor_units;  // the pillar is gone; its cell is bare base
    const AgreementResult r = compareMeshes(meshScene(s), m.mesh, "original", {});
    EXPECT_EQ(distanceStatus(r), CheckStatus::Fail);
    EXPECT_EQ(volumeStatus(r), CheckStatus::Fail);
    // From the reference: the missing pillar's top centre is `height` above
    // the bare cell's floor and at least half a pitch from any wall, so its
    // distance is at least min(height, pitch / 2); no point of the missing
    // pillar is farther than `height` from the floor straight below it.
    EXPECT_LE(r.figures.hausdorff_from_reference_mm, height_mm + 1e-9);
    EXPECT_GE(r.figures.hausdorff_from_reference_mm, std::min(height_mm, s.pitch_mm / 2) - r.figures.hausdorff_error_bound_mm);
    EXPECT_NEAR(r.figures.volume_difference_mm3, -hexArea(s.pitch_mm, s.y_scale) * height_mm, 1e-3 * hexArea(s.pitch_mm, s.y_scale) * height_mm);
}

TEST(Agreement, CopyShiftedByTenMicronsFailsByTheShift) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Mesh shifted = m.mesh;
    for (Vec3& p : shifted.positions) p.x += 0.01;
    const AgreementResult r = compareMeshes(shifted, m.mesh, "original", {});
    EXPECT_EQ(distanceStatus(r), CheckStatus::Fail);
    EXPECT_EQ(findCheck(r, "reference_distance").count, 2);  // both directions
    // No point moved farther than the shift, and the walls facing east and
    // west (pointy-top hexagons) moved straight off themselves by all of it.
    EXPECT_NEAR(r.figures.hausdorff_to_reference_mm, 0.01, 1e-9);
    EXPECT_NEAR(r.figures.hausdorff_from_reference_mm, 0.01, 1e-9);
    // The volume check alone cannot tell a shifted copy.
    EXPECT_EQ(volumeStatus(r), CheckStatus::Pass);
}

TEST(Agreement, ShiftBelowTheToleranceIsMeasuredButNotClaimedAsProven) {
    // Half the tolerance everywhere: every plane differs, and no affordable
    // sampling radius is below the remaining half micron.
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Mesh shifted = m.mesh;
    for (Vec3& p : shifted.positions) p.x += 0.0005;
    AgreementOptions o;
    o.sample_budget = 100'000;
    const AgreementResult r = compareMeshes(shifted, m.mesh, "original", o);
    EXPECT_EQ(distanceStatus(r), CheckStatus::Warn) << findCheck(r, "reference_distance").note;
    EXPECT_NEAR(r.figures.hausdorff_to_reference_mm, 0.0005, 1e-9);
    EXPECT_GT(r.figures.hausdorff_error_bound_mm, 0.0005);
    EXPECT_LE(r.figures.samples, o.sample_budget);
    EXPECT_NE(findCheck(r, "reference_distance").note.find("not proven"), std::string::npos);
    // For --strict: not proven is a failure.
    o.fail_on_warnings = true;
    EXPECT_EQ(distanceStatus(compareMeshes(shifted, m.mesh, "original", o)), CheckStatus::Fail);
}

TEST(Agreement, InsideOutCopyIsTheSameSurfaceWithTheOppositeVolume) {
    const vtest::Model m = vtest::smallModel(Bottom::Mirrored);
    Mesh flipped = m.mesh;
    for (auto& t : flipped.triangles) std::swap(t[1], t[2]);
    const AgreementResult r = compareMeshes(flipped, m.mesh, "original", {});
    // Same point set: distance 0, proven; every plane faces the other way.
    EXPECT_EQ(distanceStatus(r), CheckStatus::Pass);
    EXPECT_FALSE(r.figures.surfaces_identical);
    EXPECT_EQ(r.figures.differing_planes, 0u);
    EXPECT_EQ(r.figures.opposite_planes, r.figures.planes);
    EXPECT_EQ(volumeStatus(r), CheckStatus::Fail);
    EXPECT_NEAR(r.figures.volume_difference_mm3, -2 * r.figures.reference_volume_mm3, 1e-9 * r.figures.reference_volume_mm3);
}

TEST(Agreement, OverlappingSheetInTheReferenceIsFoundBySampling) {
    // A fin of two coincident triangles facing opposite ways, standing 5 mm
    // up from a box's top: as an oriented surface it cancels out, so the
    // exact comparison sees the box alone. Its vertices are off the box,
    // which breaks the comparison's premise: the reference is sampled
    // everywhere and the fin's tip is found.
    const Mesh box = vtest::box({0, 0, 0}, {10, 10, 10});
    Mesh fin = box;
    fin.positions.push_back({2, 5, 10});
    fin.positions.push_back({8, 5, 10});
    fin.positions.push_back({5, 5, 15});
    const uint32_t a = 8, b = 9, c = 10;
    fin.triangles.push_back({a, b, c});
    fin.triangles.push_back({a, c, b});
    const AgreementResult r = compareMeshes(box, fin, "box with a fin", {});
    EXPECT_EQ(distanceStatus(r), CheckStatus::Fail);
    EXPECT_NEAR(r.figures.hausdorff_from_reference_mm, 5.0, 1e-9);
    EXPECT_EQ(r.figures.hausdorff_to_reference_mm, 0.0);
    EXPECT_NE(findCheck(r, "reference_distance").note.find("sampled everywhere"), std::string::npos);
}

TEST(Agreement, SamplingStaysWithinTheBudget) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Mesh shifted = m.mesh;
    for (Vec3& p : shifted.positions) p.z += 0.02;
    for (size_t budget : {size_t(5'000), size_t(50'000)}) {
        AgreementOptions o;
        o.sample_budget = budget;
        const AgreementResult r = compareMeshes(shifted, m.mesh, "original", o);
        // Every vertex is measured whatever the budget.
        const size_t floor = shifted.positions.size() + m.mesh.positions.size();
        EXPECT_LE(r.figures.samples, std::max(budget, floor)) << budget;
        EXPECT_EQ(distanceStatus(r), CheckStatus::Fail);
        EXPECT_NEAR(r.figures.hausdorff_to_reference_mm, 0.02, 1e-9);
    }
}

TEST(Agreement, EmptyReferenceFails) {
    const AgreementResult r = compareMeshes(vtest::box({0, 0, 0}, {1, 1, 1}), Mesh{}, "nothing", {});
    EXPECT_EQ(distanceStatus(r), CheckStatus::Fail);
    EXPECT_EQ(volumeStatus(r), CheckStatus::Fail);
}

// The use the check exists for: OpenSCAD's render of the generated .scad
// against the direct mesh, through the command line. A model of pillars
// alone (no orientation tab, scale or legend joined to them): OpenSCAD 2021
// puts the vertices of a boolean union on its 2^-20 mm grid, which the
// agreement check allows for but "identical" does not.
TEST(Agreement, OpenScadRenderIsProvenTheSameSolid) {
    TSF_NEED_TOOL(std::filesystem::exists("/usr/bin/openscad"), "/usr/bin/openscad");
    const auto dir = vtest::scratchDir("agreement_openscad");
    std::string csv;
    const HexField f = vtest::smallField();
    for (int r = 0; r < f.grid.rows; ++r) {
        for (int c = 0; c < f.grid.cols; ++c) {
            const double v = f.values[size_t(r * f.grid.cols + c)];
            csv += (c ? "," : "") + (std::isnan(v) ? std::string("NA") : std::to_string(v));
        }
        csv += "\n";
    }
    vtest::writeText(dir / "field.csv", csv);
    const auto gen = vtest::runTsf("gen " + (dir / "field.csv").string() + " --mirror --marks-on data -o " + (dir / "direct.stl").string() +
                                       " --scad " + (dir / "m.scad").string(),
                                   dir);
    ASSERT_EQ(gen.exit_code, 0) << gen.err;
    const auto render = vtest::runTsf("render " + (dir / "m.scad").string() + " -o " + (dir / "openscad.stl").string(), dir);
    ASSERT_EQ(render.exit_code, 0) << render.err;
    const auto verify = vtest::runTsf("verify " + (dir / "openscad.stl").string() + " --reference " +
                                          (dir / "direct.stl").string() + " --json --no-printability",
                                      dir);
    ASSERT_EQ(verify.exit_code, 0) << verify.out << verify.err;
    const nlohmann::json j = nlohmann::json::parse(verify.out);
    EXPECT_TRUE(j["agreement"]["surfaces_identical"].get<bool>());
    EXPECT_EQ(j["agreement"]["samples"].get<size_t>(), 0u);
    EXPECT_EQ(j["agreement"]["hausdorff_to_reference_mm"].get<double>(), 0.0);
}

}  // namespace
}  // namespace tsf
