// libFuzzer entry point of the project target; what it checks: fuzz/Targets.h, hlod::fuzz::project.
#include "fuzz/Targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hlod::fuzz::project(data, size);
    return 0;
}
