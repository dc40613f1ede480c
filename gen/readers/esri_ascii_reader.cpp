#include "gen/readers/esri_ascii_reader.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "gen/util/error.h"
#include "gen/readers/number_field.h"
#include "gen/readers/raster_limits.h"
#include "gen/util/file_bytes.h"
#include "gen/util/text_scanner.h"

namespace tsf {
namespace {

constexpr int64_t kMaxHeaderCount = int64_t(1) << 40;  // far above any valid size; keeps arithmetic safe

std::string lowerCase(std::string_view s) {
    std::string out(s);
    for (char& c : out)
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
    return out;
}

struct HeaderValue {
    double value = 0.0;
    int line = 0;
    int column = 0;
};

struct EsriHeader {
    std::optional<HeaderValue> ncols, nrows, xllcorner, xllcenter, yllcorner, yllcenter, cellsize, dx, dy, nodata;
};

std::optional<HeaderValue>* headerSlot(EsriHeader& h, const std::string& key) {
    if (key == "ncols") return &h.ncols;
    if (key == "nrows") return &h.nrows;
    if (key == "xllcorner") return &h.xllcorner;
    if (key == "xllcenter") return &h.xllcenter;
    if (key == "yllcorner") return &h.yllcorner;
    if (key == "yllcenter") return &h.yllcenter;
    if (key == "cellsize") return &h.cellsize;
    if (key == "dx") return &h.dx;
    if (key == "dy") return &h.dy;
    if (key == "nodata_value") return &h.nodata;
    return nullptr;
}

bool startsLikeNumber(std::string_view token) {
    const char c = token.empty() ? '\0' : token[0];
    return (c >= '0' && c <= '9') || c == '-' || c == '+' || c == '.';
}

}  // namespace

Raster parseEsriAscii(std::string_view text, const std::string& path) {
    const size_t bom = text.substr(0, 3) == "\xEF\xBB\xBF" ? 3 : 0;  // some editors write a UTF-8 BOM
    TextScanner scanner(text, path, /*comment=*/'\0', bom, 1, 1);
    EsriHeader h;
    std::string_view token;
    bool have_token = scanner.next(token);
    if (!have_token) throw InputError(path, 0, 0, "is empty; expected an ESRI ASCII grid header (ncols ...)");

    // Header: key/value pairs until the first token that looks like a number.
    while (have_token && !startsLikeNumber(token) && !(lowerCase(token) == "nan")) {
        const std::string key = lowerCase(token);
        const int key_line = scanner.line(), key_column = scanner.column();
        std::optional<HeaderValue>* slot = headerSlot(h, key);
        if (slot == nullptr)
            throw InputError(path, key_line, key_column,
                             "unknown ESRI grid header key " + quoteForMessage(token) +
                                 "; expected ncols, nrows, xllcorner/xllcenter, yllcorner/yllcenter, cellsize, "
                                 "NODATA_value");
        if (slot->has_value())
            throw InputError(path, key_line, key_column,
                             "header key " + quoteForMessage(token) + " is given twice (first on line " +
                                 std::to_string((*slot)->line) + ")");
        if (!scanner.next(token))
            throw InputError(path, key_line, key_column, "header key " + key + " has no value");
        HeaderValue hv;
        hv.line = scanner.line();
        hv.column = scanner.column();
        if (key == "ncols" || key == "nrows") {
            int64_t n = 0;
            if (!parseWholeNumber(token, kMaxHeaderCount, n))
                throw InputError(path, hv.line, hv.column,
                                 key + " must be a whole number, found " + quoteForMessage(token));
            hv.value = double(n);
        } else {
            const NumberField kind = parseStrictNumber(token, hv.value);
            if (kind != NumberField::Number) {
                if (key == "nodata_value" && kind == NumberField::NotNumber && lowerCase(token) == "nan") {
                    hv.value = NAN;  // GDAL writes "NODATA_value nan"; NaN cells are no data anyway
                } else {
                    throw InputError(path, hv.line, hv.column, key + ": " + badNumberMessage(kind, token));
                }
            }
        }
        *slot = hv;
        have_token = scanner.next(token);
    }

    const int data_line = have_token ? scanner.line() : scanner.currentLine();
    const auto require = [&](const std::optional<HeaderValue>& v, const char* name) {
        if (!v) throw InputError(path, data_line, 0, std::string("the header has no ") + name);
    };
    require(h.ncols, "ncols");
    require(h.nrows, "nrows");
    if (!h.xllcorner && !h.xllcenter) require(h.xllcorner, "xllcorner or xllcenter");
    if (!h.yllcorner && !h.yllcenter) require(h.yllcorner, "yllcorner or yllcenter");
    if (h.xllcorner && h.xllcenter)
        throw InputError(path, h.xllcenter->line, 0, "the header has both xllcorner and xllcenter");
    if (h.yllcorner && h.yllcenter)
        throw InputError(path, h.yllcenter->line, 0, "the header has both yllcorner and yllcenter");
    double cellsize = 0.0;
    if (h.cellsize) {
        if (h.dx || h.dy) throw InputError(path, (h.dx ? h.dx : h.dy)->line, 0, "the header has both cellsize and dx/dy");
        cellsize = h.cellsize->value;
    } else if (h.dx && h.dy) {
        if (h.dx->value != h.dy->value)
            throw InputError(path, h.dy->line, 0,
                             "cells are not square (dx " + std::to_string(h.dx->value) + " != dy " +
                                 std::to_string(h.dy->value) + "); resample to square cells first");
        cellsize = h.dx->value;
    } else {
        require(h.cellsize, "cellsize");
    }
    if (!(cellsize > 0.0)) {
        const HeaderValue& at = h.cellsize ? *h.cellsize : *h.dx;
        throw InputError(path, at.line, at.column, "cellsize must be greater than 0");
    }
    const int64_t cols = int64_t(h.ncols->value);
    const int64_t rows = int64_t(h.nrows->value);
    checkRasterSize(path, h.nrows->line, cols, rows);

    Raster raster;
    raster.source = path;
    raster.kind = "esri-ascii";
    raster.cols = int32_t(cols);
    raster.rows = int32_t(rows);
    raster.cell_size = cellsize;
    raster.x_origin = h.xllcorner ? h.xllcorner->value : h.xllcenter->value - 0.5 * cellsize;
    raster.y_origin = h.yllcorner ? h.yllcorner->value : h.yllcenter->value - 0.5 * cellsize;
    raster.place = {.known = true,
                    .x_west = raster.x_origin,
                    .dx = cellsize,
                    .y_north = raster.y_origin + cellsize * double(raster.rows),
                    .dy = cellsize,
                    .axes = {}};
    const bool has_nodata = h.nodata.has_value() && !std::isnan(h.nodata->value);
    const double nodata = has_nodata ? h.nodata->value : 0.0;

    const int64_t cells = cols * rows;
    raster.values.reserve(size_t(std::min<int64_t>(cells, int64_t(text.size() / 2 + 1))));

    // Line structure: decided by the first data line (see the header comment).
    int line_now = have_token ? scanner.line() : 0;
    int64_t on_line = 0;
    int lines_done = 0;
    bool row_structured = false;
    const auto finishLine = [&](int line) {
        if (lines_done == 0) row_structured = on_line == cols;
        else if (row_structured && on_line != cols)
            throw InputError(path, line, 0,
                             "line has " + std::to_string(on_line) + " values, expected ncols = " +
                                 std::to_string(cols));
        ++lines_done;
        on_line = 0;
    };

    while (have_token) {
        if (scanner.line() != line_now) {
            finishLine(line_now);
            line_now = scanner.line();
        }
        if (int64_t(raster.values.size()) == cells)
            throw InputError(path, scanner.line(), scanner.column(),
                             "more values than ncols x nrows = " + std::to_string(cols) + " x " +
                                 std::to_string(rows) + " = " + std::to_string(cells));
        double v = 0.0;
        const NumberField kind = parseNumberField(token, v);
        if (kind == NumberField::Number) {
            raster.values.push_back(has_nodata && v == nodata ? NAN : v);
        } else if (kind == NumberField::NoData) {
            raster.values.push_back(NAN);
        } else {
            throw InputError(path, scanner.line(), scanner.column(), badNumberMessage(kind, token));
        }
        ++on_line;
        have_token = scanner.next(token);
    }
    if (on_line > 0) finishLine(line_now);
    if (int64_t(raster.values.size()) < cells)
        throw InputError(path, line_now > 0 ? line_now : scanner.line(), 0,
                         "too few values: expected ncols x nrows = " + std::to_string(cols) + " x " +
                             std::to_string(rows) + " = " + std::to_string(cells) + ", found " +
                             std::to_string(raster.values.size()));
    return raster;
}

Raster readEsriAscii(const std::string& path) {
    const std::string bytes = readFileBytes(path, kMaxInputFileBytes);
    return parseEsriAscii(bytes, path);
}

}  // namespace tsf
