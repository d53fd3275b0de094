// Simplification within a certified deviation: quadric collapses (QuadricSimplify.h), checked
// with the two-sided Hausdorff certificate of DeviationCheck.h, and repaired by restoring the
// input triangles where the check failed.
//
// Why: a quadric's error is a mean squared distance to planes, not a bound; a few collapses per
// mesh deviate several times more than it says (a thin part folded onto its side, a bend
// straightened). The bounded mode of QuadricSimplify.h certifies every face it reshapes
// against the input, but follows the input's points onto the result only by samples, so the
// final check finds a few input triangles (0.1-2 % on the engine and torcs) that stray from
// the result between samples.
// Repair: those input triangles are put back as they are (patches over the simplified
// surface, at distance 0 from the input and covering themselves), so one simplification
// suffices. The lock-and-resimplify repair this replaces (lock the failing corners, simplify
// again from the input, check again: up to 8 rounds) cost 2-5 full simplifications on the
// large nodes at the top of a tree, and kept more triangles than the patches add (engine root
// level: 6,148 + 90 patched against 6,382 after five rounds).
//
// Simplification runs at targetFraction * maxError (the quadric's measure), certified at
// maxError. Guarantee: the result is the input, or lies within maxError of it both ways
// (certified; the patches trivially).
// Output: triangles over the input's vertex numbering followed by `copies` (a patch corner
// whose vertex the simplifier moved gets a copy at its input position), with the positions
// they moved to (kept vertices move to the point of least error of the edges they took in,
// QuadricSimplify.h). Patches follow the simplified triangles, in input order.
// Deterministic, single-threaded.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/proxy/QuadricSimplify.h"

namespace hlod {

struct BoundedSimplifyOptions {
    double targetFraction = 0.6; // of maxError, given to the quadric simplifier
};

struct BoundedSimplifyStats {
    std::size_t patched = 0; // input triangles restored where the check failed
    bool unchanged = false;  // nothing collapsed: the input was returned as is
};

struct BoundedSimplifyResult {
    std::vector<std::uint32_t> indices; // into positions
    // The input's, moved where collapses moved them, then the copies.
    std::vector<glm::vec3> positions;
    // Per vertex past the input's: the input vertex it copies (at that vertex's input position).
    std::vector<std::uint32_t> copies;
};

BoundedSimplifyResult simplifyWithinDeviation(std::span<const glm::vec3> positions,
                                              std::span<const std::uint32_t> indices,
                                              double maxError,
                                              const BoundedSimplifyOptions& options = {},
                                              BoundedSimplifyStats* stats = nullptr);

// The same, continuing from `start` (a simplification of the input within maxError of it both
// ways, over the input's vertex numbering, QuadricSimplify.h), certified against the input.
BoundedSimplifyResult simplifyWithinDeviationFrom(std::span<const glm::vec3> positions,
                                                  std::span<const std::uint32_t> indices,
                                                  const QuadricStart& start, double maxError,
                                                  const BoundedSimplifyOptions& options = {},
                                                  BoundedSimplifyStats* stats = nullptr);

} // namespace hlod
