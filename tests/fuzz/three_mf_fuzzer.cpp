// libFuzzer target: 3MF through lib3mf, as one mesh and as parts.
#include "gen/mesh_io/three_mf_reader.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { requireValidMesh(parse3mf(bytesOf(data, size), "fuzz.3mf")); });
    // As parts: the slicer config's triangle ranges come from the file too.
    acceptOrInputError([&] {
        for (const MeshPart& p : parse3mfParts(bytesOf(data, size), "fuzz.3mf")) requireValidMesh(p.mesh);
    });
    return 0;
}
