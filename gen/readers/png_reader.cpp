#include "gen/readers/png_reader.h"

#include <png.h>

#include <cmath>
#include <csetjmp>
#include <cstdio>
#include <cstring>
#include <vector>

#include "gen/util/error.h"
#include "gen/readers/raster_limits.h"
#include "gen/util/file_bytes.h"

namespace tsf {
namespace {

constexpr size_t kPngSignatureBytes = 8;

struct PngSource {
    const unsigned char* data = nullptr;
    size_t size = 0;
    size_t pos = 0;
};

struct PngErrorState {
    char message[256] = {};
};

// libpng callbacks. pngError must not return: it records the message and
// jumps back to the setjmp of the phase function that is running.
void pngError(png_structp png, png_const_charp msg) {
    auto* state = static_cast<PngErrorState*>(png_get_error_ptr(png));
    std::snprintf(state->message, sizeof state->message, "%s", msg != nullptr ? msg : "unknown error");
    png_longjmp(png, 1);
}

void pngWarning(png_structp, png_const_charp) {}  // warnings (bad ancillary chunks) are not fatal

void pngRead(png_structp png, png_bytep out, size_t count) {
    auto* src = static_cast<PngSource*>(png_get_io_ptr(png));
    if (src->size - src->pos < count) png_error(png, "file is truncated");
    std::memcpy(out, src->data + src->pos, count);
    src->pos += count;
}

struct PngLayout {
    png_uint_32 width = 0;
    png_uint_32 height = 0;
    int channels = 0;        ///< after transforms: 1 grey, 2 grey+alpha, 3 RGB, 4 RGBA
    int bytes_per_sample = 0;
    size_t row_bytes = 0;
    bool grey_has_trns = false;  ///< grey image with a transparent grey level
    unsigned grey_trns = 0;
};

// Phase 1: header and transforms. Only trivially destructible locals: a
// longjmp out of libpng lands here and returns false.
bool readLayout(png_structp png, png_infop info, PngLayout* out) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_info(png, info);
    const int color_type = png_get_color_type(png, info);
    const int bit_depth = png_get_bit_depth(png, info);
    const bool grey = (color_type & PNG_COLOR_MASK_COLOR) == 0;
    if (color_type == PNG_COLOR_TYPE_PALETTE) png_set_palette_to_rgb(png);
    if (png_get_valid(png, info, PNG_INFO_tRNS)) {
        if (grey) {
            // Handled by us: libpng's tRNS expansion would also rescale 1/2/4-bit grey.
            png_bytep trans_alpha = nullptr;
            int num_trans = 0;
            png_color_16p trans_color = nullptr;
            png_get_tRNS(png, info, &trans_alpha, &num_trans, &trans_color);
            if (trans_color != nullptr) {
                out->grey_has_trns = true;
                out->grey_trns = trans_color->gray;
            }
        } else {
            png_set_tRNS_to_alpha(png);
        }
    }
    if (grey && bit_depth < 8) png_set_packing(png);  // one byte per pixel, values unscaled
    png_set_interlace_handling(png);
    png_read_update_info(png, info);
    out->width = png_get_image_width(png, info);
    out->height = png_get_image_height(png, info);
    out->channels = png_get_channels(png, info);
    out->bytes_per_sample = png_get_bit_depth(png, info) == 16 ? 2 : 1;
    out->row_bytes = png_get_rowbytes(png, info);
    return true;
}

// Phase 2: the pixels, into rows the caller allocated.
bool readPixels(png_structp png, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    return true;
}

// Largest expansion of deflate data (zlib's technical details: 1032:1),
// rounded up.
constexpr double kMaxDeflateRatio = 1040.0;

struct PngGuard {
    png_structp png = nullptr;
    png_infop info = nullptr;
    ~PngGuard() { png_destroy_read_struct(&png, info != nullptr ? &info : nullptr, nullptr); }
};

}  // namespace

Raster parsePng(std::string_view bytes, const std::string& path) {
    const auto* data = reinterpret_cast<const unsigned char*>(bytes.data());
    if (bytes.size() < kPngSignatureBytes || png_sig_cmp(data, 0, kPngSignatureBytes) != 0)
        throw InputError(path, 0, 0, "not a PNG file (no PNG signature at the start)");

    PngErrorState error_state;
    PngGuard guard;
    guard.png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &error_state, pngError, pngWarning);
    if (guard.png == nullptr) throw InputError(path, 0, 0, "cannot initialise libpng");
    guard.info = png_create_info_struct(guard.png);
    if (guard.info == nullptr) throw InputError(path, 0, 0, "cannot initialise libpng");
    PngSource source{data, bytes.size(), 0};
    png_set_read_fn(guard.png, &source, pngRead);

    PngLayout layout;
    if (!readLayout(guard.png, guard.info, &layout))
        throw InputError(path, 0, 0, std::string("invalid PNG: ") + error_state.message);
    checkRasterSize(path, 0, int64_t(layout.width), int64_t(layout.height));
    const int64_t cols = layout.width;
    const int64_t rows = layout.height;
    if (layout.row_bytes < size_t(cols) * size_t(layout.channels * layout.bytes_per_sample))
        throw InputError(path, 0, 0, "invalid PNG: unexpected row size");

    // Deflate expands at most about 1032 to 1: a file too small to hold the
    // pixels its header claims is refused before they are allocated (a
    // 235-byte PNG may claim 20000 x 5000 RGBA16, 800 MB).
    const double pixel_bytes = double(layout.row_bytes) * double(rows);
    if (pixel_bytes > kMaxDeflateRatio * double(bytes.size()))
        throw InputError(path, 0, 0,
                         "truncated or corrupt: the header claims " + std::to_string(cols) + " x " +
                             std::to_string(rows) + " pixels (" + std::to_string(int64_t(pixel_bytes)) +
                             " bytes), more than a file of " + std::to_string(bytes.size()) +
                             " bytes can hold compressed");
    std::vector<unsigned char> pixels(layout.row_bytes * size_t(rows));
    std::vector<png_bytep> row_pointers(static_cast<size_t>(rows));
    for (int64_t r = 0; r < rows; ++r) row_pointers[size_t(r)] = pixels.data() + size_t(r) * layout.row_bytes;
    if (!readPixels(guard.png, row_pointers.data()))
        throw InputError(path, 0, 0, std::string("invalid PNG: ") + error_state.message);

    Raster raster;
    raster.source = path;
    raster.kind = "png";
    raster.cols = int32_t(cols);
    raster.rows = int32_t(rows);
    raster.values.resize(size_t(cols * rows));
    const int bps = layout.bytes_per_sample;
    const int channels = layout.channels;
    const bool has_alpha = channels == 2 || channels == 4;
    const bool colour = channels >= 3;
    for (int64_t r = 0; r < rows; ++r) {
        const unsigned char* row = row_pointers[size_t(r)];
        for (int64_t c = 0; c < cols; ++c) {
            const unsigned char* px = row + size_t(c) * size_t(channels * bps);
            const auto sample = [&](int k) -> unsigned {
                return bps == 1 ? unsigned(px[k]) : (unsigned(px[2 * k]) << 8) | unsigned(px[2 * k + 1]);
            };
            double value = double(sample(0));
            if (has_alpha && sample(channels - 1) == 0) {
                value = NAN;
            } else if (colour && (sample(1) != sample(0) || sample(2) != sample(0))) {
                throw InputError(path, 0, 0,
                                 "colour PNG: pixel (col " + std::to_string(c) + ", row " + std::to_string(r) +
                                     ") is RGB (" + std::to_string(sample(0)) + ", " + std::to_string(sample(1)) +
                                     ", " + std::to_string(sample(2)) +
                                     "); tsf needs a greyscale image, e.g. GIMP: Image > Mode > Grayscale, or "
                                     "ImageMagick: convert in.png -colorspace Gray out.png");
            } else if (layout.grey_has_trns && sample(0) == layout.grey_trns) {
                value = NAN;
            }
            raster.values[size_t(r * cols + c)] = value;
        }
    }
    return raster;
}

Raster readPng(const std::string& path) {
    const std::string bytes = readFileBytes(path, kMaxInputFileBytes);
    return parsePng(bytes, path);
}

}  // namespace tsf
