// libFuzzer target: PNG through libpng.
#include "gen/readers/png_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { requireValidRaster(parsePng(bytesOf(data, size), "fuzz.png")); });
    return 0;
}
