#include "pipeline/select/Camera.h"

#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace hlod {

glm::dmat4 Camera::view() const { return glm::lookAt(eye, target, up); }

glm::dmat4 Camera::projection() const {
    return glm::perspective(fovY, aspect, nearPlane, farPlane);
}

double Camera::pixelsPerUnitAtDistanceOne() const {
    return static_cast<double>(viewportHeight) / (2.0 * std::tan(fovY * 0.5));
}

Frustum Frustum::fromCamera(const Camera& camera) {
    const glm::dmat4 m = camera.projection() * camera.view();
    // Rows of the combined matrix (glm is column-major: m[col][row]).
    auto row = [&](int r) { return glm::dvec4(m[0][r], m[1][r], m[2][r], m[3][r]); };
    Frustum f;
    f.planes = {row(3) + row(0), row(3) - row(0), row(3) + row(1),
                row(3) - row(1), row(3) + row(2), row(3) - row(2)};
    for (glm::dvec4& p : f.planes)
        p /= glm::length(glm::dvec3(p));
    return f;
}

bool Frustum::intersectsSphere(const glm::dvec3& c, double r) const {
    for (const glm::dvec4& p : planes) {
        if (glm::dot(glm::dvec3(p), c) + p.w < -r) return false;
    }
    return true;
}

double switchDistance(double radius, double screenSizePx, double fovY, int viewportHeight) {
    return radius * static_cast<double>(viewportHeight) / (std::tan(fovY * 0.5) * screenSizePx);
}

} // namespace hlod
