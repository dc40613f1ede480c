// Shared helpers for the haptics tests: small fields with known geometry.
#pragma once

#include <memory>
#include <vector>

#include "haptics/field_mapping.h"
#include "haptics/force_model.h"
#include "haptics/scale_space.h"

namespace tsf::haptics::testing {

/// A field, its scale space and a model over the default (Falcon-like)
/// workspace; the space lives as long as the fixture.
struct Scene {
    DeviceLimits limits;
    std::unique_ptr<ScaleSpace> space;
    FieldMapping mapping;
    ForceModel model;
};

inline std::unique_ptr<Scene> makeScene(const HeightGrid& grid, ForceParams params = {}, int levels = 1,
                                        ScaleSpaceKind kind = ScaleSpaceKind::kMipmap, double rate_Hz = 1000.0) {
    auto s = std::make_unique<Scene>();
    s->space = std::make_unique<ScaleSpace>(buildScaleSpace(grid, levels, kind));
    s->mapping = mapFieldToWorkspace(grid.cols, grid.rows, s->limits.workspace);
    s->model = makeForceModel(*s->space, s->mapping, params, s->limits, rate_Hz);
    return s;
}

/// cols x rows field whose height rises linearly from 0 (west) to 1 (east).
inline HeightGrid eastRamp(int cols, int rows) {
    std::vector<float> h;
    for (int j = 0; j < rows; ++j)
        for (int i = 0; i < cols; ++i) h.push_back(float(i) / float(cols - 1));
    return makeHeightGrid(cols, rows, h);
}

inline HeightGrid flatField(int cols, int rows, float h = 0.5f) {
    return makeHeightGrid(cols, rows, std::vector<float>(size_t(cols) * size_t(rows), h));
}

/// One call of the force model with velocity and time given.
inline ForceOutput probe(const ForceModel& m, const ForceState& s, Vec3 p, double t = 0.0, Vec3 v = Vec3(0.0),
                         double gain = 1.0) {
    ForceInput in;
    in.t_s = t;
    in.position_m = p;
    in.velocity_m_per_s = v;
    in.output_gain = gain;
    return computeForce(m, s, in);
}

}  // namespace tsf::haptics::testing
