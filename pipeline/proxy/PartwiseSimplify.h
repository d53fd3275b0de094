// Error-bounded quadric simplification of a mesh made of many disconnected parts (an
// aggregated proxy input), one connected part at a time.
//
// Based on: quadric edge collapse (Garland & Heckbert 1997, meshoptimizer's meshopt_simplify)
// and the sampled two-sided Hausdorff test of DeviationCheck.h (Metro, Cignoni et al. 1998).
//
// Why per part: edge collapses never join disconnected parts, so simplifying the parts one by
// one gives the same kind of result as one call on the whole mesh, but the deviation check and
// its retries become local. meshoptimizer's error is an area-weighted RMS distance, so some
// parts deviate more than requested; checked as a whole, one such part forces the whole node
// back to a smaller target (measured on engine-2cylinder: most nodes needed the 0.25 or 0.15
// step). Per part, only the parts that fail are redone, the others keep the coarse result.
//
// Contract: returns indices into `mesh.positions` such that every part's simplified triangles
// lie within `maxError` metres of that part's input triangles and back (sampled as in
// DeviationCheck.h); a part for which no step fits keeps its input triangles. Triangle order:
// parts in the order of their first input triangle. Single-threaded, deterministic.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "pipeline/proxy/ProxyMesh.h"

namespace hlod {

// meshoptimizer targets tried per part, as fractions of `maxError`, largest first.
inline constexpr double kPartTargetFractions[] = {0.9, 0.6, 0.4, 0.25, 0.15};

std::vector<std::uint32_t>
simplifyPartsWithinError(const ProxyMesh& mesh, double maxError,
                         std::span<const double> fractions = kPartTargetFractions);

} // namespace hlod
