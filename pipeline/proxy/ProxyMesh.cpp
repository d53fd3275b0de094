#include "pipeline/proxy/ProxyMesh.h"

#include <algorithm>
#include <cmath>

#include "pipeline/core/Error.h"

namespace hlod {

const char* toString(ProxyMethod method) {
    switch (method) {
    case ProxyMethod::Decimate:
        return "decimate";
    case ProxyMethod::Remesh:
        return "remesh";
    case ProxyMethod::Sloppy:
        return "sloppy";
    }
    return "decimate";
}

ProxyMethod proxyMethodFromString(const std::string& text) {
    if (text == "decimate") return ProxyMethod::Decimate;
    if (text == "remesh") return ProxyMethod::Remesh;
    if (text == "sloppy") return ProxyMethod::Sloppy;
    throw Error(ErrorCode::InvalidArgument,
                "unknown proxy method '" + text + "' (expected decimate, remesh or sloppy)");
}

glm::u8vec4 quantizeColor(const glm::vec4& linear) {
    glm::u8vec4 out;
    for (int i = 0; i < 4; ++i) {
        const float c = std::isfinite(linear[i]) ? std::clamp(linear[i], 0.0f, 1.0f) : 1.0f;
        out[i] = static_cast<std::uint8_t>(std::lround(c * 255.0f));
    }
    return out;
}

} // namespace hlod
