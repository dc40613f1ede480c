#include "gen/mesh_io/obj_writer.h"

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

void writeObj(const Mesh& mesh, std::ostream& out, const std::string& title) {
    const std::string name = printableTitle(title);
    std::string text = "# " + name + "\no " + name + "\n";
    for (const Vec3& p : mesh.positions) {
        appendPositionLine(text, "v ", p);
        flushText(text, out);
    }
    for (const auto& tri : mesh.triangles) {
        appendTriangleLine(text, "f ", tri, 1);
        flushText(text, out);
    }
    flushText(text, out, /*force=*/true);
}

void writeObj(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts) {
    checkMeshForWriting(mesh, path, /*float32_format=*/false);
    writeFileAtomically(path, [&](std::ostream& out) { writeObj(mesh, out, opts.title); });
}

}  // namespace tsf
