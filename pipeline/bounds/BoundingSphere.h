// Tight bounding spheres.
//
// Based on E. Welzl, "Smallest enclosing disks (balls and ellipsoids)", LNCS 555, 1991: the
// minimum enclosing ball of a point set, in its iterative form (nested loops over a random
// permutation, support sets of up to four points), expected linear time. The thesis (section
// 3.2.3) asks for minimum bounding spheres per mesh; Welzl gives the exact minimum, where
// Ritter's heuristic is typically 5-20 % larger in radius (so about 15-70 % in volume, which
// would distort the fill factors).
//
// Determinism: the permutation comes from a fixed-seed generator, so the same points give the
// same sphere bit for bit, on every run and thread.
// Robustness: the computation runs relative to the points' bounding-box centre (so kilometre
// coordinates do not eat the precision of centimetre parts), degenerate support sets
// (collinear, coplanar) fall back to the smallest valid sphere of a subset, and a final pass
// grows the radius to the farthest point, so every point is inside the result whatever the
// rounding.
#pragma once

#include <span>

#include <glm/glm.hpp>

#include "pipeline/bounds/Sphere.h"

namespace hlod {

// Minimum enclosing sphere of `points`. Empty input gives radius 0 at the origin; one point
// gives radius 0 at that point.
Sphere minimumBoundingSphere(std::span<const glm::dvec3> points);

// Smallest sphere containing both spheres (exact; the larger one when it contains the other).
// Not symmetric bit for bit under rounding: callers that need determinism pass the operands
// in a canonical order.
Sphere enclosingSphere(const Sphere& a, const Sphere& b);

// True when `inner` lies inside `outer` up to a relative tolerance `relTol` of outer's radius
// (plus an absolute `absTol` in metres).
bool sphereContains(const Sphere& outer, const Sphere& inner, double relTol = 1e-9,
                    double absTol = 1e-9);

} // namespace hlod
