#include "gen/mesh/scene_parts.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/attachments.h"

namespace tsf {
namespace {

// The prism over a raised face: its top at faceTop, its bottom on the top of
// the region it stands on (faceTop - raise_units). Ring vertices are made
// once per height, so the walls and the caps share them (no T-junctions).
Mesh raisedFacePrism(const Scene& s, const PlanarFace& f) {
    Mesh m;
    const int64_t top = s.faceTop(f), bottom = top - f.raise_units;
    std::map<std::pair<int64_t, int64_t>, uint32_t> index;  // (planar id, z units) -> vertex
    auto vertex = [&](int64_t id, int64_t z) {
        const auto [it, fresh] = index.try_emplace({id, z}, uint32_t(m.positions.size()));
        if (fresh) m.positions.push_back(s.planarPoint(id, z));
        return it->second;
    };
    for (const auto& t : f.triangles) {
        m.triangles.push_back({vertex(t[0], top), vertex(t[1], top), vertex(t[2], top)});           // CCW from above
        m.triangles.push_back({vertex(t[0], bottom), vertex(t[2], bottom), vertex(t[1], bottom)});  // CCW from below
    }
    // Rings run with the face on their left: the outward normal of edge v -> w is (w - v) x up.
    for (const auto& ring : f.rings)
        for (size_t n = 0; n < ring.size(); ++n) {
            const int64_t v = ring[n], w = ring[(n + 1) % ring.size()];
            m.triangles.push_back({vertex(v, bottom), vertex(w, bottom), vertex(w, top)});
            m.triangles.push_back({vertex(v, bottom), vertex(w, top), vertex(v, top)});
        }
    return m;
}

}  // namespace

std::vector<MeshPart> meshSceneParts(const Scene& scene) {
    std::vector<MeshPart> parts;
    if (scene.keptCount() == 0) return parts;
    // The pillars: the same Scene with every raised face brought down to its
    // region (the raise is the marks part), with what of the attachments
    // stays with them (the legend's plate, not its dots).
    Scene level = scene;
    std::vector<const PlanarFace*> raised;
    for (size_t k = 0; k < scene.faces.faces.size(); ++k)
        if (scene.faces.faces[k].raise_units > 0) {
            raised.push_back(&scene.faces.faces[k]);
            level.faces.faces[k].raise_units = 0;
        }
    // What of the attachments stays with the pillars, and their own pieces,
    // made once (they do not depend on the faces' raise).
    std::vector<Attachment> attachments = sceneAttachments(level, Assembly::Parts);
    parts.push_back({"pillars", meshScene(level, attachments)});

    // Every raised face (the orientation triangle in the data) in the marks
    // part, then each attachment's own piece in the part it names; pieces
    // of one name are one part, in the order the names first come.
    std::vector<std::pair<std::string, std::vector<MeshPart>>> pieces;
    const auto add = [&](const std::string& part, Mesh mesh) {
        auto at = std::find_if(pieces.begin(), pieces.end(), [&](const auto& p) { return p.first == part; });
        if (at == pieces.end()) at = pieces.insert(pieces.end(), {part, {}});
        at->second.push_back({"", std::move(mesh)});
    };
    for (const PlanarFace* f : raised) add("marks", raisedFacePrism(scene, *f));
    for (Attachment& a : attachments)
        if (!a.own_part.triangles.empty()) add(a.part, std::move(a.own_part));
    for (auto& [name, meshes] : pieces) parts.push_back({name, joinParts(meshes)});
    return parts;
}

}  // namespace tsf
