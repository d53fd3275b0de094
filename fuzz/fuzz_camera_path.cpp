// libFuzzer entry point of the camera_path target; what it checks: fuzz/Targets.h,
// hlod::fuzz::cameraPath.
#include "fuzz/Targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hlod::fuzz::cameraPath(data, size);
    return 0;
}
