// libFuzzer target: 3MF through lib3mf.
#include "gen/mesh_io/three_mf_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { requireValidMesh(parse3mf(bytesOf(data, size), "fuzz.3mf")); });
    return 0;
}
