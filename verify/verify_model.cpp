// verifyModel: runs the check families in order. See verify_model.h.
#include "verify/verify_model.h"

#include <chrono>
#include <future>
#include <memory>
#include <system_error>

#include "verify/column_grid.h"
#include "verify/readback.h"
#include "verify/attachment_readback.h"
#include "verify/solid_checks.h"
#include "verify/tactile.h"
#include "verify/tilt_readback.h"

namespace tsf {
namespace {

template <class Result>
void append(VerifyReport& report, Result&& r) {
    for (Check& c : r.checks) report.checks.push_back(std::move(c));
    for (Stage& s : r.stages) report.stages.push_back(std::move(s));
}

// The tactile checks read the mesh and the Scene and nothing the other
// checks make, so on a model up to this many triangles they run on a thread
// of their own beside the solid, read-back and printability checks: each of
// those stages keeps its cores only part of the time on a small model
// (100 x 100: about 1.5 of 2 cores), and the tactile checks fill the rest.
// Above it they run after the others, once the column grid is freed: their
// memory then never adds to the grid's (a 1000 x 1000 model's peak).
constexpr size_t kTactileAlongsideTriangles = 1'000'000;

TactileResult tactileChecks(const Mesh& mesh, const Scene* scene, const VerifyOptions& options) {
    TactileOptions to;
    to.max_offenders = options.max_offenders;
    to.layer_mm = options.layer_mm;
    to.sample_mm = options.tactile_sample_mm;
    to.nozzle_mm = options.nozzle_mm;
    TactileResult tr = checkTactile(mesh, scene, to);
    if (options.tactile_as_warnings)
        for (Check& c : tr.checks)
            if (c.status == CheckStatus::Fail) {
                c.status = CheckStatus::Warn;
                c.note += " (tsf verify --tactile lists the places)";
            }
    return tr;
}

}  // namespace

VerifyReport verifyModel(const Mesh& mesh, const Scene* scene, const VerifyOptions& options) {
    const auto t0 = std::chrono::steady_clock::now();
    VerifyReport report;
    report.exact = options.exact;

    // Started first when it runs alongside; its checks and stages still
    // come last in the report, as when it runs after.
    std::future<TactileResult> tactile;
    if (options.tactile && mesh.triangleCount() <= kTactileAlongsideTriangles) {
        try {
            tactile = std::async(std::launch::async, tactileChecks, std::cref(mesh), scene, std::cref(options));
        } catch (const std::system_error&) {
            // No thread to be had: they run after the others.
        }
    }

    SolidOptions so;
    so.exact = options.exact;
    so.max_offenders = options.max_offenders;
    so.self_intersections = options.self_intersections;
    so.pieces_allowed = options.pieces_allowed;
    SolidResult solid = checkSolid(mesh, so);
    report.mesh = std::move(solid.mesh);
    report.mesh.name = options.name.empty() ? "(in memory)" : options.name;
    report.mesh.read_notes = options.read_notes;
    const bool closed_oriented = solid.closed_oriented_manifold;
    // One column grid for every check that needs one: the self-intersections'
    // broad phase (checkSolid built it after the topology, so the two never
    // hold memory at once), the values read back and the printability rays;
    // freed before the tactile checks.
    std::unique_ptr<ColumnGrid> caster = std::move(solid.grid);
    append(report, std::move(solid));
    if (!caster && (scene || options.printability)) {
        // Without printability, only the heights read back ask: down and up.
        caster = std::make_unique<ColumnGrid>(mesh, ColumnGrid::kTrianglesPerColumn,
                                              options.printability ? ColumnGrid::Rays::Any : ColumnGrid::Rays::Vertical);
        report.stages.push_back({"grid", caster->buildMs()});
    }

    if (scene) {
        ReadbackOptions ro;
        ro.height_tolerance_mm = options.height_tolerance_mm;
        ro.max_offenders = options.max_offenders;
        ReadbackResult rb = readBack(mesh, *scene, *caster, ro);
        report.readback = std::move(rb.figures);
        append(report, std::move(rb));
        append(report, readBackAttachments(mesh, *scene, *caster, options.max_offenders));
        TiltReadbackResult tb = readBackTilt(mesh, *scene, *caster);
        if (!tb.checks.empty()) {
            report.tilt = std::move(tb.figures);
            append(report, std::move(tb));
        }
    }

    if (options.reference) {
        AgreementOptions ao;
        ao.distance_tolerance_mm = options.distance_tolerance_mm;
        ao.max_offenders = options.max_offenders;
        ao.fail_on_warnings = options.fail_on_warnings;
        AgreementResult ag = compareMeshes(mesh, *options.reference, options.reference_name, ao);
        report.agreement = std::move(ag.figures);
        append(report, std::move(ag));
    }

    if (options.printability) {
        PrintabilityOptions po;
        po.nozzle_mm = options.nozzle_mm;
        po.layer_mm = options.layer_mm;
        po.bed_mm = options.bed_mm;
        po.fail_on_warnings = options.fail_on_warnings;
        po.max_offenders = options.max_offenders;
        PrintabilityResult pr = checkPrintability(mesh, closed_oriented, *caster, po);
        report.printability = std::move(pr.figures);
        append(report, std::move(pr));
    }
    caster.reset();  // the tactile checks need no rays: its memory is free for theirs

    if (tactile.valid()) append(report, tactile.get());
    else if (options.tactile) append(report, tactileChecks(mesh, scene, options));

    report.total_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    return report;
}

}  // namespace tsf
