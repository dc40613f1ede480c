// libFuzzer target: PGM, P2 and P5, 8 and 16 bit.
#include "gen/readers/pgm_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { requireValidRaster(parsePgm(bytesOf(data, size), "fuzz.pgm")); });
    return 0;
}
