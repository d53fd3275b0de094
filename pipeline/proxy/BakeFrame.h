// The frame a node's proxy is baked in, quantised so that translated copies of a cluster bake
// to bit-identical proxies (issue "A compact package": rigid copies share one proxy).
//
// A node's proxy lives relative to its first input's position (an instance's translation, a
// child proxy's origin, in double). Its inputs are placed by their offsets from that origin.
// Two copies of a cluster compute these offsets from different world coordinates, so they may
// differ in the last bits; rounded to a power-of-two grid they become equal, and so do the
// aggregated floats, the
// simplification and the cache key. The grid is the largest power of two at most 1/1024 of
// the node's error budget, so rounding moves an input by at most sqrt(3)/2048 of the budget
// (far below what the deviation check can tell apart). The budget itself is rounded down to
// 10 significant bits (at most 0.1 % smaller), so copies whose spheres differ in the last
// bits share it; rounding down never loosens the 1-pixel bound.
#pragma once

#include <glm/glm.hpp>

namespace hlod {

// `budget` rounded down to 10 significant bits (0 and non-finite values are returned as is).
double quantizedBudget(double budget);

// Grid spacing (metres) of the offsets of a node with error budget `budget` (> 0).
double offsetGrid(double budget);

// `offset` rounded to the nearest multiple of `grid` on every axis.
glm::dvec3 quantizeOffset(const glm::dvec3& offset, double grid);

} // namespace hlod
