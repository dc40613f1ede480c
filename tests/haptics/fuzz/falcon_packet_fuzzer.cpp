// libFuzzer entry point for the Falcon frame parser (built with clang only:
// cmake -DTSF_BUILD_FUZZERS=ON -DCMAKE_CXX_COMPILER=clang++; run
// build/tests/falcon_packet_fuzzer). The property lives in
// falcon_stream_property.h, which the normal test suite also runs on
// random streams.
#include <cstddef>
#include <cstdint>

#include "tests/haptics/falcon_stream_property.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    tsf::haptics::testing::checkFalconStream(data, size, unsigned(size));
    return 0;
}
