#include "app/gen_run/run_preview.h"

#include <algorithm>
#include <string>

#include "app/halves_output.h"
#include "app/preview.h"
#include "app/tiles_output.h"
#include "gen/util/number_format.h"

namespace tsf::cli {

namespace {

// A piece's size for the picture's caption, whole mm: "W x D x H".
std::string pieceSize(const Mesh& m) {
    const Bounds b = meshBounds(m);
    return formatFixed(b.max.x - b.min.x, 0) + " x " + formatFixed(b.max.y - b.min.y, 0) + " x " +
           formatFixed(b.max.z - b.min.z, 0);
}

}  // namespace

void writeRunPreview(const GenCommandOptions& o, const HexField& field, const Scene& scene, const VerifiedModel& made,
                     const std::optional<VerifiedTiles>& tiles, GenSummary& summary) {
    const std::optional<VerifiedHalves>& halves = made.halves;
    // A series' pictures share one colour scale: from the bed to the
    // top of the common height scale (the same height, the same colour), mm.
    const double colour_top = o.series_count > 1 ? scene.zMm(scene.floor_units) + scene.mapping.max_height_mm : 0.0;
    if (halves) {
        writeModelPreview(halvesSideBySide(*halves), o.preview, false, colour_top,
                          "upper half " + pieceSize(halves->upper) + ", lower " + pieceSize(halves->lower) + " mm");
    } else if (tiles) {
        double w = 0, d = 0, h = 0;
        for (const auto& t : tiles->tiles) {
            const Bounds b = meshBounds(t.model.mesh);
            w = std::max(w, b.max.x - b.min.x), d = std::max(d, b.max.y - b.min.y), h = std::max(h, b.max.z - b.min.z);
        }
        writeModelPreview(tilesApart(*tiles), o.preview, false, colour_top,
                          std::to_string(tiles->tiles.size()) + " tiles, each at most " + formatFixed(w, 0) + " x " +
                              formatFixed(d, 0) + " x " + formatFixed(h, 0) + " mm");
    } else {
        writeModelPreview(made.mesh, o.preview, scene.params.bottom == Bottom::Mirrored, colour_top, "", 1200, 800,
                          field.input.categorical ? &scene : nullptr);
    }
    summary.outputs.push_back({o.preview, halves ? "preview picture of the pieces as they print"
                                          : tiles ? "preview picture of the tiles, drawn apart"
                                          : o.series_count > 1 ? "preview picture, coloured on the series' one height scale"
                                                               : "preview picture"});
}

}  // namespace tsf::cli
