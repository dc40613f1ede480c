#include "app/gen_run/bed_fit.h"

#include <optional>
#include <utility>

#include "app/printer_fit.h"
#include "gen/model/attachments.h"
#include "gen/model/build_scene.h"
#include "gen/readers/load_field.h"
#include "gen/util/error.h"

namespace tsf::cli {

Scene buildSceneForBed(GenCommandOptions& o, HexField& field) {
    Scene scene = buildScene(field, o.gen.scene);
    for (int again = 0; again < 6 && shrinkFitToBed(scene, o.printer, o.gen); ++again) {
        field = loadField(o.gen);
        scene = buildScene(field, o.gen.scene);
    }
    return scene;
}

void checkMeshFitsBed(const GenCommandOptions& o, const Scene& scene, const Mesh& mesh) {
    if (o.printer.tile) return;
    checkFitsBed(mesh, scene, o.printer, o.gen.cell_mm > 0, o.gen.min_cell_mm,
                 [&](double cell_mm) -> std::optional<std::pair<double, double>> {
                     // The model made again at that cell: the field (a raster is
                     // resampled for its cell) and the Scene, as asked otherwise.
                     GenOptions at = o.gen;
                     at.cell_mm = at.scene.pitch_mm = cell_mm;
                     try {
                         const BoxMm f = sceneFootprint(buildScene(loadField(at), at.scene));
                         return std::make_pair(f.x1 - f.x0, f.y1 - f.y0);
                     } catch (const InputError&) {
                         return std::nullopt;
                     }
                 });
}

}  // namespace tsf::cli
