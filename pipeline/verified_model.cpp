#include "pipeline/verified_model.h"

#include <future>
#include <system_error>

#include "gen/mesh/direct_mesher.h"
#include "gen/mesh/halves_mesh.h"
#include "gen/mesh/scene_parts.h"
#include "gen/mesh_io/float32_mesh.h"
#include "gen/model/features/halves.h"

namespace tsf {
namespace {

void say(const std::function<void(const std::string&)>& progress, const char* stage) {
    if (progress) progress(stage);
}

// One piece as it prints: the verifier's checks and no overhang at all (a
// half or a pin needs no supports).
VerifyReport verifyPiece(const Mesh& mesh, const Scene* scene, VerifyOptions vo, const std::string& name,
                         bool float32) {
    vo.name = name;
    VerifyReport r = verifyModel(float32 ? float32Mesh(mesh) : mesh, scene, vo);
    const Check* over = r.find("overhang");
    if (!r.passed() || (over && over->status != CheckStatus::Pass)) throw ModelVerificationFailed(name, formatReport(r));
    return r;
}

std::string pairText(const HalvesCheckResult& pair) {
    std::string text;
    for (const Check& c : pair.checks) text += std::string(toString(c.status)) + "  " + c.title + ": " + c.note + "\n";
    return text;
}

VerifiedHalves makeHalves(const Scene& scene, const Mesh& whole, const ModelRequest& rq) {
    VerifiedHalves h;
    h.upper = meshHalf(scene, HalfKind::Upper);
    h.lower = meshHalf(scene, HalfKind::Lower);
    h.pins = pinsMesh(scene.halves->pins);
    if (!rq.verify) return h;
    VerifyOptions vo = rq.verify_options;
    vo.self_intersections = true;
    vo.printability = true;
    const Scene upper_scene = halfScene(scene, HalfKind::Upper), lower_scene = halfScene(scene, HalfKind::Lower);
    const bool f32 = rq.stored_as_float32;
    h.upper_report = verifyPiece(h.upper, &upper_scene, vo, "upper half", f32);
    // The lower half is read back in halfScene's frame (its print turned back, a rigid motion away).
    h.lower_report = verifyPiece(turnLowerHalf(h.lower, scene), &lower_scene, vo, "lower half", f32);
    h.pin_report = verifyPiece(pinMesh(scene.halves->pins, 0, 0), nullptr, vo, "pin", f32);
    h.pair = checkHalves(scene, whole, h.upper, h.lower);
    if (!h.pair->passed()) throw ModelVerificationFailed("halves as a pair", pairText(*h.pair));
    return h;
}

// The whole of a model cut into halves is never printed in one piece: what
// prints is each half, flat side down, which makeHalves proved free of
// overhangs. The whole's overhang (its mirrored underside) then says nothing
// about supports; it would read as "supports needed" beside halves that need
// none.
void printedAsHalves(VerifyReport& whole) {
    for (Check& c : whole.checks) {
        if (c.id != "overhang" || c.status == CheckStatus::Pass || c.status == CheckStatus::Skipped) continue;
        c.status = CheckStatus::Pass;
        c.note = "printed as two halves, each flat side down with no overhang (checked with the halves); in one piece "
                 "it would need supports (" + c.note + ")";
        c.count = 0;
        c.worst.clear();
    }
}

}  // namespace

VerifiedModel makeVerifiedModel(const Scene& scene, const ModelRequest& rq,
                                const std::function<void(const std::string&)>& progress) {
    VerifiedModel m;
    say(progress, "meshing");
    m.mesh = meshScene(scene);
    if (rq.on_mesh) rq.on_mesh(m.mesh);
    if (rq.verify) {
        say(progress, "verifying");
        VerifyOptions vo = rq.verify_options;
        // The model as a hand reads it, as warnings (docs/tactile.md).
        vo.tactile = true;
        vo.tactile_as_warnings = true;
        // At verify's own sampling (vo.tactile_sample_mm as given): the same
        // code on the same samples, so gen's verdict is tsf verify's.
        if (!rq.verify_full && m.mesh.triangleCount() > kQuickVerifyTriangles) {
            vo.self_intersections = false;
            vo.printability = false;
            vo.tactile = false;
            m.quick = true;
        }
        // In parts, the file holds the parts, checked as float32 below; the
        // one solid is checked (and read back) as meshed. A file of float32
        // holds the mesh rounded to float32 and nothing else: the mesh is
        // rounded once, here, and that is what is checked and written (the
        // same bytes; one copy of the mesh instead of two, 320 MB at
        // 1000 x 1000).
        const bool whole_written = rq.stored_as_float32 && !rq.parts && !scene.halves;
        if (whole_written) m.mesh = float32Mesh(m.mesh);
        // The checks and the writing only read the mesh: they share it.
        std::future<void> ahead;
        if (rq.write_ahead && !rq.parts && !scene.halves) {
            try {
                ahead = std::async(std::launch::async, [&] { rq.write_ahead(m.mesh); });
            } catch (const std::system_error&) {
                // No thread to be had: the front end writes after the checks.
            }
        }
        try {
            m.report = verifyModel(m.mesh, &scene, vo);
        } catch (...) {
            if (ahead.valid()) ahead.wait();  // the mesh outlives the writer's reading of it
            throw;
        }
        if (ahead.valid()) ahead.wait();
        if (!m.report->passed()) throw ModelVerificationFailed("generated model", formatReport(*m.report));
        if (ahead.valid()) {
            ahead.get();
            m.written_ahead = true;
        }
    }
    if (rq.parts) {
        say(progress, "meshing parts");
        m.parts = meshSceneParts(scene);
        if (rq.verify) {
            // Each part alone and the parts together; the heights were read
            // back from the one-solid mesh above.
            say(progress, "verifying parts");
            VerifyOptions vo = rq.verify_options;
            vo.printability = false;
            if (rq.stored_as_float32) {
                std::vector<MeshPart> stored = m.parts;
                for (MeshPart& p : stored) p.mesh = float32Mesh(p.mesh);
                m.parts_report = verifyParts(stored, nullptr, vo);
            } else {
                m.parts_report = verifyParts(m.parts, nullptr, vo);
            }
            if (!m.parts_report->passed()) throw ModelVerificationFailed("model's parts", formatPartsReport(*m.parts_report));
        }
    }
    if (scene.halves) {
        say(progress, "halves");
        m.halves = makeHalves(scene, m.mesh, rq);
        if (m.report && m.halves->upper_report) printedAsHalves(*m.report);
    }
    return m;
}

}  // namespace tsf
