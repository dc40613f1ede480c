#include "app/gen_run/run_report.h"

#include <iostream>
#include <utility>

#include "app/bed_size.h"
#include "app/commands.h"

namespace tsf::cli {

PrintCheckReport printCheck(const GenCommandOptions& o) {
    SlicerSettings s;
    if (o.printer.layer_mm > 0) s.layer_mm = o.printer.layer_mm;
    if (o.printer.nozzle_mm > 0) s.nozzle_mm = o.printer.nozzle_mm;
    if (!o.printer.bed.empty()) {
        const BedSize bed = parseBedSize(o.printer.bed, "--bed", /*need_height=*/false);
        s.bed_width_mm = bed.width_mm;
        s.bed_depth_mm = bed.depth_mm;
    }
    try {
        return runPrintCheck(o.output, s);
    } catch (const SlicerError& e) {
        std::cerr << "tsf: error: the model was written, but the print check failed: " << e.what() << "\n";
        throw CLI::RuntimeError(kExitToolFailed);
    }
}

void reportRun(const GenCommandOptions& o, const GenSummary& summary, const std::optional<PrintCheckReport>& printed,
               nlohmann::json* json_out) {
    if (o.json) {
        nlohmann::json j = summaryJson(summary);
        if (printed) j["print_check"] = toJson(*printed);
        if (json_out) *json_out = std::move(j);
        else std::cout << j.dump(2) << "\n";
    } else {
        std::cout << formatSummary(summary);
        if (printed) std::cout << "\n" << formatPrintCheck(*printed);
    }
}

}  // namespace tsf::cli
