// The halves and pins of `tsf gen --mirror --halves`. See halves_output.h.
#include "app/halves_output.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/commands.h"
#include "gen/mesh/halves_mesh.h"
#include "verify/halves_check.h"
#include "verify/overhang.h"
#include "gen/model/features/halves.h"
#include "gen/util/number_format.h"

namespace tsf::cli {
namespace {

// A piece that fails its own checks is a bug in tsf: never hand it to a printer.
[[noreturn]] void failPiece(const VerifyReport& r, const std::string& what) {
    std::cerr << formatReport(r);
    std::cerr << "tsf: the " << what << " failed verification; nothing was written. Please report this with the input file.\n";
    throw CLI::RuntimeError(kExitCheckFailed);
}

// Checks one piece as it prints: the verifier's checks, and no overhang at all.
nlohmann::json verifyPiece(const Mesh& mesh, const Scene* scene, VerifyOptions vo, const std::string& name,
                           const std::string& what) {
    vo.name = name;
    const VerifyReport r = verifyModel(mesh, scene, vo);
    const Check* over = r.find("overhang");
    if (!r.passed() || (over && over->status != CheckStatus::Pass)) failPiece(r, what);
    return toJson(r);
}

Mesh append(Mesh m, const Mesh& b, double dx) {
    const uint32_t base = uint32_t(m.positions.size());
    for (const Vec3& p : b.positions) m.positions.push_back({p.x + dx, p.y, p.z});
    for (const auto& t : b.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    return m;
}

}  // namespace

HalvesPaths halvesPaths(const std::string& output) {
    const std::filesystem::path p(output);
    const std::string stem = (p.parent_path() / p.stem()).string(), ext = p.extension().string();
    return {stem + "-upper" + ext, stem + "-lower" + ext, stem + "-pins" + ext};
}

HalvesPieces makeHalves(const Scene& scene, const Mesh& whole, bool verify, VerifyOptions vo, GenSummary& summary) {
    HalvesPieces p;
    const Scene upper_scene = halfScene(scene, HalfKind::Upper), lower_scene = halfScene(scene, HalfKind::Lower);
    p.upper = meshHalf(scene, HalfKind::Upper);
    p.lower = meshHalf(scene, HalfKind::Lower);
    p.pins = pinsMesh(scene.halves->pins);
    nlohmann::json j;
    std::string text;
    if (verify) {
        // The lower half is read back in halfScene's frame (its print turned back, a rigid motion away).
        j["upper"] = verifyPiece(p.upper, &upper_scene, vo, "upper half", "upper half");
        j["lower"] = verifyPiece(turnLowerHalf(p.lower, scene), &lower_scene, vo, "lower half", "lower half");
        j["pin"] = verifyPiece(pinMesh(scene.halves->pins, 0, 0), nullptr, vo, "pin", "pin");
        const HalvesCheckResult pair = checkHalves(scene, whole, p.upper, p.lower);
        nlohmann::json checks = nlohmann::json::array();
        for (const Check& c : pair.checks) checks.push_back({{"id", c.id}, {"status", toString(c.status)}, {"note", c.note}});
        const HalvesJoinFigures& f = pair.figures;
        j["pair"] = {{"checks", checks},
                     {"upper_volume_mm3", f.upper_volume_mm3},
                     {"lower_volume_mm3", f.lower_volume_mm3},
                     {"whole_volume_mm3", f.whole_volume_mm3},
                     {"holes_volume_mm3", f.holes_volume_mm3},
                     {"volume_error_mm3", f.volume_error_mm3},
                     {"max_distance_mm", f.max_distance_mm},
                     {"samples", f.samples}};
        if (!pair.passed()) {
            for (const Check& c : pair.checks) std::cerr << toString(c.status) << "  " << c.title << ": " << c.note << "\n";
            std::cerr << "tsf: the halves failed verification as a pair; nothing was written. Please report this with "
                         "the input file.\n";
            throw CLI::RuntimeError(kExitCheckFailed);
        }
        text += "  halves    each verified (closed, manifold, outward, heights read back, nothing overhangs: no "
                "supports); joined they are the whole model less the pin holes (volume within " +
                formatSignificant(std::fabs(f.volume_error_mm3), 2) + " mm^3, surface within " + formatSignificant(f.max_distance_mm, 2) +
                " mm); the holes admit one way of joining only\n";
    }
    const Bounds bu = meshBounds(p.upper), bl = meshBounds(p.lower);
    text += "  pieces    upper " + formatFixed(bu.max.z - bu.min.z, 1) + " mm tall, lower " + formatFixed(bl.max.z - bl.min.z, 1) +
            " mm tall, each flat side down; " + std::to_string(kPinCount) + " pins standing\n";
    j["upper_height_mm"] = bu.max.z - bu.min.z;
    j["lower_height_mm"] = bl.max.z - bl.min.z;
    j["upper_volume_mm3"] = signedVolume(p.upper);
    j["lower_volume_mm3"] = signedVolume(p.lower);
    j["pins_volume_mm3"] = signedVolume(p.pins);
    summary.halves = j;
    summary.halves_text = text;
    return p;
}

void writeHalves(const HalvesPieces& p, const std::string& output, const MeshWriteOptions& wo, GenSummary& summary) {
    const HalvesPaths paths = halvesPaths(output);
    writeMesh(p.upper, paths.upper, wo);
    writeMesh(p.lower, paths.lower, wo);
    writeMesh(p.pins, paths.pins, wo);
    summary.outputs.push_back({paths.upper, "upper half, cut face down"});
    summary.outputs.push_back({paths.lower, "lower half, cut face down (turned over about the x axis)"});
    summary.outputs.push_back({paths.pins, std::to_string(kPinCount) + " pins, standing"});
    summary.halves["files"] = {{"upper", paths.upper}, {"lower", paths.lower}, {"pins", paths.pins}};
}

Mesh halvesSideBySide(const HalvesPieces& p) {
    constexpr double kGapMm = 10;
    const Bounds bu = meshBounds(p.upper), bl = meshBounds(p.lower);
    Mesh m = append({}, p.upper, 0);
    m = append(std::move(m), p.lower, bu.max.x + kGapMm - bl.min.x);
    return append(std::move(m), p.pins, bu.max.x + kGapMm + (bl.max.x - bl.min.x) + kGapMm);
}

std::string supportsText(const VerifyReport& r) {
    if (!r.printability || r.printability->overhang_area_mm2 <= 0) return "";
    return "  supports  needed: " + formatFixed(r.printability->overhang_area_mm2, 0) +
           " mm^2 of the underside overhangs up to " + formatFixed(r.printability->overhang_max_height_mm, 1) +
           " mm above the bed, and supports would scar the surface a reader feels; --halves prints it in two "
           "support-free halves (docs/printing.md)\n";
}

}  // namespace tsf::cli
