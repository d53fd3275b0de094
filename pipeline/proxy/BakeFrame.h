// The frame a node's proxy is baked in, quantised so that rigid copies of a cluster (translated
// and turned, issue 26 "rigid copies bake once") bake to bit-identical proxies.
//
// A node's frame is the frame of its first placed input: a leaf instance's translation and the
// rotation of its world matrix's linear part (frameRotation: the Q of its QR decomposition, so
// the frame turns with the instance), an inner child's frame. Every input is placed in the
// node's frame by its linear part and offset relative to that frame, both quantised:
//
// - Offsets are rounded to a power-of-two grid, the largest one at most 1/1024 of the node's
//   error budget: rounding moves an input by at most sqrt(3)/2048 of the budget.
// - Linear parts (an instance's linear map, an inner child's rotation, expressed in the node's
//   frame) are rounded column by column to a power-of-two grid of 2^-32 of the column's length
//   (that length itself rounded to 32 significant bits first, so that copies agree on the
//   grid): a point p of the part moves by at most sqrt(3) * 2^-32 * sum_k |L e_k| |p_k|, below
//   1/100 of the float rounding (2^-24 relative) every stored position already has.
//
// Two copies of a cluster compute these relative placements from different world matrices, so
// they differ in the last bits (about 1e-16 relative); rounded, they are equal (a straddled
// grid midpoint, chance ~1e-6 per number, only costs a second bake), and so are the aggregated
// floats, the simplification and the cache key. The budget is rounded down to 10 significant
// bits (at most 0.1 % smaller), so copies whose spheres differ in the last bits share it;
// rounding down never loosens the 1-pixel bound. What the quantisation moves (placementError)
// is far below the budget, which is what the deviation check can tell apart.
#pragma once

#include <glm/glm.hpp>

namespace hlod {

// A rigid frame in world space: world point = origin + rotation * local point.
struct RigidFrame {
    glm::dvec3 origin{0.0};
    glm::dmat3 rotation{1.0};

    glm::dmat4 matrix() const;
    bool turned() const { return rotation != glm::dmat3(1.0); }
};

// `budget` rounded down to 10 significant bits (0 and non-finite values are returned as is).
double quantizedBudget(double budget);

// Grid spacing (metres) of the offsets of a node with error budget `budget` (> 0).
double offsetGrid(double budget);

// `offset` rounded to the nearest multiple of `grid` on every axis.
glm::dvec3 quantizeOffset(const glm::dvec3& offset, double grid);

// The proper rotation (determinant +1) of the frame a linear map places its mesh in: Gram-
// Schmidt of its columns (the Q of L = QR), the third axis negated when L mirrors. Exactly the
// identity for a diagonal L with a positive diagonal (a translated or scaled instance), and
// turning L turns the result: frameRotation(R L) = R frameRotation(L) up to rounding. The
// identity when L is degenerate (a zero or dependent column).
glm::dmat3 frameRotation(const glm::dmat3& linear);

// `linear` rounded column by column (see the top of the file). Zero columns stay zero.
glm::dmat3 quantizeLinear(const glm::dmat3& linear);

// Placement of a part in a node's frame: its linear part and offset as the frame stores them.
struct PartPlacement {
    glm::dmat3 linear{1.0};
    glm::dvec3 offset{0.0};
};

// Where a part with world linear map `linear` and world position `at` sits in `frame`,
// quantised for a node of error budget `budget`: quantizeLinear(R^T linear) and
// quantizeOffset(R^T (at - origin), offsetGrid(budget)).
PartPlacement placeInFrame(const RigidFrame& frame, const glm::dmat3& linear, const glm::dvec3& at,
                           double budget);

// The most placeInFrame's rounding can move a point of the part that lies within `reach`
// (metres, in the part's own frame, measured from its origin) of the part's origin.
double placementError(const PartPlacement& placement, double reach, double budget);

} // namespace hlod
