// See verified_tiles.h.
#include "pipeline/verified_tiles.h"

#include "gen/mesh/direct_mesher.h"
#include "gen/model/attachments.h"
#include "gen/model/build_scene.h"

namespace tsf {

std::string tilesCheckText(const TilesCheckResult& r) {
    std::string text;
    for (const Check& c : r.checks) text += std::string(toString(c.status)) + "  " + c.title + ": " + c.note + "\n";
    return text;
}

VerifiedTiles makeVerifiedTiles(const HexField& field, const Scene& whole, double width_mm,
                                double depth_mm, const ModelRequest& rq,
                                const std::function<void(const std::string&)>& progress) {
    VerifiedTiles out;
    if (progress) progress("tiling");
    out.layout = planTiles(whole, attachmentBoxes(whole), width_mm, depth_mm);
    const TileLayout& L = out.layout;
    for (int32_t t = 0; t < L.rows * L.cols; ++t) {
        if (L.cells[size_t(t)] == 0) continue;
        VerifiedTile tile;
        tile.scene = buildScene(field, tileParams(whole, L, t));
        ModelRequest trq = rq;
        trq.verify_options.name = rq.verify_options.name + " (tile " + tileName(sceneTile(tile.scene)->place) + ")";
        try {
            tile.model = makeVerifiedModel(tile.scene, trq, progress);
        } catch (const ModelVerificationFailed& e) {
            throw ModelVerificationFailed("tile " + tileName(sceneTile(tile.scene)->place), e.report());
        }
        out.tiles.push_back(std::move(tile));
    }
    if (rq.verify) {
        if (progress) progress("verifying tiles");
        // The model the tiles make up: the whole, with the cells the codes
        // are under left level as in the tiles.
        SceneParams level = whole.params;
        TiledWholeRequest tiled;
        tiled.level_cells.assign(size_t(whole.grid.cellCount()), 0);
        for (const VerifiedTile& t : out.tiles)
            for (int32_t k : sceneTile(t.scene)->code_cells)
                tiled.level_cells[size_t(whole.grid.index(t.scene.col[size_t(k)], t.scene.row[size_t(k)]))] = 1;
        level.requests.set(std::move(tiled));
        const Scene assembled = buildScene(field, level);
        const Mesh assembled_mesh = meshScene(assembled);
        std::vector<const Scene*> scenes;
        std::vector<const Mesh*> meshes;
        for (const VerifiedTile& t : out.tiles) {
            scenes.push_back(&t.scene);
            meshes.push_back(&t.model.mesh);
        }
        out.assembly = checkTiles(assembled, assembled_mesh, scenes, meshes, {width_mm, depth_mm, L.seams, L.bare_seams, L.teeth});
        if (!out.assembly->passed()) throw ModelVerificationFailed("tiles as an assembly", tilesCheckText(*out.assembly));
    }
    return out;
}

}  // namespace tsf
