// libFuzzer target: Grid CSV (delimiter, decimal mark, header, index column detected).
#include "gen/readers/csv_grid_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { requireValidRaster(parseCsvGrid(bytesOf(data, size), "fuzz.csv")); });
    return 0;
}
