// Screen-space error budget (thesis 2.2.1 / 5.3), see ErrorBudget.h for the derivation.
#include "pipeline/proxy/ErrorBudget.h"

#include <cmath>
#include <string>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

// The ranges a user may give are declared once, in pipeline/graph/Parameters.cpp, and checked
// where a value enters (a flag, a project file, the panel). Here only the domain of the formulas
// below is guarded, for callers that fill ScreenParams themselves: a division by S, t and H,
// and tan(fov / 2), which is finite and positive only for 0 < fov < 180 degrees.
void requirePositive(const char* name, double value) {
    if (!std::isfinite(value) || value <= 0.0) {
        throw Error(ErrorCode::InvalidArgument,
                    std::string(name) + " must be a positive number, got " + std::to_string(value));
    }
}

} // namespace

void validate(const ScreenParams& params) {
    requirePositive("screen size", params.screenSize);
    requirePositive("pixel error", params.pixelError);
    requirePositive("viewport height", params.viewportHeight);
    if (!(params.fovYDegrees > 0.0 && params.fovYDegrees < 180.0)) {
        throw Error(ErrorCode::InvalidArgument,
                    "field of view must be between 0 and 180 degrees, got " +
                        std::to_string(params.fovYDegrees));
    }
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
