#include "gen/model/attachments.h"

#include <algorithm>
#include <optional>

#include "gen/model/feature_registry.h"
#include "gen/model/features/halves.h"
#include "gen/model/features/marks.h"

namespace tsf {

std::vector<Attachment> sceneAttachments(const Scene& scene, Assembly assembly) {
    std::vector<Attachment> out;
    if (scene.keptCount() == 0) return out;
    const auto add = [&](std::optional<Attachment> a) {
        if (a) out.push_back(std::move(*a));
    };
    // The registry's features where they stood: the one carrying the
    // marks first, the legend, the features beside the pillars.
    for (const Feature* f : featuresMarksFirst())
        if (f->attachment) add(f->attachment(scene, assembly));
    return out;
}

std::vector<ProbeSet> sceneProbes(const Scene& scene) {
    std::vector<ProbeSet> out;
    // The one carrying the marks is read back with them, last.
    std::vector<ProbeSet> sets;
    for (const Feature* f : featuresOf({FeaturePhase::BeforeMarks, FeaturePhase::Beside}))
        if (f->probes) sets.push_back(f->probes(scene));
    sets.push_back(markProbes(scene));
    for (const Feature* f : featuresOf({FeaturePhase::Marks}))
        if (f->probes) sets.push_back(f->probes(scene));
    for (ProbeSet& set : sets)
        if (!set.probes.empty()) out.push_back(std::move(set));
    return out;
}

void checkAttachments(const Scene& scene) {
    for (const Feature* f : featuresMarksLast())
        if (f->check) f->check(scene);
}

std::vector<BoxMm> attachmentBoxes(const Scene& scene) {
    std::vector<BoxMm> boxes;
    std::vector<std::optional<BoxMm>> all;
    for (const Feature* f : featuresMarksFirst())
        if (f->box) all.push_back(f->box(scene));
    for (const auto& box : all)
        if (box) boxes.push_back(*box);
    return boxes;
}

BoxMm sceneFootprint(const Scene& s) {
    BoxMm f{1e300, -1e300, 1e300, -1e300};
    auto add = [&f](const BoxMm& b) {
        f.x0 = std::min(f.x0, b.x0), f.x1 = std::max(f.x1, b.x1), f.y0 = std::min(f.y0, b.y0), f.y1 = std::max(f.y1, b.y1);
    };
    for (size_t k = 0; k < s.keptCount(); ++k) {
        const LatticePoint c = hexCentre(s.grid, s.col[k], s.row[k]);
        add({latticeX({c.i - 1, 0}, s.pitch_mm), latticeX({c.i + 1, 0}, s.pitch_mm), latticeY({0, c.j - 2}, s.pitch_mm, s.y_scale),
             latticeY({0, c.j + 2}, s.pitch_mm, s.y_scale)});
    }
    for (const BoxMm& b : attachmentBoxes(s)) add(b);
    return f;
}

std::vector<SideWidth> attachmentSideWidths(const SceneParams& params) {
    // The features beside the pillars (the tactile scale east of them),
    // then the one carrying the marks (the orientation tab west of them).
    std::vector<SideWidth> out;
    for (const Feature* f : featuresMarksLast())
        if (f->side_width)
            if (std::optional<SideWidth> w = f->side_width(params)) out.push_back(std::move(*w));
    return out;
}

std::vector<BottomHole> sceneBottomHoles(const Scene& scene) {
    std::vector<BottomHole> holes = halfBottomHoles(scene);
    for (BottomHole& h : featureBottomHoles(scene)) holes.push_back(std::move(h));
    return holes;
}

std::vector<int64_t> attachmentTopsAt(const Scene& scene, double x_mm, double y_mm) {
    std::vector<int64_t> tops;
    std::vector<std::optional<int64_t>> all;
    for (const Feature* f : featuresMarksFirst())
        if (f->top_at) all.push_back(f->top_at(scene, x_mm, y_mm));
    for (const auto& top : all)
        if (top) tops.push_back(*top);
    return tops;
}

}  // namespace tsf
