#include "app/gen_run/model_request.h"

#include <cstdio>
#include <iostream>

#include "app/commands.h"
#include "app/gen_run/bed_fit.h"
#include "app/gen_run/model_files.h"

namespace tsf::cli {

ModelRequest modelRequest(const GenCommandOptions& o, const Scene& scene) {
    ModelRequest rq;
    rq.verify = !o.no_verify;
    rq.verify_full = o.verify_full;
    rq.parts = o.parts;
    rq.stored_as_float32 = o.gen.scene.stored_as_float32;
    rq.verify_options.name = o.output.empty() ? o.scad : o.output;
    if (o.printer.nozzle_mm > 0) rq.verify_options.nozzle_mm = o.printer.nozzle_mm;
    if (o.printer.layer_mm > 0) rq.verify_options.layer_mm = o.printer.layer_mm;
    const bool quick = rq.verify && !rq.verify_full;
    rq.on_mesh = [&o, &scene, quick](const Mesh& mesh) {
        checkMeshFitsBed(o, scene, mesh);
        if (quick && mesh.triangleCount() > kQuickVerifyTriangles)
            std::fprintf(stderr, "tsf: %zu triangles: verifying topology and heights only (--verify-full for all checks)\n",
                         mesh.triangleCount());
    };
    // The model file is written (to its temporary file in the run's
    // OutputSet) while the model is verified: at 1000 x 1000 the 0.5 GB STL
    // takes about a second to convert, write and sync, on the disk more than
    // on the cores the checks use. Committed with the run's other files only
    // once every check has passed.
    // The pipeline writes none ahead for parts or halves; with --tile the
    // model may still be cut into tiles after it is made.
    if (rq.verify && !o.output.empty() && !o.printer.tile)
        rq.write_ahead = [&o](const Mesh& mesh) { writeMesh(mesh, o.output, modelWriteOptions(o)); };
    return rq;
}

void refuseUnverified(const ModelVerificationFailed& e, StageTimer& timer) {
    timer.end();
    std::cerr << e.report();
    std::cerr << "tsf: the " << e.piece() << " failed verification; nothing was written. "
                 "Please report this with the input file.\n";
    throw CLI::RuntimeError(kExitCheckFailed);
}

VerifiedModel makeModelOrRefuse(const Scene& scene, const ModelRequest& rq, StageTimer& timer) {
    try {
        return makeVerifiedModel(scene, rq, [&](const std::string& stage) { timer.begin(stage.c_str()); });
    } catch (const ModelVerificationFailed& e) {
        refuseUnverified(e, timer);
    }
}

}  // namespace tsf::cli
