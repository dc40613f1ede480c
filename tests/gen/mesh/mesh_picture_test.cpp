// drawMeshPicture: the preview shows the model, framed to fill the picture,
// and a mirrored model's underside differs from its top.
#include "gen/mesh/mesh_picture.h"

#include <gtest/gtest.h>

#include <set>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "tests/support/meshes.h"

namespace tsf {
namespace {

// Bounding box of the pixels of [x0, x1) that are not background.
struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
};
Box drawnBox(const RgbImage& img, int from_x, int to_x) {
    Box b;
    for (int y = 0; y < img.h; ++y)
        for (int x = from_x; x < to_x; ++x)
            if (img.get(x, y) != kPictureBackground) {
                b.x0 = std::min(b.x0, x), b.x1 = std::max(b.x1, x);
                b.y0 = std::min(b.y0, y), b.y1 = std::max(b.y1, y);
            }
    return b;
}

Mesh bumpMesh(Bottom bottom) {
    const HexField f = test::fieldFromFunction(6, 5, [](int c, int r) { return double((c * 3 + r * 5) % 7); });
    return meshScene(buildScene(f, test::smallParams(bottom)));
}

TEST(MeshPicture, TheModelFillsMostOfTheFrame) {
    MeshPictureOptions o;
    const RgbImage img = drawMeshPicture(bumpMesh(Bottom::Flat), o);
    ASSERT_EQ(img.w, o.width_px);
    const Box b = drawnBox(img, 0, img.w);
    const double wide = double(b.x1 - b.x0) / img.w, tall = double(b.y1 - b.y0) / img.h;
    EXPECT_GT(std::max(wide, tall), 0.8) << wide << " x " << tall;
    // Relief reads: many distinct colours, not one flat tone.
    std::set<uint32_t> colours;
    for (int y = 0; y < img.h; y += 3)
        for (int x = 0; x < img.w; x += 3) colours.insert(img.get(x, y));
    EXPECT_GT(colours.size(), 50u);
}

// The pictures of a series share one colour scale: a block 10 mm high is
// yellow at its top on a scale of its own, but only a quarter of the way
// up (blue-green) on a scale that runs to 40 mm.
TEST(MeshPicture, ASharedColourScaleColoursTheSameHeightTheSame) {
    const Mesh block = test::box({0, 0, 0}, {50, 50, 10});
    auto reddest = [](const RgbImage& img) {
        uint32_t red = 0;
        for (int y = 0; y < img.h; ++y)
            for (int x = 0; x < img.w; ++x)
                if (img.get(x, y) != kPictureBackground) red = std::max(red, img.get(x, y) >> 16);
        return red;
    };
    MeshPictureOptions own, shared;
    shared.colour_top_z_mm = 40;
    EXPECT_GT(reddest(drawMeshPicture(block, own)), 150u);  // yellow: 240 red at full light
    EXPECT_LT(reddest(drawMeshPicture(block, shared)), 60u);   // the scale's lower quarter: 30-35 red
    // The caption says the pieces' sizes when given them.
    shared.size_text = "upper half 50 x 50 x 5, lower 50 x 50 x 5 mm";
    EXPECT_NE(drawMeshPicture(block, shared).rgb, drawMeshPicture(block, MeshPictureOptions{.colour_top_z_mm = 40}).rgb);
}

TEST(MeshPicture, TheUndersideViewDiffersFromTheTop) {
    MeshPictureOptions o;
    o.underside = true;
    const RgbImage img = drawMeshPicture(bumpMesh(Bottom::Mirrored), o);
    const int half = img.w / 2;
    const Box top = drawnBox(img, 0, half), under = drawnBox(img, half, img.w);
    EXPECT_GT(double(top.x1 - top.x0) / half, 0.7);
    EXPECT_GT(double(under.x1 - under.x0) / half, 0.7);
    int differ = 0, total = 0;
    for (int y = 0; y < img.h; ++y)
        for (int x = 0; x < half; ++x, ++total) differ += img.get(x, y) != img.get(x + half, y);
    EXPECT_GT(double(differ) / total, 0.1);
}

TEST(MeshPicture, AnEmptyMeshIsABlankPicture) {
    const RgbImage img = drawMeshPicture(Mesh{});
    EXPECT_EQ(drawnBox(img, 0, img.w).x1, -1);
}

// A class map's tops in the colours the caller gives (west half one class,
// east half another): both colours show, lit, on the tops, and no top is
// coloured by height where a colour was given.
TEST(MeshPicture, TopsTakeTheColourTheCallerGives) {
    const Mesh mesh = bumpMesh(Bottom::Flat);
    const Bounds b = meshBounds(mesh);
    const double middle = (b.min.x + b.max.x) / 2;
    MeshPictureOptions o;
    o.top_colour = [middle](double x_mm, double, uint32_t& rgb) {
        rgb = x_mm < middle ? 0xff0000 : 0x0000ff;
        return true;
    };
    const RgbImage img = drawMeshPicture(mesh, o);
    int red = 0, blue = 0;
    for (int y = 0; y < img.h; ++y)
        for (int x = 0; x < img.w; ++x) {
            const uint32_t c = img.get(x, y);
            const int r = int(c >> 16) & 0xff, g = int(c >> 8) & 0xff, bl = int(c) & 0xff;
            red += r > 80 && g == 0 && bl == 0;
            blue += bl > 80 && r == 0 && g == 0;
        }
    EXPECT_GT(red, img.w * img.h / 20);
    EXPECT_GT(blue, img.w * img.h / 20);
    EXPECT_NEAR(double(red) / blue, 1.0, 0.5);
}

}  // namespace
}  // namespace tsf
