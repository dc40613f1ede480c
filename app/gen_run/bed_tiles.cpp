#include "app/gen_run/bed_tiles.h"

#include <vector>

#include "app/bed_size.h"
#include "app/gen_run/model_request.h"
#include "app/printer_fit.h"
#include "app/tiles_output.h"
#include "gen/util/error.h"

namespace tsf::cli {

std::optional<VerifiedTiles> tilesForBed(const GenCommandOptions& o, const HexField& field, const Scene& scene,
                                         const ModelRequest& rq, StageTimer& timer, GenSummary& summary) {
    std::optional<VerifiedTiles> tiles;
    if (!o.printer.tile) return tiles;
    const BedSize bed = parseBedSize(o.printer.bed, "--bed", /*need_height=*/false);
    // Each tile is fitted by the tiling itself: no bed check on its mesh.
    ModelRequest trq = rq;
    trq.on_mesh = nullptr;
    try {
        tiles = makeVerifiedTiles(field, scene, bed.width_mm - 2 * kBedMarginMm, bed.depth_mm - 2 * kBedMarginMm, trq,
                                  [&](const std::string& stage) { timer.begin(stage.c_str()); });
    } catch (const ModelVerificationFailed& e) {
        refuseUnverified(e, timer);
    }
    if (tiles->tiles.size() == 1) {
        // It fits the bed as it is: one piece, as without --tile.
        summary.printer_notes.push_back("the model fits the bed: written in one piece, not tiled");
        tiles.reset();
        return tiles;
    }
    for (const VerifiedTile& t : tiles->tiles)
        if (tilePath(o.output, sceneTile(t.scene)->place) == o.gen.input)
            throw InputError(o.output, 0, 0, "a tile would be written over the input: give another -o");
    summarizeTiles(*tiles, summary);
    return tiles;
}

}  // namespace tsf::cli
