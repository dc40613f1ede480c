#include "gen/scad/scad_joined.h"

#include <cassert>
#include <unordered_set>

#include "gen/field/hex_grid.h"
#include "gen/mesh_io/number_text.h"
#include "gen/model/scene.h"

namespace tsf {
namespace {

// Writes items as a list, `per_line` to a line.
template <class Item>
void appendRows(std::string& o, size_t count, size_t per_line, const std::string& indent, const Item& item) {
    o += "[";
    for (size_t k = 0; k < count; ++k) {
        o += k % per_line == 0 ? "\n" + indent : " ";
        item(k);
        if (k + 1 < count) o += ",";
    }
    o += count ? "\n" + indent.substr(0, indent.size() >= 2 ? indent.size() - 2 : 0) + "]" : "]";
}

}  // namespace

bool scadCanJoin(const Scene& s, const Attachment& a) {
    if (!a.ring_walls.empty() || a.joined.mesh.triangles.empty()) return false;
    const int64_t lattice = latticeVertexIdCount(s.grid);
    for (const int64_t id : a.joined.lattice_id)
        if (id >= lattice) return false;
    if (s.faces.empty()) return true;
    // The library draws a face's walls without the contacts' heights: a
    // contact whose corner is on a face's ring is left to the union.
    std::unordered_set<int64_t> on_rings;
    for (const PlanarFace& f : s.faces.faces)
        for (const auto& ring : f.rings) on_rings.insert(ring.begin(), ring.end());
    for (const WallContact& c : a.walls) {
        if (!s.drawn_by_face.empty() && s.drawn_by_face[size_t(c.kept)]) return false;
        for (const int e : {c.edge, (c.edge + 1) % kHexCorners})
            if (on_rings.count(hexCornerId(s.grid, s.col[size_t(c.kept)], s.row[size_t(c.kept)], e))) return false;
    }
    return true;
}

std::string scadJoinedData(const Scene& s, const Attachment& a, const std::string& indent) {
    assert(scadCanJoin(s, a));
    const Mesh& body = a.joined.mesh;
    // The body's own points first, then its lattice corners.
    std::vector<size_t> own, corners;
    for (size_t v = 0; v < body.positions.size(); ++v) (a.joined.lattice_id[v] >= 0 ? corners : own).push_back(v);
    std::vector<size_t> index(body.positions.size());
    for (size_t k = 0; k < own.size(); ++k) index[own[k]] = k;
    for (size_t k = 0; k < corners.size(); ++k) index[corners[k]] = own.size() + k;

    std::string o = "[\n" + indent + "// walls [col, row, edge, bottom, top] (z steps)\n" + indent;
    appendRows(o, a.walls.size(), 6, indent + "  ", [&](size_t k) {
        const WallContact& c = a.walls[k];
        o += "[" + std::to_string(s.col[size_t(c.kept)]) + ", " + std::to_string(s.row[size_t(c.kept)]) + ", " +
             std::to_string(c.edge) + ", " + std::to_string(c.bottom_units) + ", " + std::to_string(c.top_units) + "]";
    });
    o += ",\n" + indent + "// points [x, y, z] (mm)\n" + indent;
    appendRows(o, own.size(), 4, indent + "  ", [&](size_t k) {
        const Vec3& p = body.positions[own[k]];
        mesh_io::appendPoint(o, p.x, p.y, p.z);
    });
    o += ",\n" + indent + "// corners [i, j, z] (lattice units, z steps)\n" + indent;
    appendRows(o, corners.size(), 6, indent + "  ", [&](size_t k) {
        const size_t v = corners[k];
        const LatticePoint p = latticeVertexPoint(s.grid, a.joined.lattice_id[v]);
        o += "[" + std::to_string(p.i) + ", " + std::to_string(p.j) + ", " +
             std::to_string(snapUnits(body.positions[v].z, s.z_snap_mm)) + "]";
    });
    o += ",\n" + indent + "// triangles, counter-clockwise from outside\n" + indent;
    appendRows(o, body.triangles.size(), 8, indent + "  ", [&](size_t k) {
        const auto& t = body.triangles[k];
        o += "[" + std::to_string(index[t[0]]) + ", " + std::to_string(index[t[1]]) + ", " + std::to_string(index[t[2]]) + "]";
    });
    o += "\n]";
    return o;
}

std::string scadJoinedAssert(const Scene& s, const std::string& show_switch, const std::string& what) {
    std::string values = "[";
    mesh_io::appendShortest(values, s.pitch_mm);
    values += ", ";
    mesh_io::appendShortest(values, s.z_snap_mm);
    values += s.params.bottom == Bottom::Mirrored ? ", true]" : ", false]";
    return "assert(!" + show_switch + " || [cell, snap, mirror] == " + values + ",\n       \"" + what +
           " was placed by tsf for the cell, snap and mirror it wrote: set " + show_switch +
           " = false, or run tsf gen again to change them\");\n\n";
}

}  // namespace tsf
