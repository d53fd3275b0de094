// libFuzzer entry point of the scene target; what it checks: fuzz/Targets.h, hlod::fuzz::scene.
#include "fuzz/Targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hlod::fuzz::scene(data, size);
    return 0;
}
