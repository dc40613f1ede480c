// A Scene that breaks the mesher's invariants is a typed error (InputError)
// from meshScene, never an assertion: such a Scene can come from a library
// user or an edited scene sidecar.
#include "gen/model/scene_check.h"

#include <gtest/gtest.h>

#include "gen/mesh/direct_mesher.h"
#include "gen/util/error.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {
using test::fieldFromFunction;
using test::smallParams;

Scene wholeGrid(int cols, int rows, Bottom bottom) {
    return buildScene(fieldFromFunction(cols, rows, [](int c, int r) { return 1.0 + (c + 2 * r) % 4; }),
                      smallParams(bottom, Cull::None));
}

// The Scene without kept cell (col, row), lists and kept_index kept consistent.
Scene without(Scene s, int32_t col, int32_t row) {
    const int32_t k = s.keptAt(col, row);
    EXPECT_GE(k, 0);
    s.col.erase(s.col.begin() + k);
    s.row.erase(s.row.begin() + k);
    s.value.erase(s.value.begin() + k);
    s.top.erase(s.top.begin() + k);
    s.bottom.erase(s.bottom.begin() + k);
    s.kept_index.assign(s.kept_index.size(), -1);
    for (size_t i = 0; i < s.col.size(); ++i) s.kept_index[size_t(s.grid.index(s.col[i], s.row[i]))] = int32_t(i);
    return s;
}

TEST(SceneCheck, WhatBuildSceneMakesPasses) {
    for (Bottom b : {Bottom::Flat, Bottom::Mirrored}) {
        EXPECT_NO_THROW(checkScene(wholeGrid(6, 5, b)));
        EXPECT_NO_THROW(checkScene(buildScene(fieldFromFunction(9, 7, [](int c, int r) { return c * r % 5; }),
                                              smallParams(b, Cull::Hull))));
    }
    EXPECT_NO_THROW(checkScene(Scene{}));
    EXPECT_TRUE(meshScene(Scene{}).triangles.empty());
}

TEST(SceneCheck, NeighboursThatDoNotOverlapInZAreAnInputError) {
    Scene s = wholeGrid(3, 3, Bottom::Mirrored);
    const size_t k = size_t(s.keptAt(1, 1));
    s.bottom[k] = 1'000'000;  // far above every neighbour's top
    s.top[k] = s.bottom[k] + 5;
    EXPECT_INPUT_ERROR(meshScene(s), "do not overlap in z");
}

TEST(SceneCheck, BottomNotBelowTopIsAnInputError) {
    Scene s = wholeGrid(3, 3, Bottom::Mirrored);
    s.top[0] = s.bottom[0];
    EXPECT_INPUT_ERROR(meshScene(s), "must be below the top");
}

TEST(SceneCheck, TwoPiecesAreAnInputError) {
    EXPECT_INPUT_ERROR(meshScene(without(wholeGrid(3, 1, Bottom::Mirrored), 1, 0)), "more than one piece");
}

TEST(SceneCheck, AFlatBottomWithAHoleIsAnInputError) {
    const Scene holed = without(wholeGrid(5, 5, Bottom::Flat), 2, 2);
    EXPECT_INPUT_ERROR(meshScene(holed), "hole at grid cell (2, 2)");
    // A mirrored bottom has no bottom polygon: a ring is a fine solid.
    EXPECT_NO_THROW(meshScene(without(wholeGrid(5, 5, Bottom::Mirrored), 2, 2)));
}

TEST(SceneCheck, AFlatBottomAboveZeroIsAnInputError) {
    Scene s = wholeGrid(3, 3, Bottom::Flat);
    s.bottom[4] = 1;
    EXPECT_INPUT_ERROR(meshScene(s), "bottom is 0");
}

TEST(SceneCheck, InconsistentListsAreAnInputError) {
    Scene s = wholeGrid(3, 3, Bottom::Flat);
    s.top.pop_back();
    EXPECT_INPUT_ERROR(meshScene(s), "differ in length");
    s = wholeGrid(3, 3, Bottom::Flat);
    s.kept_index[0] = 5;
    EXPECT_INPUT_ERROR(meshScene(s), "disagree");
    s = wholeGrid(3, 3, Bottom::Flat);
    s.col[0] = 7;
    EXPECT_INPUT_ERROR(meshScene(s), "disagree");
    s = wholeGrid(3, 3, Bottom::Flat);
    s.pitch_mm = 0;
    EXPECT_INPUT_ERROR(meshScene(s), "pitch_mm");
}

}  // namespace
}  // namespace tsf
