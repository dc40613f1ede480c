#include "app/gen_run/model_verdict.h"

#include <cmath>
#include <cstdio>
#include <string>

#include "app/halves_output.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"
#include "verify/verify_parts.h"

namespace tsf::cli {

namespace {

/// The names of the checks passed, for the summary's details.
std::string passedChecksLine(const VerifyReport& r) {
    std::string passed;
    for (const Check& c : r.checks)
        if (c.status == CheckStatus::Pass) passed += (passed.empty() ? "" : ", ") + c.title;
    return passed.empty() ? "" : "  checks    passed: " + passed + "\n";
}

/// The verifier's verdict, its read-back and every check not passed.
std::string verifyLines(const VerifyReport& r) {
    std::string other;
    int passed = 0, failed = 0, warned = 0;
    for (const Check& c : r.checks) {
        if (c.status == CheckStatus::Pass) ++passed;
        else if (c.status != CheckStatus::Skipped) {
            (c.status == CheckStatus::Fail ? failed : warned) += 1;
            other += "  " + std::string(toString(c.status)) + "      " + c.title + (c.note.empty() ? "" : ": " + c.note) + "\n";
        }
    }
    std::string out = "  verify    " + std::string(r.passed() ? "passed" : "FAILED") + ": " + std::to_string(passed) +
                      " checks passed" + (failed ? ", " + std::to_string(failed) + " failed" : "") +
                      (warned ? ", " + std::to_string(warned) + (warned == 1 ? " warning" : " warnings") : "") + "\n";
    if (r.readback) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "  read back %zu cells: heights within %.4f mm of the data (max error %.4f mm)\n",
                      r.readback->cells_checked, r.readback->tolerance_mm, r.readback->max_error_mm);
        out += buf;
    }
    return out + other;
}

/// A model whose walls are thinner than the nozzle does not print as
/// written (the slicer leaves them out): refused, nothing written, unless
/// --keep-unprintable. An InputError (exit 2): the options made it (cells or
/// a model too small for the nozzle).
void refuseUnprintable(const VerifyReport& r, double nozzle_mm, double layer_mm, bool tilted) {
    const Check* walls = r.find("wall_thickness");
    if (!walls || walls->status == CheckStatus::Pass || walls->status == CheckStatus::Skipped) return;
    std::string where;
    for (size_t k = 0; k < walls->worst.size() && k < 3; ++k) {
        const Offender& w = walls->worst[k];
        where += (k ? "; " : "") + formatSignificant(w.amount, 3) + " mm at (" + formatSignificant(w.at_mm.x, 4) + ", " +
                 formatSignificant(w.at_mm.y, 4) + ", " + formatSignificant(w.at_mm.z, 4) + ") mm";
    }
    throw InputError("the model has " + std::to_string(walls->count) + " walls thinner than the " +
                     formatSignificant(nozzle_mm, 3) + " mm nozzle, which would not print (" + where +
                     "); nothing was written. " +
                     (tilted ? "Give tilted tops a gentler --max-slope (at most " +
                                   formatSignificant(std::floor(maxSlopeDegFor(nozzle_mm, layer_mm) * 10) / 10, 3) +
                                   " degrees for this nozzle and " + formatSignificant(layer_mm, 3) + " mm layers), "
                             : std::string()) +
                     "make the cells larger (--cell, --width), give your printer's --nozzle, or --keep-unprintable "
                     "to write it anyway");
}

// One line per part for the summary: its triangles, pieces and volume; then the assembly's verdict.
std::string partsLines(const PartsVerifyReport& r) {
    std::string out;
    for (const PartReport& p : r.parts) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "  part      %-8s %zu triangles, %zu %s, %.1f mm^3: %s\n", p.name.c_str(),
                      p.report.mesh.triangle_count, p.report.mesh.component_count,
                      p.report.mesh.component_count == 1 ? "piece" : "pieces", p.report.mesh.volume_mm3,
                      p.report.passed() ? "closed solid" : "FAILED");
        out += buf;
    }
    const Check* overlap = r.assembly.find("parts_overlap");
    out += "  parts     " + std::string(r.passed() ? "passed" : "FAILED") + " (each a closed solid; " +
           (overlap && overlap->status == CheckStatus::Pass ? "they touch and never overlap" : "overlap not proven absent") +
           ")\n";
    return out;
}

}  // namespace

void summarizeVerdict(const VerifiedModel& made, const ModelRequest& rq, const Scene& scene, bool keep_unprintable,
                      GenSummary& summary) {
    summary.mesh = &made.mesh;
    if (made.report && !keep_unprintable)
        refuseUnprintable(*made.report, rq.verify_options.nozzle_mm, rq.verify_options.layer_mm,
                          scene.shapes.cells_tilted > 0);
    if (made.report) {
        summary.verify = toJson(*made.report);
        summary.verify_text = verifyLines(*made.report);
        summary.checks_text = passedChecksLine(*made.report);
        if (!scene.halves) summary.supports_text = supportsText(*made.report);
    }
    if (made.parts_report) {
        summary.verify["parts"] = toJson(*made.parts_report);
        summary.verify_text += partsLines(*made.parts_report);
    }
    if (made.halves) summarizeHalves(*made.halves, summary);
}

}  // namespace tsf::cli
