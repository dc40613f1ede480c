#include "app/gen_run/read_field.h"

#include <cstdio>
#include <filesystem>

#include "gen/readers/load_field.h"

namespace tsf::cli {

namespace {

// Grids above this many cells print progress lines without being asked.
constexpr int64_t kProgressCells = 250000;
// Input files above this size say so before they are read (seconds of work).
constexpr int64_t kProgressInputBytes = int64_t(64) << 20;

void announceLargeInput(const std::string& input, bool progress) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(input, ec);
    if (ec || progress || int64_t(bytes) < kProgressInputBytes) return;
    std::fprintf(stderr, "tsf: reading %s (%lld MiB), this may take a while\n", input.c_str(),
                 static_cast<long long>(bytes >> 20));
}

}  // namespace

HexField readGenField(GenCommandOptions& o, GenSummary& summary) {
    announceLargeInput(o.gen.input, o.progress);
    HexField field = loadField(o.gen);
    if (field.grid.cellCount() > kProgressCells && !o.progress && !o.json)
        std::fprintf(stderr, "tsf: %d x %d cells, this may take a few seconds\n", field.grid.cols, field.grid.rows);
    // A legend's units line takes the file's own units unless --units says otherwise.
    ModelWords& words = o.gen.scene.words;
    if (!words.title.empty() && words.units.empty() && !field.input.units.empty()) {
        words.units = field.input.units;
        summary.printer_notes.push_back("the legend's units are the file's: " + words.units + " (--units to say otherwise)");
    }
    return field;
}

}  // namespace tsf::cli
