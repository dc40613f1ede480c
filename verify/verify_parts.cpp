// verifyParts: every part alone, then the assembly. See verify_parts.h.
#include "verify/verify_parts.h"

#include <chrono>

#include "verify/assembly_checks.h"
#include "verify/attachment_readback.h"
#include "verify/readback.h"
#include "verify/tilt_readback.h"
#include "verify/column_grid.h"

namespace tsf {
namespace {

template <class Result>
void append(VerifyReport& report, Result&& r) {
    for (Check& c : r.checks) report.checks.push_back(std::move(c));
    for (Stage& s : r.stages) report.stages.push_back(std::move(s));
}

bool isSolid(const VerifyReport& r) {
    for (const char* id : {"valid_input", "closed", "manifold_edges", "manifold_vertices", "consistent_orientation",
                           "degenerate_faces", "self_intersections", "outward_orientation"}) {
        const Check* c = r.find(id);
        if (!c || c->status != CheckStatus::Pass) return false;
    }
    return true;
}

}  // namespace

bool PartsVerifyReport::passed() const {
    for (const PartReport& p : parts)
        if (!p.report.passed()) return false;
    return assembly.passed();
}

PartsVerifyReport verifyParts(const std::vector<MeshPart>& parts, const Scene* scene, const VerifyOptions& options) {
    const auto t0 = std::chrono::steady_clock::now();
    PartsVerifyReport out;
    const std::string file = options.name.empty() ? "(in memory)" : options.name;
    std::vector<bool> solid;
    for (size_t k = 0; k < parts.size(); ++k) {
        VerifyOptions po = options;
        po.name = file + " part " + std::to_string(k + 1) + " of " + std::to_string(parts.size()) + ": " + parts[k].name;
        po.read_notes.clear();
        po.reference = nullptr;
        po.pieces_allowed = k > 0;
        // Printability is a property of what prints: the body alone here; a part standing on it
        // (a dome alone is thin at its rim) is judged with it in the one-solid model.
        po.printability = options.printability && k == 0;
        // Self-intersections are the precondition of the exact overlap test: never skipped here.
        po.self_intersections = true;
        VerifyReport r = verifyModel(parts[k].mesh, nullptr, po);
        solid.push_back(isSolid(r));
        out.parts.push_back({parts[k].name, std::move(r)});
    }

    VerifyReport& a = out.assembly;
    a.exact = options.exact;
    const Mesh joined = joinParts(parts);
    MeshSummary& m = a.mesh;
    m.name = file + " (" + std::to_string(parts.size()) + " parts together)";
    m.read_notes = options.read_notes;
    m.vertex_count = joined.vertexCount();
    m.triangle_count = joined.triangleCount();
    m.bounds = meshBounds(joined);
    m.signed_volume_mm3 = signedVolume(joined);
    for (const PartReport& p : out.parts) {
        m.volume_mm3 += p.report.mesh.volume_mm3;  // NaN when a part is not a closed solid
        m.area_mm2 += p.report.mesh.area_mm2;
        m.edge_count += p.report.mesh.edge_count;
        m.component_count += p.report.mesh.component_count;
    }
    append(a, checkAssembly(parts, solid, options.max_offenders));
    if (scene) {
        ColumnGrid caster(joined);
        a.stages.push_back({"grid", caster.buildMs()});
        ReadbackOptions ro;
        ro.height_tolerance_mm = options.height_tolerance_mm;
        ro.max_offenders = options.max_offenders;
        ReadbackResult rb = readBack(joined, *scene, caster, ro);
        a.readback = std::move(rb.figures);
        append(a, std::move(rb));
        append(a, readBackAttachments(joined, *scene, caster, options.max_offenders));
        TiltReadbackResult tb = readBackTilt(joined, *scene, caster);
        if (!tb.checks.empty()) {
            a.tilt = std::move(tb.figures);
            append(a, std::move(tb));
        }
    }
    a.total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

std::string formatPartsReport(const PartsVerifyReport& r) {
    std::string o;
    for (size_t k = 0; k < r.parts.size(); ++k) {
        o += "=== part " + std::to_string(k + 1) + " of " + std::to_string(r.parts.size()) + ": " + r.parts[k].name + "\n";
        o += formatReport(r.parts[k].report) + "\n";
    }
    o += "=== assembly: the " + std::to_string(r.parts.size()) + " parts together\n";
    o += formatReport(r.assembly);
    o += std::string("\nparts: ") + (r.passed() ? "PASSED" : "FAILED") + " (" + std::to_string(r.parts.size()) +
         " parts, each checked alone, and the assembly)\n";
    return o;
}

nlohmann::json toJson(const PartsVerifyReport& r) {
    nlohmann::json parts = nlohmann::json::array();
    for (const PartReport& p : r.parts) parts.push_back({{"name", p.name}, {"report", toJson(p.report)}});
    return {{"format", "tsf-verify-parts-report"},
            {"version", 1},
            {"passed", r.passed()},
            {"parts", parts},
            {"assembly", toJson(r.assembly)}};
}

}  // namespace tsf
