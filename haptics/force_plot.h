// A picture of a haptic session for a sighted helper or researcher: the
// field seen from above with the probe's path and the force felt along it.
//
// Layout: north at the top, east to the right (the same orientation as the
// input raster). The field is drawn in grey, dark = low, light = high. The
// path is drawn on top: a thin light-blue trace where the probe was in the
// air, and dots coloured by force magnitude where it touched (blue = light
// touch, through green and yellow, to red = the force limit). A colour bar on
// the right is labelled 0 and the limit in newtons, and a legend beside it
// says what the trace and the dots are. A title, when given, is drawn at the
// top. The picture is at most about 2300 x 2100 pixels for any grid. Points
// outside the field's footprint are clipped to the picture's edge.
#pragma once

#include <string>

#include "haptics/field_mapping.h"
#include "haptics/force_log.h"
#include "haptics/height_grid.h"

namespace tsf::haptics {

struct PlotOptions {
    int max_field_px = 720;  ///< longer side of the field part of the picture (64..2048), whatever the grid's size
    std::string title;       ///< drawn at the top; "" = none
};

/// Writes the picture as an 8-bit RGB PNG, atomically. Throws
/// tsf::InputError for an unusable folder, tsf::OutputError when it cannot be written.
void writeForcePlotPng(const std::string& path, const HeightGrid& grid, const FieldMapping& mapping,
                       const ForceLog& log, double max_force_N, const PlotOptions& options = {});

/// The colour of a force fraction in [0, 1] (clamped), as 0xRRGGBB.
uint32_t forceColour(double fraction);

}  // namespace tsf::haptics
