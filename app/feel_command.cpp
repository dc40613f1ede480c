// tsf feel: render a field on a force-feedback device (or a simulated one)
// at 1 kHz, then report what happened: loop timing, forces, an optional CSV
// log and a picture of the path. It reads the same inputs and model options
// as tsf gen and feels the relief gen prints (haptics/printed_relief.h).
#include <signal.h>

#include <filesystem>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include <glm/geometric.hpp>
#include <nlohmann/json.hpp>

#include "app/commands.h"
#include "app/gen_options.h"
#include "app/session_signals.h"
#include "gen/util/error.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/model/scene_json.h"
#include "gen/util/atomic_file.h"
#include "gen/readers/load_field.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "haptics/coverage.h"
#include "haptics/falcon/falcon_device.h"
#include "haptics/falcon/falcon_guardian.h"
#include "haptics/falcon/libusb_transport.h"
#include "haptics/feel_renderer.h"
#include "haptics/field_mapping.h"
#include "haptics/force_log.h"
#include "haptics/force_model.h"
#include "haptics/force_plot.h"
#include "haptics/haptic_loop.h"
#include "haptics/height_grid.h"
#include "haptics/loop_clock.h"
#include "haptics/printed_relief.h"
#include "gen/util/output_paths.h"
#include "haptics/replay_device.h"
#include "haptics/scale_space.h"
#include "haptics/sim_device.h"
#include "pipeline/feel_session.h"
#include "gen/util/number_format.h"

namespace tsf::cli {
namespace {

using namespace tsf::haptics;

struct FeelOptions {
    GenOptions gen;  ///< input and model options, as tsf gen takes them
    std::string device = "sim";
    std::string firmware;
    std::string trajectory = "sweep";
    double duration_s = 0.0;
    double rate_Hz = 1000.0;
    double stiffness_N_per_m = 1000.0;
    double max_force_N = 6.0;
    std::string friction = "on";
    double mu_s = 0.3;
    double mu_k = 0.2;
    double gravity_N = 0.0;
    double guidance_N = 0.0;
    bool volume = false;
    int levels = 4;
    int lod = 0;
    std::string scale_space = "gaussian";
    std::string sampling = "bicubic";
    std::string gradient = "analytic";
    std::string edge = "clamp";
    double press_N = 1.5;
    double start_ramp_s = 1.0;
    double spin_us = 100.0;
    std::string log;
    std::string plot;
    std::string relief_csv;
    std::string proportions = "fitted";
    std::string scene;  ///< --scene: the sidecar of the model a mesh input was made from
    bool json = false;
    bool realtime = false;
    bool no_realtime = false;
};

/// Longest log kept in memory when the run has no known end (a device
/// served until Ctrl-C): ten minutes at the loop rate.
constexpr double kMaxLogSeconds = 600.0;
/// Room in the log for a simulated session this many times its script's
/// length (the hand slows down while it waits for the finger, sim_device.h).
constexpr double kSimLogScriptFactor = 2.0;

[[noreturn]] void deviceFailed(const std::string& message) {
    std::fprintf(stderr, "tsf: error: %s\n", message.c_str());
    throw CLI::RuntimeError(kExitDeviceFailed);
}

// A mesh tsf did not make, moved so its footprint starts at (0, 0) (the
// Scene frame's grid corner), and its top sampled at the centres of a
// hexagonal grid about 60 cells across laid over it: the values (mm above
// its lowest top) of a Scene that gives the feel its grid, coverage and
// report. What is felt is the mesh's own top (meshRelief).
constexpr int kForeignMeshCells = 60;

struct MeshTop {
    HexField field;
    double floor_mm = 0;  ///< the lowest top above the mesh's bottom
    double shift_x_mm = 0, shift_y_mm = 0;  ///< the mesh's own frame = the shifted one + these
};

MeshTop meshTopField(Mesh& mesh, const std::string& path) {
    const Bounds b = meshBounds(mesh);
    for (tsf::Vec3& p : mesh.positions) {
        p.x -= b.min.x;
        p.y -= b.min.y;
    }
    const double width = b.max.x - b.min.x, depth = b.max.y - b.min.y;
    MeshTop out;
    HexField& f = out.field;
    const double pitch = std::max({width, depth, 1e-3}) / kForeignMeshCells;
    f.grid.cols = std::max(1, int32_t(std::ceil(width / pitch)));
    f.grid.rows = std::max(1, int32_t(std::ceil(depth / (pitch * kSqrt3 / 2))));
    const ReliefSurface top = reliefSurface(mesh, pitch / kReliefSamplesPerPitch);
    f.values.assign(size_t(f.grid.cellCount()), std::nan(""));
    for (int32_t r = 0; r < f.grid.rows; ++r)
        for (int32_t c = 0; c < f.grid.cols; ++c) {
            const LatticePoint centre = hexCentre(f.grid, c, r);
            const auto i = int32_t(std::floor((latticeX(centre, pitch) - top.x0_mm) / top.sample_mm));
            const auto j = int32_t(std::floor((latticeY(centre, pitch, 1.0) - top.y0_mm) / top.sample_mm));
            if (i >= 0 && j >= 0 && i < top.cols && j < top.rows) f.at(c, r) = top.z_mm[size_t(j) * size_t(top.cols) + size_t(i)];
        }
    double lowest = INFINITY;
    for (const double z : top.z_mm)
        if (std::isfinite(z)) lowest = std::min(lowest, z);
    if (!std::isfinite(lowest)) lowest = 0;
    for (double& v : f.values)
        if (std::isfinite(v)) v -= lowest;  // mm above the lowest top
    out.floor_mm = lowest - b.min.z;
    out.shift_x_mm = b.min.x;
    out.shift_y_mm = b.min.y;
    f.source = path;
    f.pitch_data = pitch;
    f.how = "the mesh's own top (no scene sidecar), on " + std::to_string(f.grid.cols) + " x " +
            std::to_string(f.grid.rows) + " hexagons laid over it";
    f.input.kind = "mesh";
    return out;
}

// The Scene for meshTopField's values: one hexagon per value at the pitch
// they were sampled at, heights in mm as the values are, the floor at the
// mesh's lowest top, nothing added (no marks, no culling).
SceneParams meshTopParams(const MeshTop& top) {
    const HexField& f = top.field;
    SceneParams p;
    p.pitch_mm = f.pitch_data;
    double highest = 0;
    for (const double v : f.values)
        if (std::isfinite(v)) highest = std::max(highest, v);
    p.max_height_mm = std::max(highest, 1e-3);
    p.value_max = p.max_height_mm;
    p.baseline_mode = BaselineMode::Zero;
    // The floor: the lowest top above the mesh's bottom (at least a snap step).
    p.base_mm = std::max(top.floor_mm, 0.001);
    p.cull = Cull::None;
    p.marks.notch = false;
    p.marks.triangle = false;
    p.structural_texture = false;
    return p;
}

// A mesh file (STL, 3MF, OFF, OBJ), felt as it is.
bool isMeshFile(const std::string& path) {
    const std::string ext = lowerCaseExtension(path);
    return ext == ".stl" || ext == ".3mf" || ext == ".off" || ext == ".obj";
}

// A scene sidecar written beside a model by tsf gen (gen/model/scene_json.h).
bool isSceneSidecar(const std::string& path) {
    const std::string suffix = ".scene.json";
    return path.size() > suffix.size() && path.compare(path.size() - suffix.size(), suffix.size(), suffix) == 0;
}

struct FieldFacts {
    double min = 0.0, max = 0.0;  ///< finite values
    int64_t nodata = 0;
};

FieldFacts fieldFacts(const HexField& field) {
    FieldFacts f{INFINITY, -INFINITY, 0};
    for (double v : field.values) {
        if (!std::isfinite(v)) ++f.nodata;
        else f.min = std::min(f.min, v), f.max = std::max(f.max, v);
    }
    if (f.min > f.max) f.min = f.max = NAN;
    return f;
}

/// Frames the Falcon answered per second of the loop: the achieved rate.
double framesPerSecond(const FalconDevice& d, const LoopStats& loop) {
    return loop.elapsed_s > 0.0 ? double(d.stats().frames_received) / loop.elapsed_s : 0.0;
}

/// What the Falcon's link did: firmware, packets, the achieved rate.
nlohmann::json falconJson(const FalconDevice& d, const LoopStats& loop) {
    const FalconLinkStats& s = d.stats();
    return {{"firmware", s.firmware_was_running ? "already running" : "loaded"},
            {"firmware_bytes", s.firmware.bytes},
            {"firmware_attempts", s.firmware.attempts},
            {"packets_sent", s.packets_sent},
            {"frames_received", s.frames_received},
            {"frames_per_s", framesPerSecond(d, loop)},
            {"ticks_without_frame", s.ticks_without_frame},
            {"longest_silence_ticks", s.max_silent_ticks},
            {"resends", s.resends},
            {"bytes_discarded", s.bytes_discarded},
            {"usb_errors", s.usb_errors},
            {"solver_fallbacks", s.solver_fallbacks},
            {"limited_commands", s.limited_commands},
            {"refused_forces", s.refused_forces},
            {"stale_zeroed_commands", s.stale_zeroed},
            {"frames_with_unknown_bits", s.frames_with_unknown_bits},
            {"homed_ticks", s.ticks_homed}};
}

std::string falconText(const FalconDevice& d, const LoopStats& loop) {
    const FalconLinkStats& s = d.stats();
    char b[512];
    std::snprintf(b, sizeof b,
                  "  falcon    firmware %s; %llu packets, %llu frames (%.0f per s), %llu ticks without a frame "
                  "(longest %llu), %llu resent, %llu solver fallbacks, %llu commands at the motor limit; "
                  "homed for %llu ticks\n",
                  s.firmware_was_running ? "already running"
                                         : ("loaded (" + std::to_string(s.firmware.bytes) + " bytes, " +
                                            std::to_string(s.firmware.attempts) + " attempt" +
                                            (s.firmware.attempts == 1 ? ")" : "s)")).c_str(),
                  (unsigned long long)s.packets_sent, (unsigned long long)s.frames_received,
                  framesPerSecond(d, loop),
                  (unsigned long long)s.ticks_without_frame, (unsigned long long)s.max_silent_ticks,
                  (unsigned long long)s.resends, (unsigned long long)s.solver_fallbacks,
                  (unsigned long long)s.limited_commands, (unsigned long long)s.ticks_homed);
    return b;
}

ForceParams forceParams(const FeelOptions& o) {
    ForceParams p;
    p.stiffness_N_per_m = o.stiffness_N_per_m;
    p.max_force_N = o.max_force_N;
    p.friction = o.friction == "on";
    p.mu_static = o.mu_s;
    p.mu_kinetic = o.mu_k;
    p.gravity_N = o.gravity_N;
    p.guidance_N = o.guidance_N;
    p.sampling.interpolation = o.sampling == "bilinear" ? Interpolation::kBilinear : Interpolation::kBicubic;
    p.sampling.central_differences = o.gradient == "central";
    p.edge = o.edge == "wall" ? EdgeMode::kWall : EdgeMode::kClamp;
    return p;
}

// Metres (the device frame) shown in millimetres.
std::string mm(double m) { return formatFixed(m * 1000.0, 1) + " mm"; }

void runFeel(const FeelOptions& o) {
    if (!(o.rate_Hz >= 100.0 && o.rate_Hz <= 10000.0))
        throw InputError("--rate must be between 100 and 10000 ticks per second");
    if (!(o.duration_s >= 0.0) || !std::isfinite(o.duration_s)) throw InputError("--duration must be 0 or more seconds");
    if (!(o.start_ramp_s >= 0.0 && o.start_ramp_s <= 10.0)) throw InputError("--start-ramp must be 0 to 10 seconds");
    if (!(o.press_N >= 0.0 && o.press_N <= 8.0)) throw InputError("--press must be 0 to 8 N");
    if (!(o.spin_us >= 0.0 && o.spin_us <= 1000.0)) throw InputError("--spin-us must be 0 to 1000");
    if (o.realtime && o.no_realtime) throw InputError("--realtime and --no-realtime contradict each other");

    // Every input is checked before a device is opened: a Falcon must be
    // served without pause once it is open (its link drops when packets stop).
    const std::string& spec = o.device;
    const bool is_sim = spec == "sim";
    const bool is_replay = spec.rfind("replay:", 0) == 0;
    const bool is_falcon = spec == "falcon";
    if (!is_sim && !is_replay && !is_falcon)
        throw InputError("--device must be sim, replay:FILE or falcon (got '" + spec + "')");
    if (is_replay && spec.size() == 7) throw InputError("--device replay: needs a file name, as in replay:session.csv");
    if (!o.firmware.empty() && !is_falcon) throw InputError("--firmware is for --device falcon");
    checkOutputPaths({{o.gen.input, "the field"},
                      {is_replay ? spec.substr(7) : std::string(), "the recording replayed"},
                      {o.firmware, "--firmware"}},
                     {{o.log, "--log"}, {o.plot, "--plot"}, {o.relief_csv, "--relief"}});
    const SimTrajectory trajectory = parseSimTrajectory(o.trajectory);
    FalconOptions falcon_options;
    if (is_falcon && !o.firmware.empty()) falcon_options.firmware = readFalconFirmware(o.firmware);

    if (!(o.levels >= 1 && o.levels <= kMaxScaleLevels))
        throw InputError("--levels must be 1 to " + std::to_string(kMaxScaleLevels));
    if (!(o.lod >= 0 && o.lod < o.levels)) throw InputError("--lod must be between 0 and --levels - 1");

    // The relief tsf gen would print from the same input and options, the
    // model a sidecar (MODEL.stl.scene.json) describes, exactly as printed,
    // or a mesh file itself (a model as written, or as OpenSCAD rendered an
    // edited .scad) on the grid of its sidecar.
    const bool from_mesh = isMeshFile(o.gen.input);
    if (!from_mesh && !o.scene.empty()) throw InputError("--scene is for a mesh input (MODEL.stl --scene MODEL.stl.scene.json)");
    if (from_mesh && !o.scene.empty() && !std::filesystem::exists(o.scene))
        throw InputError("--scene " + o.scene + ": no such file (tsf gen writes MODEL.stl.scene.json beside the model)");
    // The sidecar: --scene, else MODEL.stl.scene.json (what tsf gen writes),
    // else MODEL.scene.json; none: a mesh tsf did not make, whose top is
    // felt on a grid laid over it.
    std::string sidecar;
    if (from_mesh) {
        const std::filesystem::path in(o.gen.input);
        std::filesystem::path stem = in;
        stem.replace_extension(".scene.json");
        for (const std::string& candidate : {o.scene, o.gen.input + ".scene.json", stem.string()})
            if (!candidate.empty() && std::filesystem::exists(candidate)) {
                sidecar = candidate;
                break;
            }
    }
    const bool foreign_mesh = from_mesh && sidecar.empty();
    const bool from_sidecar = (from_mesh && !foreign_mesh) || isSceneSidecar(o.gen.input);
    Mesh file_mesh;
    if (from_mesh) {
        MeshReadReport read;
        file_mesh = readMesh(o.gen.input, &read);
        if (file_mesh.triangles.empty()) throw InputError(o.gen.input + ": the mesh has no triangles to feel");
    }
    HexField field;
    refuseBandSeries(o.gen, "feel");
    if (!from_sidecar && !from_mesh) field = loadField(o.gen);
    Scene scene;
    double relief_shift_x_mm = 0, relief_shift_y_mm = 0;  // --relief is written in the mesh's own frame
    if (foreign_mesh) {
        const MeshTop top = meshTopField(file_mesh, o.gen.input);
        field = top.field;
        scene = buildScene(field, meshTopParams(top));
        relief_shift_x_mm = top.shift_x_mm;
        relief_shift_y_mm = top.shift_y_mm;
    }
    if (!foreign_mesh) scene = from_sidecar ? readSceneJson(from_mesh ? sidecar : o.gen.input) : buildScene(field, o.gen.scene);
    if (from_mesh) {
        const double overhang = overhangAreaMm2(file_mesh);
        // A hand from above meets the top only: say what it cannot reach.
        if (overhang > 0 && !o.json)
            std::fprintf(stderr,
                         "tsf: note: %s has %.0f mm^2 of surface facing down above the bed (overhangs, a mirrored "
                         "underside): a hand from above cannot reach under it; the top is felt\n",
                         o.gen.input.c_str(), overhang);
    }
    if (from_sidecar && !foreign_mesh) {
        // The values the model holds, for the report: its kept cells' (NaN:
        // a pit without data), not the culled cells of its grid.
        field.grid = scene.grid;
        field.values = scene.value;
        field.source = o.gen.input;
        field.how = from_mesh ? "the mesh as written, on the grid of its scene sidecar"
                              : "the model its scene sidecar describes, as printed";
    }
    const DeviceLimits limits;  // the Falcon's (sim and replay stand in for one)
    const FeelSurface surface =
        buildFeelSurface(scene, o.levels, o.scale_space == "mipmap" ? ScaleSpaceKind::kMipmap : ScaleSpaceKind::kGaussian,
                         limits, from_mesh ? &file_mesh : nullptr,
                         o.proportions == "printed" ? Proportions::kAsPrinted : Proportions::kFitted);
    const ReliefInfo& relief = surface.relief;
    const HeightGrid& grid = surface.grid;
    const FieldMapping& mapping = surface.mapping;
    const ScaleSpace& space = surface.space;
    const double build_s = surface.build_s;

    std::unique_ptr<HapticDevice> device;
    FalconDevice* falcon = nullptr;
    double script_s = 0.0;
    if (is_falcon) {
        auto f = std::make_unique<FalconDevice>(openFalconUsb, std::move(falcon_options));
        falcon = f.get();
        device = std::move(f);
    } else if (is_sim) {
        SimScript script = makeSimScript(trajectory, mapping, o.press_N, reliefRowLines(scene, relief, mapping));
        script_s = script.duration_s();
        device = std::make_unique<SimDevice>(std::move(script), limits);
    } else {
        const std::string path = spec.substr(7);
        auto replay = std::make_unique<ReplayDevice>(readReplayFile(path), path, limits);
        script_s = replay->duration_s();
        device = std::move(replay);
    }

    FeelRequest rq;
    rq.force = forceParams(o);
    rq.renderer.start_lod = o.lod;
    rq.renderer.start_volume = o.volume;
    rq.realtime = o.realtime || (!o.no_realtime && device->needsRealtime());
    rq.spin_us = o.spin_us;
    rq.loop.rate_Hz = o.rate_Hz;
    rq.loop.duration_s = o.duration_s;
    rq.loop.start_ramp_s = o.start_ramp_s;
    // A simulated hand that waits for its finger runs longer than its script.
    double expected_s = o.duration_s > 0.0 ? o.duration_s : (is_sim ? kSimLogScriptFactor : 1.0) * script_s;
    if (!(expected_s > 0.0)) expected_s = kMaxLogSeconds;
    // Room for the stop ramp and a second's slack too.
    rq.log_records = size_t((std::min(expected_s, kMaxLogSeconds) + rq.loop.stop_ramp_s + 1.0) * o.rate_Hz);
    const bool realtime = rq.realtime;

    FeelOutcome session;
    int signal_caught = 0;
    {
        SessionSignals signals;
        rq.loop.pause_requested = &SessionSignals::pause();
        rq.loop.pause = &SessionSignals::pauseProcess;
        try {
            // Started before the Falcon is opened, released after it is
            // closed at zero force: should this process die in between
            // (SIGKILL, a crash), the guardian zeroes the Falcon.
            std::optional<FalconGuardian> guardian;
            if (falcon) guardian.emplace(openFalconUsb);
            session = runFeelSession(scene, surface, *device, rq, SessionSignals::stop(), [&] {
                if (falcon && !falcon->homed())
                    std::fprintf(stderr, "tsf: home the Falcon: pull the grip all the way out toward you, then push it "
                                         "back in; forces start when its light turns from red to green (Ctrl-C ends)\n");
            });
        } catch (const DeviceError& e) {
            deviceFailed(e.what());
        }
        signal_caught = SessionSignals::caught();
    }
    const LoopStats& stats = session.stats;
    const ForceLog& log = session.log;
    const std::string& priority = session.priority;
    const double wall_s = session.wall_s;

    if (!o.log.empty()) writeForceLogCsv(o.log, log);
    if (!o.relief_csv.empty()) {
        // 0.5 mm, or a sixth of a cell where cells are narrower than 3 mm.
        const double sample_mm = std::min(0.5, scene.pitch_mm / kReliefSamplesPerPitch);
        const ReliefSurface r = from_mesh ? reliefSurface(file_mesh, sample_mm) : reliefSurface(scene, sample_mm);
        writeFileAtomically(o.relief_csv, [&](std::ostream& os) {
            os << "x_mm,y_mm,z_mm\n";
            char line[96];
            for (int32_t j = 0; j < r.rows; ++j)
                for (int32_t i = 0; i < r.cols; ++i) {
                    const double z = r.z_mm[size_t(j) * size_t(r.cols) + size_t(i)];
                    std::snprintf(line, sizeof line, std::isnan(z) ? "%.4f,%.4f,NaN\n" : "%.4f,%.4f,%.4f\n",
                                  relief_shift_x_mm + r.x0_mm + (i + 0.5) * r.sample_mm,
                                  relief_shift_y_mm + r.y0_mm + (j + 0.5) * r.sample_mm, z);
                    os << line;
                }
        });
    }
    if (!o.plot.empty()) {
        haptics::PlotOptions po;
        po.title = "tsf feel: " + std::filesystem::path(o.gen.input).filename().string() + ", " + o.device + ", " +
                   std::to_string(log.size()) + " ticks";
        writeForcePlotPng(o.plot, grid, mapping, log, o.max_force_N, po);
    }

    const RendererCounters& c = session.counters;
    const double contact_pct = c.ticks ? 100.0 * double(c.contact_ticks) / double(c.ticks) : 0.0;
    const double clamped_pct = c.ticks ? 100.0 * double(c.clamped_ticks) / double(c.ticks) : 0.0;
    const Coverage& coverage = session.coverage;
    const FieldFacts facts = fieldFacts(field);
    const ValueMapping& vm = scene.mapping;
    const double pitch_m = mapping.cell_m * relief.samples_per_pitch;  // one hexagon's width on the device
    if (o.json) {
        nlohmann::json j;
        j["field"] = {{"file", o.gen.input},     {"how", field.how},          {"cols", field.grid.cols},
                      {"rows", field.grid.rows}, {"min", facts.min},          {"max", facts.max},
                      {"nodata_cells", facts.nodata}, {"kept_cells", scene.keptCount()}};
        j["relief"] = {{"transfer", toString(vm.transfer)},
                       {"baseline", vm.baseline},
                       {"value_max", vm.value_max},
                       {"printed_height_mm", vm.max_height_mm},
                       {"felt_height_m", mapping.relief_m},
                       {"samples_per_cell", relief.samples_per_pitch},
                       {"exact_at_cell_centres", relief.exact_at_centres}};
        j["sidecar"] = sidecar.empty() ? nlohmann::json(nullptr) : nlohmann::json(sidecar);
        j["device"] = device->name();
        if (falcon) j["falcon"] = falconJson(*falcon, stats);
        j["mapping_m"] = {{"cell", pitch_m},
                          {"sample", mapping.cell_m},
                          {"width", mapping.cell_m * grid.cols},
                          {"depth", mapping.cell_m * grid.rows},
                          {"relief", mapping.relief_m},
                          {"floor_y", mapping.floor_y_m},
                          {"volume_bottom_y", mapping.volume_bottom_y_m},
                          {"volume_top_y", mapping.volume_top_y_m}};
        j["proportions"] = {{"mode", o.proportions},
                            {"scale_xy", surface.scale.xy},
                            {"scale_z", surface.scale.z},
                            {"slope_exaggeration", surface.scale.slopeExaggeration()}};
        j["scale_space"] = {{"kind", o.scale_space}, {"levels", space.count()}, {"build_s", build_s}};
        j["loop"] = {{"end", loopEndName(stats.end)},
                     {"realtime", realtime},
                     {"priority", priority},
                     {"ticks", stats.ticks},
                     {"loop_time_s", stats.elapsed_s},
                     {"wall_time_s", wall_s},
                     {"rate_Hz", stats.rate_Hz},
                     {"target_rate_Hz", stats.target_rate_Hz},
                     {"lateness_us", {{"p50", stats.lateness.quantile_us(0.5)},
                                      {"p99", stats.lateness.quantile_us(0.99)},
                                      {"max", stats.lateness.max_us()}}},
                     {"compute_us", {{"p50", stats.compute.quantile_us(0.5)},
                                     {"p99", stats.compute.quantile_us(0.99)},
                                     {"max", stats.compute.max_us()}}},
                     {"overruns", stats.overruns},
                     {"pauses", stats.pauses},
                     {"stalls", stats.stalls},
                     {"failed_writes", stats.failed_writes},
                     {"zero_force_sent", stats.zero_force_sent}};
        j["forces"] = {{"max_N", c.max_force_N},
                       {"limit_N", o.max_force_N},
                       {"contact_ticks", c.contact_ticks},
                       {"clamped_ticks", c.clamped_ticks},
                       {"clamped_share", c.ticks ? double(c.clamped_ticks) / double(c.ticks) : 0.0},
                       {"damping_ticks", c.damping_ticks},
                       {"rejected_ticks", c.rejected_ticks},
                       {"mode_switches", c.mode_switches},
                       {"max_penetration_m", c.max_penetration_m}};
        j["coverage"] = {{"cells", coverage.cells}, {"touched", coverage.touched}, {"fraction", coverage.fraction()}};
        j["log"] = {{"file", o.log}, {"records", log.size()}, {"dropped", log.dropped()}};
        j["plot"] = o.plot;
        j["relief_csv"] = o.relief_csv;
        std::cout << j.dump(2) << "\n";
    } else {
        std::printf("tsf feel: %s (%d x %d cells, values %g..%g%s) on %s\n", o.gen.input.c_str(), field.grid.cols,
                    field.grid.rows, facts.min, facts.max,
                    facts.nodata ? (", " + std::to_string(facts.nodata) + " no-data cells as floor").c_str() : "",
                    device->name().c_str());
        if (from_mesh)
            std::printf("  sidecar   %s\n", sidecar.empty() ? "none: the mesh's own top, on a grid laid over it"
                                                            : (sidecar + " (its grid and heights)").c_str());
        std::printf("  relief    as printed: %s from %g (floor) to %g (top: %.1f mm printed, %s felt), %zu cells\n",
                    toString(vm.transfer), vm.baseline, vm.value_max, vm.max_height_mm, mm(mapping.relief_m).c_str(),
                    scene.keptCount());
        std::printf("  mapping   %s x %s footprint, cell %s, volume slab %s\n", mm(mapping.cell_m * grid.cols).c_str(),
                    mm(mapping.cell_m * grid.rows).c_str(), mm(pitch_m).c_str(),
                    mm(mapping.volume_top_y_m - mapping.volume_bottom_y_m).c_str());
        if (o.proportions == "printed")
            std::printf("  scale     as printed: %s device mm per printed mm in x, y and z (slopes feel as printed)\n",
                        formatFixed(surface.scale.xy, 2).c_str());
        else
            std::printf("  scale     fitted: %s device mm per printed mm across, %s up: slopes feel %sx steeper than "
                        "printed (--proportions printed: as printed)\n",
                        formatFixed(surface.scale.xy, 2).c_str(), formatFixed(surface.scale.z, 2).c_str(),
                        formatFixed(surface.scale.slopeExaggeration(), 1).c_str());
        std::printf("  levels    %d %s levels built in %.1f ms\n", space.count(), o.scale_space.c_str(), build_s * 1e3);
        std::printf("  loop      %llu ticks in %.2f s (%.1f Hz, target %.0f Hz), %s, %s\n",
                    (unsigned long long)stats.ticks, stats.elapsed_s, stats.rate_Hz, stats.target_rate_Hz,
                    realtime ? "real time" : "faster than real time", priority.c_str());
        if (realtime)
            std::printf("  timing    lateness p50 %.0f us, p99 %.0f us, max %.0f us; compute p99 %.0f us; overruns %llu\n",
                        stats.lateness.quantile_us(0.5), stats.lateness.quantile_us(0.99), stats.lateness.max_us(),
                        stats.compute.quantile_us(0.99), (unsigned long long)stats.overruns);
        if (falcon) std::printf("%s", falconText(*falcon, stats).c_str());
        std::printf("  forces    max %.2f N (limit %.2f N), contact %.0f%% of ticks, at the limit %.1f%% (%llu), "
                    "observer damping %llu, rejected %llu\n",
                    c.max_force_N, o.max_force_N, contact_pct, clamped_pct, (unsigned long long)c.clamped_ticks,
                    (unsigned long long)c.damping_ticks, (unsigned long long)c.rejected_ticks);
        std::printf("  coverage  touched %lld of %lld cells (%.1f%%)%s\n", (long long)coverage.touched,
                    (long long)coverage.cells, 100.0 * coverage.fraction(), log.dropped() ? ", log full: undercounted" : "");
        std::printf("  ended     %s; zero force %s", loopEndName(stats.end),
                    stats.zero_force_sent ? "sent" : "NOT confirmed by the device");
        if (stats.pauses || stats.stalls)
            std::printf("; %llu pause%s and %llu stall%s, each followed by the start ramp again",
                        (unsigned long long)stats.pauses, stats.pauses == 1 ? "" : "s",
                        (unsigned long long)stats.stalls, stats.stalls == 1 ? "" : "s");
        std::printf("\n");
        if (!o.log.empty())
            std::printf("  log       %s (%zu rows%s)\n", o.log.c_str(), log.size(),
                        log.dropped() ? (", " + std::to_string(log.dropped()) + " dropped: log full").c_str() : "");
        if (!o.plot.empty()) std::printf("  plot      %s\n", o.plot.c_str());
        if (!o.relief_csv.empty()) std::printf("  relief    %s (the printed surface, x_mm,y_mm,z_mm)\n", o.relief_csv.c_str());
    }
    std::fflush(stdout);
    if (stats.end == LoopEnd::kDeviceFailed) {
        const std::string why = device->failureReason();
        deviceFailed(why.empty() ? "the device stopped answering during the session" : why);
    }
    if (stats.end == LoopEnd::kInterrupted) {
        // The device is closed at zero force: now end as the signal asks.
        finishBySignal(signal_caught);
        throw CLI::RuntimeError(signal_caught ? 128 + signal_caught : kExitInterrupted);
    }
}

}  // namespace

void addFeelCommand(CLI::App& app) {
    auto o = std::make_shared<FeelOptions>();
    CLI::App* cmd = app.add_subcommand("feel", "Feel a field on a force-feedback device (or a simulated one)");
    cmd->footer(
        "Examples:\n"
        "  tsf feel field.csv --device sim --trajectory sweep --log forces.csv --plot forces.png\n"
        "  tsf feel field.csv --device replay:forces.csv --log again.csv\n"
        "  tsf feel examples/volcano.csv --device falcon --firmware nvent_firmware.bin\n"
        "The input and model options are tsf gen's: the relief felt is the relief gen prints.\n"
        "Given MODEL.stl.scene.json (the sidecar tsf gen writes), the model it describes is felt as printed:\n"
        "orientation tab, legend and scale included; the model options are then not used.\n"
        "Given a mesh (MODEL.stl, .3mf, .off, .obj), that mesh is felt on the grid of its sidecar (--scene, else\n"
        "MODEL.stl.scene.json, else MODEL.scene.json beside it; the summary says which), or, without one (a mesh\n"
        "tsf did not make), on a grid laid over it:\n"
        "  tsf feel edited.stl --scene model.stl.scene.json   # an edit of the .scad, rendered by OpenSCAD\n"
        "Device frame: x right, y up, z toward the user, metres; north of the field is away from the user.\n"
        "Buttons: centre = volume mode on/off, plus = coarser level, minus = finer level.\n"
        "Ctrl-C, SIGTERM (kill, timeout), a closed terminal and Ctrl-\\ ramp the force to zero, close the device\n"
        "and end the session (exit code 130, or the signal's own status); Ctrl-Z holds zero force while stopped\n"
        "and ramps in again after fg. With a Falcon, a guardian process zeroes it if tsf is killed or crashes.\n"
        "See docs/haptics.md.");
    addGenOptions(cmd, o->gen);
    cmd->add_option("--device", o->device, "sim | replay:FILE | falcon")->capture_default_str();
    cmd->add_option("--firmware", o->firmware,
                    "Falcon firmware file (nvent_firmware.bin from Novint's SDK), loaded when the Falcon has none "
                    "running (after every power-up)");
    cmd->add_option("--trajectory", o->trajectory, "Simulated hand: sweep | taps | finger")
        ->check(CLI::IsMember({"sweep", "taps", "finger"}))->capture_default_str();
    cmd->add_option("--duration", o->duration_s, "Seconds to run (0 = until the script or recording ends, or Ctrl-C)")
        ->capture_default_str();
    cmd->add_option("--rate", o->rate_Hz, "Loop rate, Hz")->capture_default_str();
    cmd->add_option("--stiffness", o->stiffness_N_per_m, "Surface stiffness, N/m (at most the device's safe bound)")
        ->capture_default_str();
    cmd->add_option("--max-force", o->max_force_N, "Force limit, N (at most the device's)")->capture_default_str();
    cmd->add_option("--friction", o->friction, "on | off")->check(CLI::IsMember({"on", "off"}))->capture_default_str();
    cmd->add_option("--mu-s", o->mu_s, "Static friction coefficient")->capture_default_str();
    cmd->add_option("--mu-k", o->mu_k, "Kinetic friction coefficient (<= --mu-s)")->capture_default_str();
    cmd->add_option("--gravity", o->gravity_N, "Constant downward force, N (0 = off)")->capture_default_str();
    cmd->add_option("--guidance", o->guidance_N, "Pull toward the surface in empty space, N (0 = off)")
        ->capture_default_str();
    cmd->add_flag("--volume", o->volume, "Start in volume mode (smoothed levels stacked above the surface)");
    cmd->add_option("--levels", o->levels, "Scale-space levels")->capture_default_str();
    cmd->add_option("--lod", o->lod, "Starting level of detail (0 = full detail)")->capture_default_str();
    cmd->add_option("--scale-space", o->scale_space, "mipmap | gaussian")
        ->check(CLI::IsMember({"mipmap", "gaussian"}))->capture_default_str();
    cmd->add_option("--sampling", o->sampling, "bilinear | bicubic")
        ->check(CLI::IsMember({"bilinear", "bicubic"}))->capture_default_str();
    cmd->add_option("--gradient", o->gradient, "analytic | central")
        ->check(CLI::IsMember({"analytic", "central"}))->capture_default_str();
    cmd->add_option("--edge", o->edge, "Outside the field: clamp (flat) | wall")
        ->check(CLI::IsMember({"clamp", "wall"}))->capture_default_str();
    cmd->add_option("--press", o->press_N, "Simulated hand's downward push, N")->capture_default_str();
    cmd->add_option("--start-ramp", o->start_ramp_s, "Seconds over which the force ramps in")->capture_default_str();
    cmd->add_option("--spin-us", o->spin_us, "Busy-wait this long before each deadline (real time only)")
        ->capture_default_str();
    cmd->add_option("--log", o->log, "Write a CSV of time, position, force and mode per tick");
    cmd->add_option("--plot", o->plot, "Write a PNG of the field with the path and the forces felt");
    cmd->add_option("--scene", o->scene,
                    "With a mesh input (MODEL.stl, .3mf, .off, .obj): the scene sidecar of the model it was made from "
                    "(default MODEL.stl.scene.json, else MODEL.scene.json beside it), for its grid and heights; the mesh itself is felt, "
                    "e.g. what OpenSCAD rendered after an edit of the .scad");
    cmd->add_option("--proportions", o->proportions,
                    "fitted: the footprint fills the workspace and the relief its height band, each scaled apart "
                    "(slopes steeper than printed; the summary says how much); printed: one scale for x, y and z, so "
                    "slopes feel as printed (a lower relief: small steps and dots get hard to feel)")
        ->check(CLI::IsMember({"fitted", "printed"}))->capture_default_str();
    cmd->add_option("--relief", o->relief_csv,
                    "Write the surface felt as CSV: x_mm,y_mm,z_mm of the printed model's top on a 0.5 mm grid "
                    "(finer for cells under 3 mm) over its whole footprint, NaN where nothing is");
    cmd->add_flag("--json", o->json, "Print the statistics as JSON");
    cmd->add_flag("--realtime", o->realtime, "Run on the wall clock even for simulated devices");
    cmd->add_flag("--no-realtime", o->no_realtime, "Run as fast as possible (simulated devices do by default)");
    cmd->callback([o] { runFeel(*o); });
}

}  // namespace tsf::cli
