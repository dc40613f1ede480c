#include "gen/io/load_field.h"

#include "gen/error.h"
#include "gen/io/point_binning.h"
#include "gen/io/point_reader.h"
#include "gen/io/raster_reader.h"
#include "gen/resample.h"

namespace tsf {

HexField loadField(const FieldLoadOptions& o) {
    if (!o.delimiter.empty() && o.delimiter != "," && o.delimiter != ";" && o.delimiter != "tab" &&
        o.delimiter != "\t" && o.delimiter != "space" && o.delimiter != " ")
        throw InputError("--delimiter: expected , ; tab or space, got '" + o.delimiter + "'");
    const char delimiter = o.delimiter.empty()                              ? 0
                           : (o.delimiter == "tab" || o.delimiter == "\t") ? '\t'
                           : (o.delimiter == "space" || o.delimiter == " ") ? ' '
                                                                            : o.delimiter[0];
    if (!o.points.empty()) {
        PointColumns cols = parsePointColumns(o.points);
        cols.delimiter = delimiter;
        const PointTable table = readPointsCsv(o.input, cols);
        BinOptions b;
        b.aggregate = parseAggregate(o.aggregate);
        b.bin_size = o.bin_size;
        b.hex_cols = o.bins;
        HexField f = binPoints(table, b);
        f.source = o.input;
        return f;
    }
    RasterReadOptions ro;
    ro.delimiter = delimiter;
    const Raster raster = readRaster(o.input, ro);
    ResampleOptions rs;
    rs.hex_cols = o.bins;
    rs.method = parseResampleMethod(o.sample);
    HexField f = resampleRaster(raster, rs);
    f.source = o.input;
    return f;
}

}  // namespace tsf
