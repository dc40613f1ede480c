#include "gen/scad/scad_attachments.h"

#include "gen/scad/scad_halves.h"
#include "gen/scad/scad_legend.h"
#include "gen/scad/scad_scale.h"
#include "gen/scad/scad_tab.h"

namespace tsf {

std::vector<ScadAttachment> scadAttachments(const Scene& scene, bool join) {
    std::vector<ScadAttachment> out;
    for (std::optional<ScadAttachment> a :
         {scadLegend(scene, join), scadScale(scene, join), scadTab(scene, join), scadHalves(scene)})
        if (a) out.push_back(std::move(*a));
    return out;
}

}  // namespace tsf
