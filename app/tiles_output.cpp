// The tiles of `tsf gen --tile`. See tiles_output.h.
#include "app/tiles_output.h"

#include <algorithm>
#include <filesystem>

#include "app/commands.h"
#include "gen/model/feature_registry.h"
#include "gen/util/number_format.h"

namespace tsf::cli {

std::string tilePath(const std::string& output, const TilePlace& t) {
    const std::filesystem::path p(output);
    return ((p.parent_path() / p.stem()).string()) + "-tile-" + std::to_string(t.row + 1) + "-" + std::to_string(t.col + 1) +
           p.extension().string();
}

std::vector<std::string> tilePaths(const VerifiedTiles& v, const std::string& output) {
    std::vector<std::string> out;
    for (const VerifiedTile& t : v.tiles) out.push_back(tilePath(output, sceneTile(t.scene)->place));
    return out;
}

namespace {

// "-tile-<digits>-<digits>" exactly.
bool isTilePlace(const std::string& text) {
    const std::string prefix = "-tile-";
    if (text.compare(0, prefix.size(), prefix) != 0) return false;
    const std::string rest = text.substr(prefix.size());
    const size_t dash = rest.find('-');
    if (dash == 0 || dash == std::string::npos || dash + 1 == rest.size()) return false;
    for (size_t k = 0; k < rest.size(); ++k)
        if (k != dash && (rest[k] < '0' || rest[k] > '9')) return false;
    return true;
}

}  // namespace

std::vector<std::string> removeStaleTiles(const std::string& output, const std::vector<std::string>& keep) {
    const std::filesystem::path p(output);
    const std::string stem = p.stem().string(), ext = p.extension().string();
    const std::filesystem::path folder = p.parent_path().empty() ? std::filesystem::path(".") : p.parent_path();
    std::vector<std::string> removed;
    std::error_code ec;
    for (std::filesystem::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= stem.size() + ext.size() || name.compare(0, stem.size(), stem) != 0 ||
            name.compare(name.size() - ext.size(), ext.size(), ext) != 0)
            continue;
        if (!isTilePlace(name.substr(stem.size(), name.size() - stem.size() - ext.size()))) continue;
        const std::string path = (p.parent_path() / name).string();
        bool kept = false;
        for (const std::string& k : keep) kept = kept || std::filesystem::path(k).filename() == name;
        std::error_code file_ec;
        if (kept || !it->is_regular_file(file_ec)) continue;
        if (std::filesystem::remove(it->path(), file_ec)) removed.push_back(path);
    }
    std::sort(removed.begin(), removed.end());
    return removed;
}

void summarizeTiles(const VerifiedTiles& v, GenSummary& summary) {
    const TileLayout& L = v.layout;
    nlohmann::json j;
    j["rows"] = L.rows;
    j["cols"] = L.cols;
    j["count"] = v.tiles.size();
    j["teeth"] = L.teeth;
    j["seams"] = L.seams;
    j["tooth_neck_cells"] = L.tooth_cells;
    std::string text = "  tiles     " + std::to_string(v.tiles.size()) + " tiles in " + std::to_string(L.rows) + " rows x " +
                       std::to_string(L.cols) + " columns (row 1 north, column 1 west), cut along the hexagons' edges: every pillar whole, "
                       "in one tile; " + std::to_string(L.teeth) + " dovetail teeth on " + std::to_string(L.seams) +
                       " seams (teeth east and south, sockets west and north)\n";
    nlohmann::json list = nlohmann::json::array();
    for (const VerifiedTile& t : v.tiles) {
        const Bounds b = meshBounds(t.model.mesh);
        const SceneTile& st = *sceneTile(t.scene);
        nlohmann::json one = {{"row", st.place.row + 1},
                              {"col", st.place.col + 1},
                              {"cells", t.scene.keptCount()},
                              {"size_mm", {b.max.x - b.min.x, b.max.y - b.min.y, b.max.z - b.min.z}},
                              {"volume_mm3", signedVolume(t.model.mesh)},
                              {"marks", carriedMarks(t.scene).has_value() || !t.scene.faces.faces.empty()},
                              {"code_pits", st.code_cells.size()},
                              {"code_pit_diameter_mm", 2 * st.pit_radius_mm}};
        if (t.model.report) one["verify"] = toJson(*t.model.report);
        list.push_back(one);
        text += "            tile " + std::to_string(st.place.row + 1) + "-" + std::to_string(st.place.col + 1) + ": " +
                formatFixed(b.max.x - b.min.x, 1) + " x " + formatFixed(b.max.y - b.min.y, 1) + " x " + formatFixed(b.max.z - b.min.z, 1) +
                " mm, " + std::to_string(t.scene.keptCount()) + " cells" +
                (st.code_cells.empty() ? ", no room for its code"
                                       : ", code: " + std::to_string(st.code_cells.size()) + " pits on the underside") +
                (one["marks"].get<bool>() ? ", carries the orientation marks" : "") + (t.model.report ? ", verified" : "") + "\n";
    }
    j["tiles"] = list;
    if (v.assembly) {
        nlohmann::json checks = nlohmann::json::array();
        for (const Check& c : v.assembly->checks) checks.push_back({{"id", c.id}, {"status", toString(c.status)}, {"note", c.note}});
        const TilesCheckFigures& f = v.assembly->figures;
        j["assembly"] = {{"checks", checks},
                         {"whole_volume_mm3", f.whole_volume_mm3},
                         {"tiles_volume_mm3", f.tiles_volume_mm3},
                         {"code_pits_volume_mm3", f.pits_volume_mm3},
                         {"volume_error_mm3", f.volume_error_mm3}};
        text += "  assembly  put together the tiles are the model: every cell in one tile at its height, volume within " +
                formatSignificant(std::fabs(f.volume_error_mm3), 2) + " mm^3 of the model's less the code pits; every tile fits the bed";
        for (const Check& c : v.assembly->checks)
            if (c.status == CheckStatus::Warn) text += "; " + c.note;
        text += "\n";
    }
    text += "  code      each tile's place is pitted into its underside as an L: a corner pit, then one pit per column "
            "number going east and one per row number going south (turned over about the west-east axis: north)\n";
    summary.tiles = j;
    summary.tiles_text = text;
}

void writeTiles(const VerifiedTiles& v, const std::string& output, const MeshWriteOptions& wo, GenSummary& summary) {
    nlohmann::json files = nlohmann::json::array();
    for (const VerifiedTile& t : v.tiles) {
        const std::string path = tilePath(output, sceneTile(t.scene)->place);
        writeMesh(t.model.mesh, path, wo);
        summary.outputs.push_back({path, "tile " + tileName(sceneTile(t.scene)->place)});
        files.push_back(path);
    }
    summary.tiles["files"] = files;
}

std::string tilesMarksSentence(const VerifiedTiles& v) {
    std::string carried, notch, triangle;
    for (const VerifiedTile& t : v.tiles) {
        const std::string name = "row " + std::to_string(sceneTile(t.scene)->place.row + 1) + ", column " +
                                 std::to_string(sceneTile(t.scene)->place.col + 1);
        if (carriedMarks(t.scene)) carried = name;
        if (t.scene.marks.notch) notch = name;
        if (t.scene.marks.triangle) triangle = name;
    }
    if (!carried.empty()) return "The orientation tab, with the notch and the triangle, is on the tile in " + carried + ".";
    std::string out;
    if (!notch.empty()) out += "The orientation notch is on the tile in " + notch + ".";
    if (!triangle.empty()) out += std::string(out.empty() ? "" : " ") + "The orientation triangle is on the tile in " + triangle + ".";
    return out.empty() ? "The model has no orientation marks." : out;
}

Mesh tilesApart(const VerifiedTiles& v) {
    constexpr double kGapMm = 8;
    Mesh m;
    for (const VerifiedTile& t : v.tiles) {
        const double dx = kGapMm * sceneTile(t.scene)->place.col, dy = -kGapMm * sceneTile(t.scene)->place.row;
        const uint32_t base = uint32_t(m.positions.size());
        for (const Vec3& p : t.model.mesh.positions) m.positions.push_back({p.x + dx, p.y + dy, p.z});
        for (const auto& tri : t.model.mesh.triangles) m.triangles.push_back({tri[0] + base, tri[1] + base, tri[2] + base});
    }
    return m;
}

}  // namespace tsf::cli
