// Bounding sphere value type shared by bounds computation, clustering and LOD selection.
// Units: metres, world space (double precision: scenes may span kilometres).
#pragma once

#include <glm/glm.hpp>

namespace hlod {

struct Sphere {
    glm::dvec3 center{0.0};
    double radius = 0.0;
    // 4/3 pi r^3, in cubic metres.
    double volume() const;
};

} // namespace hlod
