// libFuzzer entry point of the gltf target; what it checks: fuzz/Targets.h, hlod::fuzz::gltf.
#include "fuzz/Targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hlod::fuzz::gltf(data, size);
    return 0;
}
