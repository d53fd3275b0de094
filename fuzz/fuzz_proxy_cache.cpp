// libFuzzer entry point of the proxy_cache target; what it checks: fuzz/Targets.h,
// hlod::fuzz::proxyCache.
#include "fuzz/Targets.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    hlod::fuzz::proxyCache(data, size);
    return 0;
}
