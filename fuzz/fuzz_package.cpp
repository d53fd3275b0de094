// libFuzzer entry point of the package target; what it checks: fuzz/Targets.h, hlod::fuzz::package.
#include "fuzz/Targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hlod::fuzz::package(data, size);
    return 0;
}
