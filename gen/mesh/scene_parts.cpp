#include "gen/mesh/scene_parts.h"

#include <map>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/features/legend_join.h"
#include "gen/model/features/orientation_tab.h"
#include "gen/model/features/scale.h"

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
    // region (the raise is the marks part), with the legend's plate but not
    // its dots (the legend part).
    Scene level = scene;
    std::vector<const PlanarFace*> raised;
    for (size_t k = 0; k < scene.faces.faces.size(); ++k)
        if (scene.faces.faces[k].raise_units > 0) {
            raised.push_back(&scene.faces.faces[k]);
            level.faces.faces[k].raise_units = 0;
        }
    level.scale.reset();  // the scale is a part of its own, touching the pillars' east walls
    level.marks.tab.reset();  // the tab too, touching their west walls
    if (level.legend) level.legend->layout.dots.clear();
    parts.push_back({"pillars", meshScene(level)});

    // Every raised face (the orientation triangle in the data) or the
    // orientation tab in one part.
    std::vector<MeshPart> prisms;
    for (const PlanarFace* f : raised) prisms.push_back({"", raisedFacePrism(scene, *f)});
    if (scene.marks.tab) prisms.push_back({"", meshTabBody(scene, /*joined=*/false).mesh});
    if (!prisms.empty()) parts.push_back({"marks", joinParts(prisms)});
    if (scene.legend) parts.push_back({"legend", legendDotsMesh(scene)});
    if (scene.scale) parts.push_back({"scale", meshScaleBody(scene, /*joined=*/false).mesh});
    return parts;
}

}  // namespace tsf
