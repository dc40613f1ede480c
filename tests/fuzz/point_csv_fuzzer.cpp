// libFuzzer target: point CSV (tsf gen --points), by header names and by
// column indices.
#include "gen/readers/point_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    static const PointColumns by_name = parsePointColumns("x=lon,y=lat,w=weight");
    static const PointColumns by_index = parsePointColumns("x=0,y=1");
    for (const PointColumns* cols : {&by_name, &by_index})
        acceptOrInputError([&] {
            const PointTable t = parsePointsCsv(bytesOf(data, size), "fuzz.csv", *cols);
            if (t.y.size() != t.x.size() || (t.hasWeight() && t.weight.size() != t.x.size())) __builtin_trap();
        });
    return 0;
}
