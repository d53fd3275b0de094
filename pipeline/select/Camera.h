// A perspective camera for LOD selection: what the renderer sees, in world units (metres).
// Frustum planes follow Gribb & Hartmann, "Fast Extraction of Viewing Frustum Planes from the
// World-View-Projection Matrix" (2001).
#pragma once

#include <array>

#include <glm/glm.hpp>

namespace hlod {

struct Camera {
    glm::dvec3 eye{0.0, 0.0, 10.0};
    glm::dvec3 target{0.0};
    glm::dvec3 up{0.0, 1.0, 0.0};
    double fovY = 0.7853981633974483; // vertical field of view, radians (45°)
    double aspect = 16.0 / 9.0;       // width / height
    int viewportHeight = 1080;        // pixels
    double nearPlane = 0.1;
    double farPlane = 1.0e5;

    glm::dmat4 view() const;
    glm::dmat4 projection() const;
    // Pixels per world unit at distance 1 along the view axis: H / (2 tan(fovY/2)).
    double pixelsPerUnitAtDistanceOne() const;
};

// Planes (a,b,c,d) with normals pointing inside: a point p is inside when a·p + d >= 0.
struct Frustum {
    std::array<glm::dvec4, 6> planes;
    static Frustum fromCamera(const Camera& camera);
    // False when the sphere lies entirely outside one plane.
    bool intersectsSphere(const glm::dvec3& center, double radius) const;
};

// Distance from which a sphere of `radius` projects to `screenSizePx` pixels in diameter:
// d = r · H / (tan(fovY/2) · S). Closer than that, the node is too big and is refined.
double switchDistance(double radius, double screenSizePx, double fovY, int viewportHeight);

} // namespace hlod
