#include "runners/prusa_slicer/print_check.h"

#include <cmath>
#include <cstdio>
#include <sstream>

#include "gen/util/error.h"
#include "gen/mesh_io/mesh_reader.h"

namespace tsf {
namespace {

std::string fixed(double v, int decimals) {
    if (!std::isfinite(v)) return "unknown";
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

nlohmann::json numberOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json sliceJson(const GcodeSummary& g) {
    return {{"layers", g.layers},
            {"max_z_mm", numberOrNull(g.max_z_mm)},
            {"support_extruded", g.has_support},
            {"print_time_s", numberOrNull(g.print_time_s)},
            {"filament_mm", numberOrNull(g.filament_mm)},
            {"filament_cm3", numberOrNull(g.filament_cm3)},
            {"filament_g", numberOrNull(g.filament_g)},
            {"layer_height_mm", numberOrNull(g.layer_height_mm)},
            {"first_layer_height_mm", numberOrNull(g.first_layer_height_mm)},
            {"nozzle_mm", numberOrNull(g.nozzle_mm)}};
}

std::string filament(const GcodeSummary& g) {
    return fixed(g.filament_mm / 1000.0, 2) + " m = " + fixed(g.filament_cm3, 2) + " cm3 = " + fixed(g.filament_g, 1) +
           " g";
}

}  // namespace

PrintCheckReport runPrintCheck(const std::string& model_path, const SlicerSettings& settings) {
    if (!(settings.layer_mm > 0) || !(settings.nozzle_mm > 0) || !(settings.filament_density_g_cm3 > 0) ||
        !(settings.bed_width_mm > 0) || !(settings.bed_depth_mm > 0))
        throw InputError("print check: layer height, nozzle, filament density and bed size must be positive");
    PrintCheckReport r;
    r.model = model_path;
    r.settings = settings;
    const Mesh mesh = readMesh(model_path);
    if (mesh.triangles.empty()) throw InputError(model_path + ": the model has no triangles");
    const Bounds b = meshBounds(mesh);
    r.triangles = long(mesh.triangles.size());
    r.size_mm[0] = b.max.x - b.min.x;
    r.size_mm[1] = b.max.y - b.min.y;
    r.size_mm[2] = b.max.z - b.min.z;
    if (r.size_mm[0] > settings.bed_width_mm || r.size_mm[1] > settings.bed_depth_mm)
        throw InputError(model_path + ": the model is " + fixed(r.size_mm[0], 1) + " x " + fixed(r.size_mm[1], 1) +
                         " mm, larger than the " + fixed(settings.bed_width_mm, 0) + " x " +
                         fixed(settings.bed_depth_mm, 0) + " mm bed; give the printer's bed with --bed WxD or make "
                         "the model smaller (tsf gen --width/--depth)");
    r.slicer_version = prusaSlicerVersion(settings);
    r.info = prusaSlicerInfo(model_path, settings);
    r.plain = prusaSlice(model_path, settings, /*with_support=*/false);
    r.supported = prusaSlice(model_path, settings, /*with_support=*/true);
    return r;
}

std::string formatPrintCheck(const PrintCheckReport& r) {
    std::ostringstream o;
    const SlicerSettings& s = r.settings;
    o << "print check: " << r.model << "\n";
    o << "  slicer:            " << r.slicer_version << ", built-in profile; layer " << fixed(s.layer_mm, 2)
      << " mm (first layer too), nozzle " << fixed(s.nozzle_mm, 2) << " mm, bed " << fixed(s.bed_width_mm, 0) << " x "
      << fixed(s.bed_depth_mm, 0) << " mm, filament " << fixed(s.filament_density_g_cm3, 2) << " g/cm3\n";
    o << "  model:             " << fixed(r.size_mm[0], 1) << " x " << fixed(r.size_mm[1], 1) << " x "
      << fixed(r.size_mm[2], 1) << " mm, " << r.triangles << " triangles, " << r.info.objects
      << (r.info.objects == 1 ? " object" : " objects") << " as PrusaSlicer loads it, " << r.info.parts
      << (r.info.parts == 1 ? " piece" : " pieces") << "\n";
    if (r.repairNeeded())
        o << "  repair:            NEEDED: PrusaSlicer finds the mesh not manifold (" << r.info.open_edges
          << " open edges) and repairs it silently to slice it; check the model with tsf verify\n";
    else
        o << "  repair:            none needed (PrusaSlicer: manifold)\n";
    o << "  layers:            " << r.plain.layers << " (top at " << fixed(r.plain.max_z_mm, 2) << " mm)\n";
    o << "  print time:        " << formatDuration(r.plain.print_time_s) << " (PrusaSlicer's estimate, normal mode)\n";
    o << "  filament:          " << filament(r.plain) << "\n";
    if (r.supportsNeeded()) {
        o << "  supports:          NEEDED: with automatic supports PrusaSlicer extrudes support material; then "
          << formatDuration(r.supported.print_time_s) << " and " << filament(r.supported) << " ("
          << fixed((r.supported.filament_cm3 - r.plain.filament_cm3), 2)
          << " cm3 more). Supports leave scars on the surface they touch\n";
    } else {
        o << "  supports:          none needed (automatic supports add nothing)\n";
    }
    return o.str();
}

nlohmann::json toJson(const PrintCheckReport& r) {
    const SlicerSettings& s = r.settings;
    return {{"model", r.model},
            {"slicer", r.slicer_version},
            {"settings",
             {{"layer_mm", s.layer_mm},
              {"nozzle_mm", s.nozzle_mm},
              {"filament_density_g_cm3", s.filament_density_g_cm3},
              {"bed_mm", {s.bed_width_mm, s.bed_depth_mm}},
              {"slicer_arguments", prusaSliceArguments(s, false)}}},
            {"size_mm", {r.size_mm[0], r.size_mm[1], r.size_mm[2]}},
            {"triangles", r.triangles},
            {"manifold", r.info.manifold},
            {"repair_needed", r.repairNeeded()},
            {"open_edges", r.info.open_edges},
            {"objects", r.info.objects},
            {"parts", r.info.parts},
            {"volume_mm3", r.info.volume_mm3},
            {"supports_needed", r.supportsNeeded()},
            {"layers", r.plain.layers},
            {"print_time_s", numberOrNull(r.plain.print_time_s)},
            {"filament_mm", numberOrNull(r.plain.filament_mm)},
            {"filament_cm3", numberOrNull(r.plain.filament_cm3)},
            {"filament_g", numberOrNull(r.plain.filament_g)},
            {"without_supports", sliceJson(r.plain)},
            {"with_supports", sliceJson(r.supported)}};
}

PrintCheckTotal sumPrintChecks(const std::vector<PrintCheckReport>& reports) {
    PrintCheckTotal t;
    for (const PrintCheckReport& r : reports) {
        ++t.pieces;
        t.print_time_s += r.plain.print_time_s;
        t.filament_mm += r.plain.filament_mm;
        t.filament_cm3 += r.plain.filament_cm3;
        t.filament_g += r.plain.filament_g;
        const GcodeSummary& as_printed = r.supportsNeeded() ? r.supported : r.plain;
        t.supported_time_s += as_printed.print_time_s;
        t.supported_filament_g += as_printed.filament_g;
        t.pieces_needing_supports += r.supportsNeeded();
    }
    return t;
}

std::string formatPrintCheckTotal(const PrintCheckTotal& t) {
    std::ostringstream o;
    o << "total: " << t.pieces << " pieces printed one after another\n";
    o << "  print time:        " << formatDuration(t.print_time_s) << "\n";
    o << "  filament:          " << fixed(t.filament_mm / 1000.0, 2) << " m = " << fixed(t.filament_cm3, 2) << " cm3 = "
      << fixed(t.filament_g, 1) << " g\n";
    if (t.pieces_needing_supports > 0)
        o << "  supports:          " << t.pieces_needing_supports << " of the pieces need them; with them "
          << formatDuration(t.supported_time_s) << " and " << fixed(t.supported_filament_g, 1) << " g\n";
    else
        o << "  supports:          none needed by any piece\n";
    return o.str();
}

nlohmann::json toJson(const PrintCheckTotal& t) {
    return {{"pieces", t.pieces},
            {"print_time_s", numberOrNull(t.print_time_s)},
            {"filament_mm", numberOrNull(t.filament_mm)},
            {"filament_cm3", numberOrNull(t.filament_cm3)},
            {"filament_g", numberOrNull(t.filament_g)},
            {"pieces_needing_supports", t.pieces_needing_supports},
            {"with_supports_where_needed", {{"print_time_s", numberOrNull(t.supported_time_s)},
                                            {"filament_g", numberOrNull(t.supported_filament_g)}}}};
}

}  // namespace tsf
