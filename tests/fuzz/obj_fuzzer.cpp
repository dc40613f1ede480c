// libFuzzer target: Wavefront OBJ.
#include "gen/mesh_io/obj_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { requireValidMesh(parseObj(bytesOf(data, size), "fuzz.obj")); });
    return 0;
}
