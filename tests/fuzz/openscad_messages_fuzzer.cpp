// libFuzzer target: OpenSCAD's console output parsed into messages (what
// tsf render reports from an engine's output).
#include "tests/fuzz/fuzz_target.h"
#include "runners/openscad/openscad_messages.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { (void)parseOpenScadOutput(std::string(bytesOf(data, size))); });
    return 0;
}
