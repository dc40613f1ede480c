// Coverage: how much of the printed field a session touched - the share of
// the Scene's kept cells (every pillar that is printed) over which the probe
// was in contact with the surface at least once, from the force log.
//
// A cell counts as touched when a logged tick has the contact flag
// (force_model.h) and the probe's x, z lie over that cell's hexagon
// (printed_relief.h gives the relief grid's geometry). The force log must
// hold the whole session for the figure to be complete (a full log drops
// ticks and undercounts).
#pragma once

#include <cstdint>

#include "gen/model/scene.h"
#include "haptics/field_mapping.h"
#include "haptics/force_log.h"
#include "haptics/printed_relief.h"

namespace tsf::haptics {

struct Coverage {
    int64_t cells = 0;    ///< kept cells of the Scene
    int64_t touched = 0;  ///< of those, touched at least once
    double fraction() const { return cells > 0 ? double(touched) / double(cells) : 0.0; }
};

Coverage touchedCells(const Scene& scene, const ReliefInfo& relief, const FieldMapping& mapping, const ForceLog& log);

}  // namespace tsf::haptics
