#include "app/printer_fit.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "app/bed_size.h"
#include "gen/model/attachments.h"
#include "gen/util/error.h"
#include "gen/field/resample.h"
#include "gen/field/hex_grid.h"
#include "gen/util/number_format.h"

namespace tsf::cli {
std::vector<std::string> applyPrinterFit(const PrinterSpec& printer, const GivenOptions& given, GenOptions& gen) {
    std::vector<std::string> notes;
    SceneParams& p = gen.scene;
    if (!printer.bed.empty()) {
        const BedSize bed = parseBedSize(printer.bed, "--bed", /*need_height=*/false);
        const double w = bed.width_mm - 2 * kBedMarginMm, d = bed.depth_mm - 2 * kBedMarginMm;
        if (!(w > 0) || !(d > 0))
            throw InputError("--bed " + printer.bed + ": a bed must be larger than twice the " + formatSignificant(kBedMarginMm, 4) +
                             " mm margin kept on each side");
        if (printer.tile) {
            notes.push_back("cut into tiles that each fit the " + formatSignificant(bed.width_mm, 4) + " x " +
                            formatSignificant(bed.depth_mm, 4) + " mm bed less " + formatSignificant(kBedMarginMm, 4) +
                            " mm on each side (--tile)");
        } else if (given.width && p.fit_width_mm > w)
            throw InputError("--width " + formatSignificant(p.fit_width_mm, 4) + " mm does not fit the " + formatSignificant(bed.width_mm, 4) +
                             " mm bed less " + formatSignificant(kBedMarginMm, 4) + " mm on each side: give --width " + formatSignificant(w, 4) +
                             " or less, or leave it out");
        if (given.depth && p.fit_depth_mm > d && !printer.tile)
            throw InputError("--depth " + formatSignificant(p.fit_depth_mm, 4) + " mm does not fit the " + formatSignificant(bed.depth_mm, 4) +
                             " mm bed less " + formatSignificant(kBedMarginMm, 4) + " mm on each side: give --depth " + formatSignificant(d, 4) +
                             " or less, or leave it out");
        // What stands east or west of the pillars (gen/model/attachments.h):
        // the pillars get the rest of the width.
        const std::vector<SideWidth> sides = attachmentSideWidths(p);
        double beside_mm = 0;
        std::string beside;
        for (const SideWidth& side : sides) {
            beside_mm += side.width_mm;
            beside += (beside.empty() ? "" : ", ") + side.what + " " + formatSignificant(side.width_mm, 4) + " mm";
        }
        if (!given.width && !printer.tile) {
            // The pillars keep at least a quarter of the width, and 20 mm.
            const bool room = w - beside_mm >= std::max(20.0, 0.25 * w);
            p.fit_width_mm = gen.fit_width_mm = room ? w - beside_mm : w;
            if (beside_mm > 0 && room)
                notes.push_back("the pillars get " + formatSignificant(w - beside_mm, 4) + " mm of the width, " + beside);
        }
        if (!given.depth && !printer.tile) p.fit_depth_mm = gen.fit_depth_mm = d;
        if ((!given.width || !given.depth) && !printer.tile)
            notes.push_back("fitted into " + formatSignificant(p.fit_width_mm, 4) + " x " + formatSignificant(p.fit_depth_mm, 4) + " mm: the " +
                            formatSignificant(bed.width_mm, 4) + " x " + formatSignificant(bed.depth_mm, 4) + " mm bed less " + formatSignificant(kBedMarginMm, 4) +
                            " mm on each side");
    }
    if ((printer.nozzle_mm > 0 || printer.layer_mm > 0) && !given.max_slope && p.tilt != TiltSource::None) {
        // The steepest top whose rim is still a nozzle wide one layer below
        // its edge (see kDefaultMaxSlopeDeg), for this printer.
        const double nozzle = printer.nozzle_mm > 0 ? printer.nozzle_mm : kDefaultSlopeNozzleMm;
        const double layer = printer.layer_mm > 0 ? printer.layer_mm : kDefaultSlopeLayerMm;
        p.max_slope_deg = std::min(kMaxSlopeLimitDeg, maxSlopeDegFor(nozzle, layer));
        notes.push_back("tilted tops lean at most " + formatSignificant(p.max_slope_deg, 3) + " degrees (one " +
                        formatSignificant(layer, 4) + " mm layer below a rim it is still a " +
                        formatSignificant(nozzle, 4) + " mm nozzle wide; --max-slope to choose)");
    }
    if (printer.nozzle_mm > 0) {
        const double min_cell = kCellNozzleWidths * printer.nozzle_mm;
        gen.min_cell_mm = std::max(kMinTactileCellMm, min_cell);
        if (min_cell > kMinTactileCellMm)
            notes.push_back("raster cells at least " + formatSignificant(min_cell, 4) + " mm (" + formatSignificant(kCellNozzleWidths, 4) + " widths of the " +
                            formatSignificant(printer.nozzle_mm, 4) + " mm nozzle)");
    }
    if (printer.layer_mm > 0) {
        p.printer_layer_mm = printer.layer_mm;
        if (given.snap) {
            if (std::fabs(std::remainder(p.z_snap_mm, printer.layer_mm)) > 1e-9 &&
                std::fabs(std::remainder(printer.layer_mm, p.z_snap_mm)) > 1e-9)
                notes.push_back("--snap " + formatSignificant(p.z_snap_mm, 4) + " mm is not a multiple of the " + formatSignificant(printer.layer_mm, 4) +
                                " mm layer: some steps will print a layer higher or lower");
        } else {
            // The options the user gave are the ones an error names.
            if (p.base_mm < printer.layer_mm)
                throw InputError("--layer " + formatSignificant(printer.layer_mm, 4) + " with --base " +
                                 formatSignificant(p.base_mm, 4) +
                                 ": the base must be at least one layer thick; give a --base of at least " +
                                 formatSignificant(printer.layer_mm, 4) + " mm or a thinner --layer");
            p.z_snap_mm = printer.layer_mm;
            notes.push_back("heights snapped to whole " + formatSignificant(printer.layer_mm, 4) + " mm layers (--snap to choose)");
        }
    }
    return notes;
}

std::string cellNozzleNote(double pitch_mm, const PrinterSpec& printer) {
    const double min_cell = kCellNozzleWidths * printer.nozzle_mm;
    if (!(printer.nozzle_mm > 0) || pitch_mm >= min_cell) return "";
    return "cells " + formatSignificant(pitch_mm, 4) + " mm across are narrower than " + formatSignificant(kCellNozzleWidths, 4) + " widths of the " +
           formatSignificant(printer.nozzle_mm, 4) + " mm nozzle (" + formatSignificant(min_cell, 4) +
           " mm): pillars print as blobs of perimeters (a larger --cell, or fewer --bins)";
}

bool shrinkFitToBed(const Scene& scene, const PrinterSpec& printer, GenOptions& gen) {
    if (printer.bed.empty() || printer.tile || gen.scene.pitch_mm > 0 || scene.keptCount() == 0) return false;
    const BedSize bed = parseBedSize(printer.bed, "--bed", /*need_height=*/false);
    const double w = bed.width_mm - 2 * kBedMarginMm, d = bed.depth_mm - 2 * kBedMarginMm;
    const BoxMm f = sceneFootprint(scene);
    const double over_w = f.x1 - f.x0 - w, over_d = f.y1 - f.y0 - d;
    if (over_w <= 0 && over_d <= 0) return false;
    // Round the overflow up to 0.01 mm so the next fit lands inside.
    if (over_w > 0) gen.scene.fit_width_mm = std::max(1.0, gen.scene.fit_width_mm - std::ceil(over_w * 100) / 100 - 0.01);
    if (over_d > 0) gen.scene.fit_depth_mm = std::max(1.0, gen.scene.fit_depth_mm - std::ceil(over_d * 100) / 100 - 0.01);
    // The field is resampled for the same box (gen/field/resample.h).
    gen.fit_width_mm = gen.scene.fit_width_mm;
    gen.fit_depth_mm = gen.scene.fit_depth_mm;
    return true;
}

void checkFitsBed(const Mesh& mesh, const Scene& scene, const PrinterSpec& printer, bool cell_given, double min_cell_mm,
                  const SizeAtCell& size_at) {
    if (printer.bed.empty() || mesh.positions.empty()) return;
    const BedSize bed = parseBedSize(printer.bed, "--bed", /*need_height=*/false);
    const double w = bed.width_mm - 2 * kBedMarginMm, d = bed.depth_mm - 2 * kBedMarginMm;
    const Bounds b = meshBounds(mesh);
    const double mw = b.max.x - b.min.x, md = b.max.y - b.min.y;
    if (mw <= w && md <= d) return;
    const auto fits = [&](const std::optional<std::pair<double, double>>& size) {
        return size && size->first <= w && size->second <= d;
    };
    // The pillars scale with the cell; what stands beside them (the
    // orientation tab, the scale, the legend's plate) does not. The pillars'
    // own extent at this cell, from the kept cells' hexagons:
    int64_t i_lo = INT64_MAX, i_hi = INT64_MIN, j_lo = INT64_MAX, j_hi = INT64_MIN;
    for (size_t k = 0; k < scene.keptCount(); ++k) {
        const LatticePoint c = hexCentre(scene.grid, scene.col[k], scene.row[k]);
        i_lo = std::min(i_lo, c.i - 1), i_hi = std::max(i_hi, c.i + 1);
        j_lo = std::min(j_lo, c.j - 2), j_hi = std::max(j_hi, c.j + 2);
    }
    const double pw = scene.keptCount() ? latticeX({i_hi - i_lo, 0}, scene.pitch_mm) : mw;
    const double pd = scene.keptCount() ? latticeY({0, j_hi - j_lo}, scene.pitch_mm, scene.y_scale) : md;
    const double fw = std::max(0.0, mw - pw), fd = std::max(0.0, md - pd);
    const std::string what = "the model is " + formatSignificant(mw, 4) + " x " + formatSignificant(md, 4) + " mm, larger than the " +
                             formatSignificant(bed.width_mm, 4) + " x " + formatSignificant(bed.depth_mm, 4) + " mm bed less " +
                             formatSignificant(kBedMarginMm, 4) + " mm on each side (" + formatSignificant(w, 4) + " x " +
                             formatSignificant(d, 4) + " mm)";
    const double min_cell = std::max(kMinTactileCellMm, min_cell_mm);
    if (cell_given && size_at) {
        // The largest cell that fits, rounded down to 0.01 mm, from the
        // pillars' share; then tried, and smaller by 1 % until a model at it
        // fits. Never below the smallest cell a fingertip tells apart.
        const double scale = std::min(pw > 0 ? (w - fw) / pw : 0.0, pd > 0 ? (d - fd) / pd : 0.0);
        double cell = std::floor(scene.pitch_mm * scale * 100.0) / 100.0;
        for (int tries = 0; tries < 8 && cell >= min_cell; ++tries, cell = std::floor(cell * 0.99 * 100.0) / 100.0)
            if (fits(size_at(cell)))
                throw InputError(what + "; give --cell " + formatSignificant(cell, 4) + " or less (tried: it fits), or leave --cell out " +
                                 "to fit the bed, or add --tile to print it in tiles that each fit");
    }
    // No cell a fingertip reads makes it fit (or tsf chose the cell): the bed it needs, at the smallest cell.
    std::optional<std::pair<double, double>> smallest;
    if (size_at && scene.pitch_mm > min_cell + 1e-9) smallest = size_at(min_cell);
    const double need_w = smallest ? smallest->first : mw, need_d = smallest ? smallest->second : md;
    const std::string at = smallest ? "at --cell " + formatSignificant(min_cell, 4) + ", the smallest a fingertip tells apart, it is " +
                                          formatSignificant(need_w, 4) + " x " + formatSignificant(need_d, 4) + " mm"
                                    : std::string(scene.pitch_mm <= min_cell + 1e-9 ? "its cells are the smallest a fingertip tells apart (" +
                                                                                          formatSignificant(min_cell, 4) + " mm)"
                                                                                    : "");
    // What stands beside the pillars, to 0.1 mm (the pillars' hexagons and the model's bounds differ by float noise).
    const double side_w = std::round(fw * 10) / 10, side_d = std::round(fd * 10) / 10;
    std::string beside;
    if (side_w > 0 || side_d > 0)
        beside = "; what stands beside the pillars (the orientation tab, the scale, the legend) takes " +
                 (side_w > 0 ? formatSignificant(side_w, 4) + " mm of the width" : std::string()) +
                 (side_w > 0 && side_d > 0 ? " and " : "") +
                 (side_d > 0 ? formatSignificant(side_d, 4) + " mm of the depth" : std::string()) +
                 " whatever the cell: leaving out --scale or --title/--units gives the pillars more";
    const double bed_w = std::ceil(need_w + 2 * kBedMarginMm), bed_d = std::ceil(need_d + 2 * kBedMarginMm);
    throw InputError(what + (at.empty() ? "" : "; " + at) + ": it needs a bed of at least " + formatSignificant(bed_w, 4) + " x " +
                     formatSignificant(bed_d, 4) + " mm (--bed " + formatSignificant(bed_w, 4) + "x" + formatSignificant(bed_d, 4) +
                     "), or --tile to print it in tiles that each fit" + beside);
}

}  // namespace tsf::cli
