// Axis-aligned bounding box in double precision (world space may span kilometres).
#pragma once

#include <algorithm>
#include <limits>

#include <glm/glm.hpp>

namespace hlod {

struct Aabb {
    glm::dvec3 min{std::numeric_limits<double>::max()};
    glm::dvec3 max{std::numeric_limits<double>::lowest()};

    bool empty() const { return min.x > max.x || min.y > max.y || min.z > max.z; }
    void expand(const glm::dvec3& p) {
        min = glm::min(min, p);
        max = glm::max(max, p);
    }
    void expand(const Aabb& b) {
        if (b.empty()) return;
        min = glm::min(min, b.min);
        max = glm::max(max, b.max);
    }
    glm::dvec3 center() const { return (min + max) * 0.5; }
    glm::dvec3 extent() const { return empty() ? glm::dvec3(0.0) : max - min; }
    double diagonal() const { return glm::length(extent()); }
    double volume() const {
        const glm::dvec3 e = extent();
        return e.x * e.y * e.z;
    }
    // Bounds of this box after an affine transform (the 8 corners).
    Aabb transformed(const glm::dmat4& m) const;
};

} // namespace hlod
