// Printer fit: `tsf gen --bed WxD --nozzle D --layer H` shape the model's
// defaults for one printer, and a model larger than the bed is refused.
//
// Rules (docs/printing.md, "Printer fit"):
//   - --bed: without --width/--depth the grid is fitted into the bed less
//     kBedMarginMm on every side (room for the slicer's skirt and for taking
//     the print off); a --width or --depth larger than that is refused. A
//     model that still does not fit (a --cell too large) is refused after
//     meshing, with the largest --cell that fits. With --tile the model keeps
//     its size and is cut into tiles that each fit (gen/model/features/tiles.h).
//   - --nozzle: a pillar narrower than kCellNozzleWidths nozzle widths is a
//     blob of perimeters, not a hexagon; the default cell for rasters is at
//     least that wide (never below the 3 mm tactile minimum), and narrower
//     cells (--cell, --bins) get a note. The verifier's wall and gap checks use it.
//   - --layer: without --snap, heights snap to whole layers, so each value
//     step the model shows is one the printer prints; the verifier's base
//     check uses it.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "app/gen_options.h"
#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"

namespace tsf::cli {

/// Free space kept between the model and each edge of the bed, mm.
inline constexpr double kBedMarginMm = 5.0;
/// Narrowest pillar, in nozzle widths: two perimeters on each side.
inline constexpr double kCellNozzleWidths = 4.0;

struct PrinterSpec {
    std::string bed;       ///< --bed "WxD" as given; "" = no bed
    double nozzle_mm = 0;  ///< --nozzle; 0 = not given
    double layer_mm = 0;   ///< --layer; 0 = not given
    bool tile = false;     ///< --tile: a model larger than the bed is cut into tiles (gen/model/features/tiles.h), not fitted
};

/// Which model options the user gave himself (the printer never overrides them).
struct GivenOptions {
    bool width = false, depth = false, snap = false, max_slope = false;
};

/// Shapes `gen` for the printer before the field is loaded; returns what it
/// changed, one line each, for the summary. Throws InputError for a bad
/// --bed or a --width/--depth larger than the bed.
std::vector<std::string> applyPrinterFit(const PrinterSpec& printer, const GivenOptions& given, GenOptions& gen);

/// A note when cells pitch_mm across are narrower than kCellNozzleWidths
/// nozzle widths; "" when they are not or no nozzle was given.
std::string cellNozzleNote(double pitch_mm, const PrinterSpec& printer);

/// With --bed and the cell left to tsf: when what stands beside the pillars
/// (the legend's plate, the tab, the scale) takes the model past the bed,
/// shrinks the fit box by the overflow (gen.scene.fit_width_mm,
/// fit_depth_mm, and the field's own) and returns true: the field is then
/// read again (a raster resampled to fewer cells, never narrower than the
/// tactile minimum) and the Scene built again.
bool shrinkFitToBed(const Scene& scene, const PrinterSpec& printer, GenOptions& gen);

/// The x, y size (mm) of the whole model (pillars and what stands beside
/// them) made at --cell cell_mm, everything else as asked; none when no
/// model can be made at that cell.
using SizeAtCell = std::function<std::optional<std::pair<double, double>>(double cell_mm)>;

/// After meshing: throws InputError when the mesh's footprint is larger
/// than the bed less its margins, saying what does fit, each remedy tried
/// (size_at) rather than guessed: with a --cell given (cell_given), the
/// largest --cell at or above min_cell_mm (the smallest a fingertip tells
/// apart) that fits; never a cell below it. Else, and when no such cell
/// fits: the bed the model needs, --tile, and what stands beside the
/// pillars (the tab, the scale, the legend), whose size no cell changes.
void checkFitsBed(const Mesh& mesh, const Scene& scene, const PrinterSpec& printer, bool cell_given, double min_cell_mm,
                  const SizeAtCell& size_at);

}  // namespace tsf::cli
