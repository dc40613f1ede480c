// libFuzzer target: OFF.
#include "gen/mesh_io/off_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { requireValidMesh(parseOff(bytesOf(data, size), "fuzz.off")); });
    return 0;
}
