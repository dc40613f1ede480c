// libFuzzer target: tsf feel --device replay: files.
#include "haptics/replay_device.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { (void)haptics::parseReplayCsv(std::string(bytesOf(data, size)), "fuzz-replay.csv"); });
    return 0;
}
