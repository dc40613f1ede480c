#include "gen/app/preview.h"

#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <unistd.h>

#include "gen/util/temp_files.h"
#include "verify/render/openscad_runner.h"

namespace tsf::cli {

void writeModelPreview(const std::string& model_path, const std::string& png_path, int width_px, int height_px) {
    namespace fs = std::filesystem;
    const fs::path model = fs::absolute(model_path);
    const ScopedTempFile scad("tsf-preview-", ".scad");  // removed on every exit, signals included
    {
        std::ofstream out(scad.path());
        // A warm colour and the default light show steps between pillars clearly.
        out << "color(\"#e8a33d\") import(\"" << model.generic_string() << "\");\n";
    }
    ScadRenderRequest rq;
    rq.scad_path = scad.path();
    rq.output_path = png_path;
    rq.format = ScadExportFormat::Png;
    rq.png.width_px = width_px;
    rq.png.height_px = height_px;
    rq.timeout_s = 300;
    const auto engine = makeOpenScadEngine();
    const ScadRenderResult result = renderScad(*engine, rq);
    if (!result.ok()) {
        std::string lines;
        for (const ScadMessage& m : result.errors()) lines += "\n  " + m.text;
        throw std::runtime_error("the preview picture could not be drawn: " + result.summary + lines);
    }
}

}  // namespace tsf::cli
