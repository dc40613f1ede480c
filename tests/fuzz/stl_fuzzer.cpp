// libFuzzer target: STL, binary and ASCII (told apart by content, as readMesh does).
#include "gen/mesh_io/stl_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { requireValidMesh(parseStl(bytesOf(data, size), "fuzz.stl")); });
    return 0;
}
