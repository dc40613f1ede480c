// libFuzzer target: ESRI ASCII grid.
#include "gen/readers/esri_ascii_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { requireValidRaster(parseEsriAscii(bytesOf(data, size), "fuzz.asc")); });
    return 0;
}
