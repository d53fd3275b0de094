// Screen-space error budget (thesis 2.2.1 / 5.3), see ErrorBudget.h for the derivation.
#include "pipeline/proxy/ErrorBudget.h"

#include <cmath>
#include <string>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

void requireRange(const char* name, double value, double lo, double hi, bool openEnds) {
    const bool ok = openEnds ? (value > lo && value < hi) : (value >= lo && value <= hi);
    if (!std::isfinite(value) || !ok) {
        throw Error(ErrorCode::InvalidArgument,
                    std::string(name) + " must be within " + (openEnds ? "(" : "[") +
                        std::to_string(lo) + ", " + std::to_string(hi) + (openEnds ? ")" : "]") +
                        ", got " + std::to_string(value));
    }
}

} // namespace

void validate(const ScreenParams& params) {
    requireRange("screen size", params.screenSize, 1.0, 100000.0, false);
    requireRange("pixel error", params.pixelError, 0.01, 1000.0, false);
    requireRange("field of view", params.fovYDegrees, 0.0, 180.0, true);
    requireRange("viewport height", params.viewportHeight, 1.0, 100000.0, false);
}

double nodeDiameter(const ClusterNode& node) {
    if (node.sphere.radius > 0.0) return 2.0 * node.sphere.radius;
    return node.box.diagonal();
}

double proxyErrorBudget(double diameter, const ScreenParams& params) {
    return params.pixelError * diameter / params.screenSize;
}

double switchDistance(double diameter, const ScreenParams& params) {
    const double halfFov = params.fovYDegrees * 0.5 * 3.14159265358979323846 / 180.0;
    return diameter * params.viewportHeight / (2.0 * params.screenSize * std::tan(halfFov));
}

} // namespace hlod
