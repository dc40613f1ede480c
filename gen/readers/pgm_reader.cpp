#include "gen/readers/pgm_reader.h"

#include <algorithm>

#include "gen/util/error.h"
#include "gen/readers/number_field.h"
#include "gen/readers/raster_limits.h"
#include "gen/util/file_bytes.h"
#include "gen/util/text_scanner.h"

namespace tsf {
namespace {

constexpr int64_t kMaxPgmMaxval = 65535;
constexpr int64_t kMaxHeaderNumber = int64_t(1) << 40;  // far above any valid size; keeps arithmetic safe

int64_t readHeaderNumber(TextScanner& scanner, const std::string& path, const char* what) {
    std::string_view token;
    if (!scanner.next(token))
        throw InputError(path, scanner.line() > 0 ? scanner.line() : 1, 0,
                         std::string("file ends before the PGM ") + what);
    int64_t v = 0;
    if (!parseWholeNumber(token, kMaxHeaderNumber, v))
        throw InputError(path, scanner.line(), scanner.column(),
                         std::string("expected the PGM ") + what + " (a whole number), found " +
                             quoteForMessage(token));
    return v;
}

std::string otherNetpbmHint(char kind) {
    switch (kind) {
        case '1': case '4': return "a PBM bitmap";
        case '3': case '6': return "a colour PPM image";
        case '7': return "a PAM image";
        default: return "";
    }
}

std::string pixelName(int64_t index, int64_t width) {
    return "pixel (col " + std::to_string(index % width) + ", row " + std::to_string(index / width) + ")";
}

}  // namespace

Raster parsePgm(std::string_view bytes, const std::string& path) {
    if (bytes.size() < 2 || bytes[0] != 'P' || (bytes[1] != '2' && bytes[1] != '5')) {
        if (bytes.size() >= 2 && bytes[0] == 'P') {
            const std::string kind = otherNetpbmHint(bytes[1]);
            if (!kind.empty())
                throw InputError(path, 1, 1,
                                 "is " + kind + " (magic P" + std::string(1, bytes[1]) +
                                     "), expected a greymap (P2 or P5); convert it, e.g. "
                                     "`pnmtopnm`/`ppmtopgm in.ppm > out.pgm`");
        }
        throw InputError(path, 1, 1, "not a PGM file: expected \"P2\" or \"P5\" at the start");
    }
    const bool binary = bytes[1] == '5';
    if (bytes.size() > 2 && bytes[2] != ' ' && bytes[2] != '\t' && bytes[2] != '\n' && bytes[2] != '\r' &&
        bytes[2] != '#')
        throw InputError(path, 1, 3, "expected whitespace after the magic number \"P" + std::string(1, bytes[1]) + "\"");

    TextScanner header(bytes, path, /*comment=*/'#', 2, 1, 3);
    const int64_t width = readHeaderNumber(header, path, "width");
    const int width_line = header.line();
    const int64_t height = readHeaderNumber(header, path, "height");
    checkRasterSize(path, width_line, width, height);
    const int64_t maxval = readHeaderNumber(header, path, "maxval");
    if (maxval < 1 || maxval > kMaxPgmMaxval)
        throw InputError(path, header.line(), header.column(),
                         "maxval " + std::to_string(maxval) + " is out of range; expected 1..65535");

    Raster raster;
    raster.source = path;
    raster.kind = "pgm";
    raster.cols = int32_t(width);
    raster.rows = int32_t(height);
    const int64_t cells = width * height;

    if (binary) {
        // Exactly one whitespace byte separates maxval from the samples.
        const size_t after_maxval = header.offset();
        if (after_maxval < bytes.size()) {
            const char c = bytes[after_maxval];
            if (c != ' ' && c != '\t' && c != '\n' && c != '\r')
                throw InputError(path, header.line(), header.column(),
                                 "expected a single whitespace byte after maxval, found " +
                                     quoteForMessage(bytes.substr(after_maxval, 1)));
        }
        const size_t data_start = after_maxval + 1;
        const int64_t bytes_per_sample = maxval < 256 ? 1 : 2;
        const int64_t needed = cells * bytes_per_sample;
        const int64_t available = data_start <= bytes.size() ? int64_t(bytes.size() - data_start) : 0;
        if (available < needed)
            throw InputError(path, 0, 0,
                             "truncated: the " + std::to_string(width) + " x " + std::to_string(height) +
                                 " image with maxval " + std::to_string(maxval) + " needs " +
                                 std::to_string(needed) + " bytes of samples from byte offset " +
                                 std::to_string(data_start) + ", but the file ends at byte offset " +
                                 std::to_string(bytes.size()) + " (" + std::to_string(available) +
                                 " bytes, " + std::to_string(available / bytes_per_sample) + " samples)");
        raster.values.resize(size_t(cells));
        const auto* p = reinterpret_cast<const unsigned char*>(bytes.data() + data_start);
        for (int64_t k = 0; k < cells; ++k) {
            const int64_t v = bytes_per_sample == 1 ? int64_t(p[k]) : (int64_t(p[2 * k]) << 8) | int64_t(p[2 * k + 1]);
            if (v > maxval)
                throw InputError(path, 0, 0,
                                 "sample " + std::to_string(v) + " at byte offset " +
                                     std::to_string(data_start + size_t(k * bytes_per_sample)) + " (" +
                                     pixelName(k, width) + ") is above maxval " + std::to_string(maxval));
            raster.values[size_t(k)] = double(v);
        }
        return raster;
    }

    // P2: at least 2 bytes per sample (digit + separator) bound the allocation.
    raster.values.reserve(size_t(std::min<int64_t>(cells, int64_t(bytes.size() / 2 + 1))));
    std::string_view token;
    while (int64_t(raster.values.size()) < cells) {
        if (!header.next(token))
            throw InputError(path, header.line(), 0,
                             "truncated: expected " + std::to_string(cells) + " grey levels (" +
                                 std::to_string(width) + " x " + std::to_string(height) + "), found " +
                                 std::to_string(raster.values.size()));
        int64_t v = 0;
        if (!parseWholeNumber(token, kMaxHeaderNumber, v))
            throw InputError(path, header.line(), header.column(),
                             "expected a grey level 0.." + std::to_string(maxval) + ", found " +
                                 quoteForMessage(token));
        if (v > maxval)
            throw InputError(path, header.line(), header.column(),
                             "grey level " + std::to_string(v) + " is above maxval " + std::to_string(maxval));
        raster.values.push_back(double(v));
    }
    if (header.next(token))
        throw InputError(path, header.line(), header.column(),
                         "more grey levels than width x height = " + std::to_string(cells) +
                             "; check the size in the header");
    return raster;
}

Raster readPgm(const std::string& path) {
    const std::string bytes = readFileBytes(path, kMaxInputFileBytes);
    return parsePgm(bytes, path);
}

}  // namespace tsf
