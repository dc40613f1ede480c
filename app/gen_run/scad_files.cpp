#include "app/gen_run/scad_files.h"

#include <cstdio>
#include <string>
#include <vector>

#include "gen/scad/scad_render_cost.h"

namespace tsf::cli {

void writeScadFiles(const GenCommandOptions& o, const ScadOptions& so, const Scene& scene, GenSummary& summary) {
    writeScad(scene, so, o.scad);
    const std::string slow = scadRenderWarning(estimateScadRender(scene, so.strategy), o.scad);
    if (!slow.empty()) std::fprintf(stderr, "tsf: warning: %s\n", slow.c_str());
    const std::vector<std::string> paths = scadOutputPaths(so, o.scad);
    for (size_t k = 0; k < paths.size(); ++k)
        summary.outputs.push_back({paths[k], k == 0 ? "OpenSCAD"
                                             : so.write_parameter_sets && k == 1 ? "OpenSCAD parameter sets, openscad -p"
                                                                                 : "OpenSCAD library"});
}

}  // namespace tsf::cli
