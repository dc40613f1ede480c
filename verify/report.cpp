// VerifyReport printing and JSON. See report.h.
#include "verify/report.h"

#include "gen/util/number_format.h"

#include <cmath>
#include <sstream>

#include "verify/detail/format.h"

namespace tsf {

using detail::fmtMm;
using detail::fmtNum;
using detail::fmtPoint;

const char* toString(CheckStatus s) {
    switch (s) {
        case CheckStatus::Pass: return "pass";
        case CheckStatus::Fail: return "fail";
        case CheckStatus::Warn: return "warn";
        default: return "skipped";
    }
}

bool VerifyReport::passed() const { return countStatus(CheckStatus::Fail) == 0; }

size_t VerifyReport::countStatus(CheckStatus s) const {
    size_t n = 0;
    for (const Check& c : checks) n += c.status == s;
    return n;
}

const Check* VerifyReport::find(const std::string& id) const {
    for (const Check& c : checks)
        if (c.id == id) return &c;
    return nullptr;
}

namespace {

const char* label(CheckStatus s) {
    switch (s) {
        case CheckStatus::Pass: return "PASS";
        case CheckStatus::Fail: return "FAIL";
        case CheckStatus::Warn: return "WARN";
        default: return "SKIP";
    }
}

std::string fmtMs(double ms) { return formatFixed(ms, ms < 10 ? 1 : 0) + " ms"; }

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }
nlohmann::json point(const Vec3& p) { return nlohmann::json::array({num(p.x), num(p.y), num(p.z)}); }

}  // namespace

std::string formatReport(const VerifyReport& r) {
    std::ostringstream o;
    const MeshSummary& m = r.mesh;
    o << "model: " << (m.name.empty() ? "(in memory)" : m.name) << "\n";
    o << "  " << m.triangle_count << " triangles, " << m.vertex_count << " vertices, "
      << m.component_count << (m.component_count == 1 ? " piece" : " pieces") << "\n";
    if (m.triangle_count) {
        o << "  size " << fmtMm(m.bounds.max.x - m.bounds.min.x) << " x " << fmtMm(m.bounds.max.y - m.bounds.min.y)
          << " x " << fmtMm(m.bounds.max.z - m.bounds.min.z) << " mm, from " << fmtPoint(m.bounds.min) << " to "
          << fmtPoint(m.bounds.max) << "\n";
        o << "  volume " << (std::isnan(m.volume_mm3) ? "n/a (not a closed oriented solid; signed sum " +
                                                            fmtNum(m.signed_volume_mm3) + ")"
                                                      : fmtNum(m.volume_mm3))
          << " mm^3, area " << fmtNum(m.area_mm2) << " mm^2\n";
    }
    for (const std::string& n : m.read_notes) o << "  read: " << n << "\n";
    if (r.exact) o << "  kernel: exact constructions (Epeck)\n";
    o << "\n";

    for (const Check& c : r.checks) {
        o << label(c.status) << "  " << c.title;
        if (c.status == CheckStatus::Fail || c.status == CheckStatus::Warn) o << ": " << c.count;
        if (!c.note.empty()) o << " - " << c.note;
        o << "\n";
        for (const Offender& w : c.worst) {
            o << "        ";
            if (std::isfinite(w.at_mm.x)) o << "at " << fmtPoint(w.at_mm) << ": ";
            o << w.detail << "\n";
        }
        if (c.count > int64_t(c.worst.size()) && !c.worst.empty())
            o << "        ... and " << (c.count - int64_t(c.worst.size())) << " more\n";
    }

    if (r.readback) {
        const ReadbackFigures& b = *r.readback;
        o << "\nvalues read back: " << b.cells_checked << " cells, " << b.surfaces_checked << " surfaces; max error "
          << fmtNum(b.max_error_mm) << " mm (mean " << fmtNum(b.mean_error_mm) << "), tolerance " << fmtNum(b.tolerance_mm)
          << " mm; max value error " << fmtNum(b.max_value_error) << " data units (mean " << fmtNum(b.mean_value_error)
          << ")\n";
    }
    if (r.agreement) {
        const AgreementFigures& a = *r.agreement;
        o << "\nagreement with " << a.reference << ": "
          << (!a.surfaces_compared   ? std::string("surfaces not compared exactly")
              : a.surfaces_identical ? "surfaces identical (exact, " + std::to_string(a.planes) + " planes)"
              : a.differing_planes   ? "surfaces differ in " + std::to_string(a.differing_planes) + " of " +
                                         std::to_string(a.planes) + " planes"
                                     : "same surface, facing the other way in " + std::to_string(a.opposite_planes) +
                                         " of " + std::to_string(a.planes) + " planes")
          << (a.rounded_to.empty() ? std::string() : ", the same within " + fmtNum(a.rounding_bound_mm) +
                                                          " mm rounded to " + a.rounded_to)
          << "; Hausdorff " << fmtNum(a.hausdorff_to_reference_mm) << " mm (to) / "
          << fmtNum(a.hausdorff_from_reference_mm) << " mm (from), +" << fmtNum(a.hausdorff_error_bound_mm)
          << " mm at most, " << a.samples << " samples; tolerance " << fmtNum(a.distance_tolerance_mm)
          << " mm; volume " << fmtNum(a.volume_mm3) << " vs " << fmtNum(a.reference_volume_mm3) << " mm^3\n";
    }
    if (r.printability) {
        const PrintabilityFigures& p = *r.printability;
        o << "\nprintability (nozzle " << fmtMm(p.nozzle_mm) << " mm, layer " << fmtMm(p.layer_mm) << " mm): thinnest wall "
          << fmtMm(p.min_wall_mm) << " mm, narrowest gap " << fmtMm(p.min_gap_mm) << " mm, thinnest slab "
          << fmtMm(p.min_slab_mm) << " mm, overhang " << fmtNum(p.overhang_area_mm2) << " mm^2 up to "
          << fmtMm(p.overhang_max_height_mm) << " mm above the bed\n";
    }

    o << "\ntime:";
    for (const Stage& st : r.stages) o << " " << st.name << " " << fmtMs(st.time_ms);
    o << "\n";

    const size_t fails = r.countStatus(CheckStatus::Fail), warns = r.countStatus(CheckStatus::Warn);
    const size_t passes = r.countStatus(CheckStatus::Pass), skips = r.countStatus(CheckStatus::Skipped);
    o << "\nresult: " << (fails ? "FAIL" : "PASS") << " - ";
    if (fails) o << fails << " failed, ";
    o << passes << " passed";
    if (warns) o << ", " << warns << (warns == 1 ? " warning" : " warnings");
    if (skips) o << ", " << skips << " skipped";
    o << " (" << fmtMs(r.total_ms) << ")\n";
    return o.str();
}

nlohmann::json toJson(const VerifyReport& r) {
    using nlohmann::json;
    json j;
    j["format"] = "tsf-verify-report";
    j["version"] = 1;
    j["passed"] = r.passed();
    j["exact"] = r.exact;
    j["total_ms"] = r.total_ms;

    const MeshSummary& m = r.mesh;
    j["mesh"] = {
        {"name", m.name},
        {"vertices", m.vertex_count},
        {"triangles", m.triangle_count},
        {"edges", m.edge_count},
        {"bounds_mm", {{"min", point(m.bounds.min)}, {"max", point(m.bounds.max)}}},
        {"size_mm", point({m.bounds.max.x - m.bounds.min.x, m.bounds.max.y - m.bounds.min.y, m.bounds.max.z - m.bounds.min.z})},
        {"volume_mm3", num(m.volume_mm3)},
        {"signed_volume_mm3", num(m.signed_volume_mm3)},
        {"area_mm2", num(m.area_mm2)},
        {"components", m.component_count},
        {"unreferenced_vertices", m.unreferenced_vertices},
        {"duplicate_position_vertices", m.duplicate_position_vertices},
        {"read_notes", m.read_notes},
    };

    json checks = json::array();
    for (const Check& c : r.checks) {
        json worst = json::array();
        for (const Offender& w : c.worst)
            worst.push_back({{"at_mm", point(w.at_mm)}, {"amount", num(w.amount)}, {"detail", w.detail}});
        checks.push_back({{"id", c.id},
                          {"title", c.title},
                          {"status", toString(c.status)},
                          {"count", c.count},
                          {"unit", c.unit},
                          {"note", c.note},
                          {"stage", c.stage},
                          {"time_ms", c.time_ms},
                          {"worst", worst}});
    }
    j["checks"] = checks;

    json stages = json::array();
    for (const Stage& s : r.stages) stages.push_back({{"name", s.name}, {"time_ms", s.time_ms}});
    j["stages"] = stages;

    if (r.readback) {
        const ReadbackFigures& b = *r.readback;
        json worst = json::array();
        for (const CellReadback& c : b.worst)
            worst.push_back({{"col", c.col}, {"row", c.row}, {"x_mm", c.x_mm}, {"y_mm", c.y_mm}, {"surface", c.surface},
                             {"expected_mm", num(c.expected_mm)}, {"measured_mm", num(c.measured_mm)},
                             {"error_mm", num(c.error_mm)}, {"value", num(c.value)}, {"value_read", num(c.value_read)},
                             {"value_error", num(c.value_error)}});
        j["readback"] = {
            {"cells_checked", b.cells_checked},
            {"surfaces_checked", b.surfaces_checked},
            {"missed", b.missed},
            {"over_tolerance", b.over_tolerance},
            {"tolerance_mm", b.tolerance_mm},
            {"height_step_tolerance_mm", b.height_step_tolerance_mm},
            {"float32_rounding_mm", b.float32_rounding_mm},
            {"max_error_mm", num(b.max_error_mm)},
            {"mean_error_mm", num(b.mean_error_mm)},
            {"max_value_error", num(b.max_value_error)},
            {"mean_value_error", num(b.mean_value_error)},
            {"outside_cells_checked", b.outside_cells_checked},
            {"outside_cells_hit", b.outside_cells_hit},
            {"worst", worst},
        };
    }
    if (r.tilt) {
        const TiltReadbackFigures& t = *r.tilt;
        j["tilt"] = {{"cells_checked", t.cells_checked}, {"missed", t.missed}, {"over_tolerance", t.over_tolerance},
                     {"max_error_top", t.max_error_top}, {"max_error_bottom", t.max_error_bottom},
                     {"max_top_bottom", t.max_top_bottom}, {"max_tolerance", t.max_tolerance},
                     {"max_slope", t.max_slope}, {"worst", t.worst}};
    }
    if (r.agreement) {
        const AgreementFigures& a = *r.agreement;
        j["agreement"] = {
            {"reference", a.reference},
            {"reference_triangles", a.reference_triangles},
            {"volume_mm3", num(a.volume_mm3)},
            {"reference_volume_mm3", num(a.reference_volume_mm3)},
            {"volume_difference_mm3", num(a.volume_difference_mm3)},
            {"volume_tolerance_mm3", num(a.volume_tolerance_mm3)},
            {"hausdorff_to_reference_mm", num(a.hausdorff_to_reference_mm)},
            {"hausdorff_from_reference_mm", num(a.hausdorff_from_reference_mm)},
            {"hausdorff_error_bound_mm", num(a.hausdorff_error_bound_mm)},
            {"distance_tolerance_mm", num(a.distance_tolerance_mm)},
            {"surfaces_compared", a.surfaces_compared},
            {"surfaces_identical", a.surfaces_identical},
            {"planes", a.planes},
            {"differing_planes", a.differing_planes},
            {"opposite_planes", a.opposite_planes},
            {"differing_area_mm2", num(a.differing_area_mm2)},
            {"reference_differing_area_mm2", num(a.reference_differing_area_mm2)},
            {"rounded_to", a.rounded_to.empty() ? json(nullptr) : json(a.rounded_to)},
            {"rounding_bound_mm", num(a.rounding_bound_mm)},
            {"samples", a.samples},
            {"sample_budget", a.sample_budget},
        };
    }
    if (r.printability) {
        const PrintabilityFigures& p = *r.printability;
        j["printability"] = {
            {"nozzle_mm", num(p.nozzle_mm)},
            {"layer_mm", num(p.layer_mm)},
            {"min_wall_mm", num(p.min_wall_mm)},
            {"min_gap_mm", num(p.min_gap_mm)},
            {"min_slab_mm", num(p.min_slab_mm)},
            {"bed_mm", p.bed_mm ? point(*p.bed_mm) : json(nullptr)},
            {"fits_bed", p.fits_bed},
            {"fits_bed_rotated", p.fits_bed_rotated},
            {"overhang_area_mm2", num(p.overhang_area_mm2)},
            {"overhang_max_height_mm", num(p.overhang_max_height_mm)},
        };
    }
    return j;
}

}  // namespace tsf
