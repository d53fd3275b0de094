// Exact overlap volumes (formulas and references in OverlapVolume.h).
#include "pipeline/bounds/OverlapVolume.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace hlod {

double Sphere::volume() const { return 4.0 / 3.0 * std::numbers::pi * radius * radius * radius; }

double sphereIntersectionVolume(const Sphere& a, const Sphere& b) {
    const double d = glm::length(b.center - a.center);
    const double big = std::max(a.radius, b.radius);
    const double small = std::min(a.radius, b.radius);
    if (d >= big + small) return 0.0;
    if (d <= big - small) return Sphere{glm::dvec3(0.0), small}.volume();
    const double sum = big + small;
    const double diff = big - small;
    const double lens = (sum - d) * (sum - d) * (d * d + 2.0 * d * sum - 3.0 * diff * diff);
    // Rounding near tangency can push the product a hair below zero.
    return std::max(0.0, std::numbers::pi * lens / (12.0 * d));
}

double boxIntersectionVolume(const Aabb& a, const Aabb& b) {
    if (a.empty() || b.empty()) return 0.0;
    const glm::dvec3 lo = glm::max(a.min, b.min);
    const glm::dvec3 hi = glm::min(a.max, b.max);
    const glm::dvec3 e = hi - lo;
    if (e.x <= 0.0 || e.y <= 0.0 || e.z <= 0.0) return 0.0;
    return e.x * e.y * e.z;
}

} // namespace hlod
