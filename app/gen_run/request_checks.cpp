#include "app/gen_run/request_checks.h"

#include <filesystem>
#include <string>
#include <vector>

#include "app/halves_output.h"
#include "gen/key/model_key.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/model/scene_json.h"
#include "gen/util/error.h"
#include "gen/util/file_bytes.h"
#include "gen/util/output_paths.h"

namespace tsf::cli {

namespace {

// Largest existing parameter-set file read to decide whether tsf wrote it
// (tsf writes a few KB).
constexpr int64_t kMaxOwnFileBytes = 64 << 20;
// A scene sidecar is told by the head alone: it grows with the grid (71 MiB
// at 1000 x 1000), and its "format" key comes among the first top-level keys
// (written in sorted order, before "hull", "marks" and the cells).
constexpr size_t kSceneHeadBytes = 64 << 10;

/// A .brf tsf wrote: Braille ASCII only (and CR, LF, form feeds), beside a
/// key text tsf wrote.
bool isTsfKeyBrf(const std::string& brf_path) {
    std::filesystem::path text(brf_path);
    text.replace_extension(".txt");
    std::error_code ec;
    if (!std::filesystem::exists(text, ec) || !isTsfModelKey(readFileHead(text.string(), 64))) return false;
    for (const char c : readFileBytes(brf_path, kMaxOwnFileBytes))
        if (!((c >= 0x20 && c <= 0x5F) || c == '\r' || c == '\n' || c == '\f')) return false;
    return true;
}

// A file tsf names itself (not given on the command line) that exists and
// was not written by tsf is refused unless --force.
// head_bytes > 0: only that many bytes are read and judged.
void refuseForeignFile(const std::string& path, bool (*ours)(const std::string&), const std::string& what,
                       const std::string& alternative, size_t head_bytes = 0) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return;
    if (ours(head_bytes > 0 ? readFileHead(path, head_bytes) : readFileBytes(path, kMaxOwnFileBytes))) return;
    throw InputError(path, 0, 0,
                     "exists and was not written by tsf; it would be replaced by " + what +
                         ". Give --force to replace it, or " + alternative);
}

bool isTsfScene(const std::string& text) {
    return text.find("\"" + std::string(kSceneJsonFormat) + "\"") != std::string::npos;
}

// No output may be the input or another output, and files the user did not
// name (the parameter sets beside --scad, the scene sidecar) replace only
// what tsf wrote before, unless --force.
void checkOutputs(const GenCommandOptions& o, const ScadOptions& so) {
    std::vector<NamedPath> outputs;
    if (o.gen.scene.halves && !o.output.empty()) {
        const HalvesPaths h = halvesPaths(o.output);
        outputs.push_back({h.upper, "the upper half of -o"});
        outputs.push_back({h.lower, "the lower half of -o"});
        outputs.push_back({h.pins, "the pins of -o"});
    } else {
        outputs.push_back({o.output, "-o"});
    }
    outputs.push_back({o.preview, "--preview"});
    const std::vector<std::string> scad_paths = o.scad.empty() ? std::vector<std::string>() : scadOutputPaths(so, o.scad);
    if (!o.scad.empty()) outputs.push_back({o.scad, "--scad"});
    if (so.write_parameter_sets && !o.scad.empty())
        outputs.push_back({scad_paths[1], "the OpenSCAD parameter sets written beside --scad"});
    if (!o.no_sidecar) outputs.push_back({sidecarPath(o), "the scene sidecar (--no-scene leaves it out)"});
    if (!o.no_key) {
        outputs.push_back({keyPaths(o).first, "the model's key (--no-key leaves it out)"});
        outputs.push_back({keyPaths(o).second, "the model's braille key (--no-key leaves it out)"});
    }
    std::vector<NamedPath> inputs = {{o.gen.input, "the input"}};
    if (!o.gen.class_names.empty()) inputs.push_back({o.gen.class_names, "--class-names"});
    checkOutputPaths(inputs, outputs);
    if (o.force) return;
    if (so.write_parameter_sets && !o.scad.empty())
        refuseForeignFile(scad_paths[1], isTsfParameterSetFile, "the OpenSCAD parameter sets of --scad " + o.scad,
                          "choose another --scad name");
    if (!o.no_sidecar)
        refuseForeignFile(sidecarPath(o), isTsfScene, "the scene sidecar", "give --no-scene", kSceneHeadBytes);
    if (!o.no_key) {
        refuseForeignFile(keyPaths(o).first, isTsfModelKey, "the model's key", "give --no-key");
        std::error_code ec;
        if (std::filesystem::exists(keyPaths(o).second, ec) && !isTsfKeyBrf(keyPaths(o).second))
            throw InputError(keyPaths(o).second, 0, 0,
                             "exists and was not written by tsf; it would be replaced by the model's braille key. Give "
                             "--force to replace it, or give --no-key");
    }
}

// --tile writes each tile to a file of its own, from a flat model and a bed.
void checkTileRequest(const GenCommandOptions& o) {
    if (o.printer.bed.empty())
        throw InputError("--tile", 0, 0, "--tile cuts the model into tiles that fit the bed: give --bed WIDTHxDEPTH");
    if (o.output.empty())
        throw InputError("--tile", 0, 0, "--tile writes each tile to a file of its own: give -o MODEL.stl|.3mf|.off|.obj");
    const char* other = o.parts ? "--parts" : o.print_check ? "--print-check" : !o.scad.empty() ? "--scad" : nullptr;
    if (other)
        throw InputError(other, 0, 0,
                         std::string("--tile writes each tile to a file of its own (MODEL-tile-ROW-COL); leave out ") + other +
                             (o.print_check ? " and run tsf print-check on the tiles (it sums their time and filament)"
                                            : ": the tiles are not drawn in OpenSCAD or as parts yet"));
    if (o.gen.scene.halves || o.gen.scene.bottom == Bottom::Mirrored)
        throw InputError(o.gen.scene.halves ? "--halves" : "--mirror", 0, 0,
                         "--tile cuts a flat model: leave out --mirror and --halves");
}

}  // namespace

void checkGenRequest(const GenCommandOptions& o, const ScadOptions& so) {
    if (o.output.empty() && o.scad.empty())
        throw InputError("nothing to write: give -o MODEL.stl|.3mf|.off|.obj and/or --scad MODEL.scad");
    checkOutputs(o, so);
    const std::string model_ext = o.output.empty() ? "" : lowerCaseExtension(o.output);
    if (o.parts && model_ext != ".3mf")
        throw InputError(o.output.empty() ? "--parts" : o.output, 0, 0,
                         "--parts writes a 3MF (one object, a part per feature): give -o MODEL.3mf; "
                         "STL, OFF and OBJ hold one solid");
    if (o.parts_layout != "portable" && !o.parts)
        throw InputError("--parts-layout", 0, 0, "--parts-layout lays out the parts of --parts: add --parts");
    if (o.gen.scene.halves && (o.parts || o.print_check))
        throw InputError(o.parts ? "--parts" : "--print-check", 0, 0,
                         "--halves writes each piece to a file of its own (MODEL-upper, MODEL-lower, MODEL-pins); "
                         "leave out --parts and --print-check and run tsf print-check on each piece");
    if (o.printer.tile) checkTileRequest(o);
    if (o.print_check && model_ext != ".stl" && model_ext != ".3mf")
        throw InputError(o.output.empty() ? "--print-check" : o.output, 0, 0,
                         "--print-check slices the model file: give -o MODEL.stl or -o MODEL.3mf");
    if (!o.preview.empty() && lowerCaseExtension(o.preview) != ".png")
        throw InputError(o.preview, 0, 0, "--preview writes a PNG picture: give a name ending in .png");
}

}  // namespace tsf::cli
