#include "gen/mesh_io/off_writer.h"

#include <ostream>

#include "gen/util/atomic_file.h"
#include "gen/mesh_io/mesh_write_checks.h"
#include "gen/mesh_io/text_lines.h"

namespace tsf {

using mesh_io::appendPositionLine;
using mesh_io::appendTriangleLine;
using mesh_io::flushText;
using mesh_io::checkMeshForWriting;
using mesh_io::printableTitle;

void writeOff(const Mesh& mesh, std::ostream& out, const std::string& title) {
    std::string text = "OFF\n# " + printableTitle(title) + "\n";
    text += std::to_string(mesh.positions.size()) + " " + std::to_string(mesh.triangles.size()) + " 0\n";
    for (const Vec3& p : mesh.positions) {
        appendPositionLine(text, "", p);
        flushText(text, out);
    }
    for (const auto& tri : mesh.triangles) {
        appendTriangleLine(text, "3 ", tri, 0);
        flushText(text, out);
    }
    flushText(text, out, /*force=*/true);
}

void writeOff(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts) {
    checkMeshForWriting(mesh, path, /*float32_format=*/false);
    writeFileAtomically(path, [&](std::ostream& out) { writeOff(mesh, out, opts.title); });
}

}  // namespace tsf
