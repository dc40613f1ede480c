// libFuzzer target: The scene sidecar (JSON).
#include "gen/model/scene_json.h"
#include "tests/fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    using namespace tsf;
    using namespace tsf::fuzz;
    acceptOrInputError([&] { (void)parseSceneJson(std::string(bytesOf(data, size)), "fuzz.scene.json"); });
    return 0;
}
