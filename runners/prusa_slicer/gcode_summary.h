// summarizeGcode: what a slicer's G-code says about the print, read from the
// comments PrusaSlicer (and Slic3r, SuperSlicer) write into it, never from
// the slicer's log.
//
// Read:
//   - ";LAYER_CHANGE" lines: one per printed layer (support layers that sit
//     between object layers count too, as the printer prints them);
//   - ";Z:<mm>": the height of each layer; the highest is max_z_mm;
//   - ";TYPE:Support material" and ";TYPE:Support material interface": the
//     slicer extruded support (has_support);
//   - the closing block: "; filament used [mm] = ", "[cm3]", "; total
//     filament used [g] = " and "; estimated printing time (normal mode) =
//     1d 2h 3m 4s";
//   - the configuration block: "; layer_height = ", "; first_layer_height = ",
//     "; nozzle_diameter = ", "; support_material = ".
// A value that is absent stays NaN (numbers) or -1 (counts); the caller says
// what a missing figure means. Units: mm, cm^3, g, s.
#pragma once

#include <istream>
#include <string>

namespace tsf {

struct GcodeSummary {
    int layers = 0;                ///< ";LAYER_CHANGE" lines
    double max_z_mm;               ///< highest ";Z:" (NaN when none)
    bool has_support = false;      ///< any support extrusion
    double filament_mm;            ///< filament length
    double filament_cm3;           ///< filament volume
    double filament_g;             ///< filament mass (0 when the slicer had no density)
    double print_time_s;           ///< the slicer's estimate, normal mode
    double layer_height_mm;        ///< the slicer's setting
    double first_layer_height_mm;  ///< the slicer's setting
    double nozzle_mm;              ///< the slicer's setting (first extruder)
    GcodeSummary();
};

/// Reads the G-code from `in` line by line (any size; nothing is kept but the figures).
GcodeSummary summarizeGcode(std::istream& in);

/// "7h 1m 55s", "1d 2h", "11m 24s", "45s" -> seconds; NaN when the text is not such a duration.
double parseSlicerDuration(const std::string& text);

/// Seconds -> "7 h 01 min" (or "11 min 24 s" below an hour), for reports.
std::string formatDuration(double seconds);

}  // namespace tsf
