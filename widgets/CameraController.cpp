// Turntable camera navigation on a vtkCamera (see CameraController.h).
#include "widgets/CameraController.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/gtc/matrix_transform.hpp>
#include <vtkCamera.h>

namespace hlod::widgets {

namespace {

glm::dvec3 get(const double* v) { return {v[0], v[1], v[2]}; }

glm::dvec3 rotate(const glm::dvec3& v, const glm::dvec3& axis, double degrees) {
    return glm::dvec3(glm::rotate(glm::dmat4(1.0), glm::radians(degrees), axis) *
                      glm::dvec4(v, 0.0));
}

} // namespace

CameraController::CameraController(vtkCamera* camera) : camera_(camera) {}

glm::dvec3 CameraController::up() const {
    glm::dvec3 axis(0.0);
    axis[upAxis_] = 1.0;
    return axis;
}

void CameraController::setUpAxis(int axis) {
    upAxis_ = std::clamp(axis, 0, 2);
    const glm::dvec3 u = up();
    camera_->SetViewUp(u.x, u.y, u.z);
    camera_->OrthogonalizeViewUp();
}

void CameraController::setDefaultDirection() {
    // Horizontal axes for each up axis, chosen so that "front" is the side a modeller faces:
    // +Z for Y-up formats (glTF), -Y for Z-up CAD.
    glm::dvec3 right(1, 0, 0), front(0, 0, 1);
    if (upAxis_ == 2)
        front = {0, -1, 0};
    else if (upAxis_ == 0)
        right = {0, 1, 0}, front = {0, 0, 1};
    const glm::dvec3 dir = glm::normalize(0.6 * right + 0.55 * up() + 0.8 * front);
    const glm::dvec3 focal = get(camera_->GetFocalPoint());
    const double distance = std::max(camera_->GetDistance(), 1e-6);
    const glm::dvec3 eye = focal + dir * distance;
    camera_->SetPosition(eye.x, eye.y, eye.z);
    setUpAxis(upAxis_);
}

void CameraController::orbit(double azimuth, double elevation) {
    const glm::dvec3 focal = get(camera_->GetFocalPoint());
    glm::dvec3 offset = get(camera_->GetPosition()) - focal;
    const double distance = glm::length(offset);
    if (distance <= 0.0) return;
    const glm::dvec3 u = up();
    offset = rotate(offset, u, azimuth);
    // Tilt, keeping the angle to the horizon inside the clamp so the view never flips.
    const double current =
        glm::degrees(std::asin(std::clamp(glm::dot(offset, u) / distance, -1.0, 1.0)));
    const double target = std::clamp(current + elevation, -kMaxElevation, kMaxElevation);
    glm::dvec3 side = glm::cross(u, offset);
    if (glm::length(side) < 1e-12 * distance) {
        // Looking straight down the up axis: use the camera's right vector instead.
        const glm::dvec3 viewUp = get(camera_->GetViewUp());
        side = glm::cross(viewUp, offset);
    }
    offset = rotate(offset, glm::normalize(side), -(target - current));
    const glm::dvec3 eye = focal + offset;
    camera_->SetPosition(eye.x, eye.y, eye.z);
    camera_->SetViewUp(u.x, u.y, u.z);
    camera_->OrthogonalizeViewUp();
}

void CameraController::pan(double dx, double dy, int viewportHeight) {
    if (viewportHeight <= 0) return;
    const glm::dvec3 focal = get(camera_->GetFocalPoint());
    const glm::dvec3 eye = get(camera_->GetPosition());
    const double distance = glm::length(eye - focal);
    // World units per pixel at the focal plane, so the focal point moves with the cursor.
    const double worldPerPixel =
        2.0 * distance * std::tan(glm::radians(camera_->GetViewAngle()) / 2.0) / viewportHeight;
    const glm::dvec3 forward = glm::normalize(focal - eye);
    const glm::dvec3 viewUp = glm::normalize(get(camera_->GetViewUp()));
    const glm::dvec3 right = glm::normalize(glm::cross(forward, viewUp));
    const glm::dvec3 shift = (-dx * right + dy * viewUp) * worldPerPixel;
    camera_->SetFocalPoint(focal.x + shift.x, focal.y + shift.y, focal.z + shift.z);
    camera_->SetPosition(eye.x + shift.x, eye.y + shift.y, eye.z + shift.z);
}

void CameraController::dolly(double factor) {
    if (factor <= 0.0) return;
    camera_->Dolly(factor);
}

void CameraController::fit(const std::array<double, 6>& bounds, double aspect, double margin) {
    if (bounds[0] > bounds[1] || bounds[2] > bounds[3] || bounds[4] > bounds[5]) return;
    std::vector<glm::dvec3> corners;
    for (int i = 0; i < 8; ++i)
        corners.emplace_back(bounds[(i & 1) ? 1 : 0], bounds[(i & 2) ? 3 : 2],
                             bounds[(i & 4) ? 5 : 4]);
    fit(corners, aspect, margin);
}

void CameraController::fit(const std::vector<glm::dvec3>& points, double aspect, double margin) {
    if (points.empty()) return;
    glm::dvec3 lo(std::numeric_limits<double>::max()), hi(std::numeric_limits<double>::lowest());
    for (const glm::dvec3& p : points) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    glm::dvec3 back = get(camera_->GetPosition()) - get(camera_->GetFocalPoint());
    back = glm::length(back) > 0.0 ? glm::normalize(back) : glm::dvec3(0, 0, 1);
    const glm::dvec3 viewUp = glm::normalize(get(camera_->GetViewUp()));
    const glm::dvec3 right = glm::normalize(glm::cross(viewUp, back));
    const glm::dvec3 upOnScreen = glm::cross(back, right);
    const double tanV = std::tan(glm::radians(camera_->GetViewAngle()) / 2.0) * (1.0 - margin);
    const double tanH = tanV * std::max(aspect, 1e-3);
    const double minDistance = 1e-6 + glm::length(hi - lo) * 0.01;

    // Distance from `center` such that every point projects inside the frame:
    // |x| / (d - z) <= tanH and |y| / (d - z) <= tanV, with z towards the camera.
    auto distanceFor = [&](const glm::dvec3& center) {
        double d = minDistance;
        for (const glm::dvec3& p : points) {
            const glm::dvec3 rel = p - center;
            const double z = glm::dot(rel, back);
            d = std::max({d, z + std::abs(glm::dot(rel, right)) / tanH,
                          z + std::abs(glm::dot(rel, upOnScreen)) / tanV});
        }
        return d;
    };
    // Start at the box centre, then move the centre sideways so the projected extents are
    // symmetric (perspective makes one step approximate: three converge to well under a pixel
    // of imbalance that matters), keeping every point inside after each move.
    glm::dvec3 center = (lo + hi) * 0.5;
    double distance = distanceFor(center);
    for (int iteration = 0; iteration < 3; ++iteration) {
        double uMin = 1e300, uMax = -1e300, vMin = 1e300, vMax = -1e300;
        for (const glm::dvec3& p : points) {
            const glm::dvec3 rel = p - center;
            const double depth = distance - glm::dot(rel, back);
            const double u = glm::dot(rel, right) / depth, v = glm::dot(rel, upOnScreen) / depth;
            uMin = std::min(uMin, u), uMax = std::max(uMax, u);
            vMin = std::min(vMin, v), vMax = std::max(vMax, v);
        }
        center += distance * (0.5 * (uMin + uMax) * right + 0.5 * (vMin + vMax) * upOnScreen);
        distance = distanceFor(center);
    }
    const glm::dvec3 eye = center + back * distance;
    camera_->SetFocalPoint(center.x, center.y, center.z);
    camera_->SetPosition(eye.x, eye.y, eye.z);
    camera_->SetViewUp(upOnScreen.x, upOnScreen.y, upOnScreen.z);
}

} // namespace hlod::widgets
