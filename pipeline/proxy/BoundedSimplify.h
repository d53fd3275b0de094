// Simplification within a certified deviation: quadric collapses (QuadricSimplify.h), checked
// with the two-sided Hausdorff certificate of DeviationCheck.h, and repaired by locking the
// vertices where the check failed, until it passes.
//
// Why: a quadric's error is a mean squared distance to planes, not a bound; a few collapses per
// mesh deviate several times more than it says (a thin part folded onto its side, a bend
// straightened). Rejecting the whole result for them (what the part-wise meshoptimizer path
// did) kept nearly every input on scenes made of long strips. Locking only the failing places
// keeps the rest of the simplification: the next round cannot move those vertices, so an
// original triangle with all three corners locked survives unchanged, and a simplified
// triangle that cut a corner cannot form again.
//
// Rounds: simplify at targetFraction * maxError; check at maxError; on failure lock the three
// corners of every failing original triangle, and for every failing simplified triangle the
// vertices that were collapsed into its corners and lie within its longest edge of the failing
// point; repeat. After maxRounds, or when a round adds no lock, the input is returned as is.
// Guarantee: the result is the input, or lies within maxError of it both ways (certified).
// Output: triangles over the input's vertex numbering, with the positions they moved to (kept
// vertices move to the point of least error of the edges they took in, QuadricSimplify.h).
// Deterministic, single-threaded.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

struct BoundedSimplifyOptions {
    double targetFraction = 0.6; // of maxError, given to the quadric simplifier
    int maxRounds = 8;
};

struct BoundedSimplifyStats {
    int rounds = 0;         // simplification rounds run
    std::size_t locked = 0; // vertices locked by failed checks
    bool fellBack = false;  // the input was returned unsimplified
};

struct BoundedSimplifyResult {
    std::vector<std::uint32_t> indices; // into positions
    std::vector<glm::vec3> positions;   // the input's, moved where collapses moved them
};

BoundedSimplifyResult simplifyWithinDeviation(std::span<const glm::vec3> positions,
                                              std::span<const std::uint32_t> indices,
                                              double maxError,
                                              const BoundedSimplifyOptions& options = {},
                                              BoundedSimplifyStats* stats = nullptr);

} // namespace hlod
