// Exact intersection volumes of two bounding volumes, for the fill factor of thesis eq. 3.1
// (F_AB = (F_A V_A + F_B V_B - V_overlap) / V_AB).
//
// Sphere-sphere: the lens formed by two spherical caps (closed form, e.g. Weisstein,
// "Sphere-Sphere Intersection", MathWorld): for radii R, r at centre distance d with
// |R - r| < d < R + r,
//     V = pi (R + r - d)^2 (d^2 + 2 d (R + r) - 3 (R - r)^2) / (12 d),
// 0 when d >= R + r, and the smaller sphere's volume when one contains the other.
// Box-box: product of the per-axis overlaps (0 when any axis does not overlap).
// Units: cubic metres. Empty boxes overlap nothing.
#pragma once

#include "pipeline/bounds/Sphere.h"
#include "pipeline/scene/Aabb.h"

namespace hlod {

double sphereIntersectionVolume(const Sphere& a, const Sphere& b);
double boxIntersectionVolume(const Aabb& a, const Aabb& b);

} // namespace hlod
