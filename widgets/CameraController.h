// Turntable camera navigation on a vtkCamera, driven by the viewport's mouse and key handlers.
//
// Turntable rather than VTK's trackball: orbiting turns around the scene's up axis and tilts
// around the camera's horizontal axis (clamped short of the poles), so the horizon never rolls;
// that is what users of DCC tools and CAD viewers expect when inspecting buildings and plants.
// All angles are degrees; pan is in viewport pixels so the point under the cursor follows it.
#pragma once

#include <array>
#include <vector>

#include <glm/glm.hpp>

class vtkCamera;

namespace hlod::widgets {

class CameraController {
public:
    explicit CameraController(vtkCamera* camera);

    // 0 = X, 1 = Y, 2 = Z. Also resets the view up vector of the camera.
    void setUpAxis(int axis);
    int upAxis() const { return upAxis_; }

    // Turns the camera around the focal point: `azimuth` around the up axis, `elevation` tilts
    // towards the up axis. Elevation stays within +-kMaxElevation degrees.
    void orbit(double azimuth, double elevation);
    // Moves camera and focal point in the view plane by a pixel offset of a viewport
    // `viewportHeight` pixels high (x right, y down as in Qt).
    void pan(double dx, double dy, int viewportHeight);
    // Moves towards the focal point: factor > 1 gets closer (distance / factor).
    void dolly(double factor);
    // Looks at `points` from the current direction: the view is centred on them and the camera
    // is just far enough that every point is inside the frustum with `margin` (fraction of the
    // half-frame) to spare. `aspect` = width / height. Points can be the corners of each
    // instance's box: much tighter than one box around the scene for sparse layouts.
    void fit(const std::vector<glm::dvec3>& points, double aspect, double margin = 0.06);
    // Same for the 8 corners of `bounds` (xmin, xmax, ymin, ymax, zmin, zmax).
    void fit(const std::array<double, 6>& bounds, double aspect, double margin = 0.06);
    // The default view: from the front, right and above (about 30 degrees elevation).
    void setDefaultDirection();

    static constexpr double kMaxElevation = 89.0;

private:
    glm::dvec3 up() const;

    vtkCamera* camera_;
    int upAxis_ = 1;
};

} // namespace hlod::widgets
