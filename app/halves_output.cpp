// The halves and pins of `tsf gen --mirror --halves`. See halves_output.h.
#include "app/halves_output.h"

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "app/commands.h"
#include "gen/model/features/halves.h"
#include "gen/util/number_format.h"

namespace tsf::cli {
namespace {

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

void summarizeHalves(const VerifiedHalves& p, GenSummary& summary) {
    nlohmann::json j;
    std::string text;
    if (p.pair) {
        j["upper"] = toJson(*p.upper_report);
        j["lower"] = toJson(*p.lower_report);
        j["pin"] = toJson(*p.pin_report);
        nlohmann::json checks = nlohmann::json::array();
        for (const Check& c : p.pair->checks) checks.push_back({{"id", c.id}, {"status", toString(c.status)}, {"note", c.note}});
        const HalvesJoinFigures& f = p.pair->figures;
        j["pair"] = {{"checks", checks},
                     {"upper_volume_mm3", f.upper_volume_mm3},
                     {"lower_volume_mm3", f.lower_volume_mm3},
                     {"whole_volume_mm3", f.whole_volume_mm3},
                     {"holes_volume_mm3", f.holes_volume_mm3},
                     {"volume_error_mm3", f.volume_error_mm3},
                     {"max_distance_mm", f.max_distance_mm},
                     {"samples", f.samples}};
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
}

void writeHalves(const VerifiedHalves& p, const std::string& output, const MeshWriteOptions& wo, GenSummary& summary) {
    const HalvesPaths paths = halvesPaths(output);
    writeMesh(p.upper, paths.upper, wo);
    writeMesh(p.lower, paths.lower, wo);
    writeMesh(p.pins, paths.pins, wo);
    summary.outputs.push_back({paths.upper, "upper half, cut face down"});
    summary.outputs.push_back({paths.lower, "lower half, cut face down (turned over about the x axis)"});
    summary.outputs.push_back({paths.pins, std::to_string(kPinCount) + " pins, standing"});
    summary.halves["files"] = {{"upper", paths.upper}, {"lower", paths.lower}, {"pins", paths.pins}};
}

Mesh halvesSideBySide(const VerifiedHalves& p) {
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
