// RgbImage: a small 8-bit RGB picture for the pictures tsf draws itself
// (feel --plot, gen --preview), with a 3 x 5 pixel font for labels and an
// atomic PNG writer.
//
// Layout: row-major, row 0 at the top, 3 bytes per pixel (R, G, B). Colours
// are 0xRRGGBB. Drawing outside the picture is clipped.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace tsf {

struct RgbImage {
    int w = 0, h = 0;
    std::vector<uint8_t> rgb;  ///< w * h * 3

    /// A w x h picture filled with `background`.
    RgbImage(int width, int height, uint32_t background);
    void set(int x, int y, uint32_t c);
    uint32_t get(int x, int y) const;
    /// A filled disc of radius r pixels.
    void dot(int x, int y, int r, uint32_t c);
    /// A filled rectangle [x0, x1) x [y0, y1).
    void fill(int x0, int y0, int x1, int y1, uint32_t c);
    /// A line `thickness` pixels wide.
    void line(double x0, double y0, double x1, double y1, int thickness, uint32_t c);
};

/// Draws `text` with its top-left corner at (x, y), each font pixel `scale`
/// image pixels square. Letters (upper case; lower case is drawn as upper),
/// digits and " .,:;-+/()=%'<>_" have glyphs; any other character is blank.
void drawText(RgbImage& img, int x, int y, std::string_view text, int scale, uint32_t c);

/// Width in pixels of drawText(text, scale).
int textWidth(std::string_view text, int scale);

/// Height in pixels of one line of drawText at `scale`.
inline int textHeight(int scale) { return 5 * scale; }

/// Writes the picture as an 8-bit RGB PNG, atomically (atomic_file.h).
/// Throws tsf::OutputError when it cannot be written.
void writePng(const std::string& path, const RgbImage& img);

}  // namespace tsf
