// Dropping whole parts of a proxy that the rest of it already stands for (issue "every proxy
// pays for itself": let a proxy join and drop whole parts within the budget).
//
// Why: parts smaller than the budget already go (SmallParts.h), but long thin parts do not:
// the back face of a two-sided barrier (a sheet of its own once the two sides are welded
// apart), a kerb or barrier a metre tall along a road seen with a two-metre budget, a sign on a
// wall. Each is longer than the budget, and its borders hold the simplifier, so it stays a
// ribbon of triangles at every level (torcs-spring: the reason proxies of whole stretches of
// track kept most of their input). When every point of such a part lies within the budget of
// the rest of the proxy, the rest stands for it within one pixel at the switch, and the part
// can go.
//
// Rule (greedy, deterministic): parts are visited by decreasing area (ties by part number);
// a part is dropped when every point of its input triangles lies within `limit` of the
// simplified triangles of the parts kept before it (certified as in DeviationCheck.h), and kept
// otherwise. The kept set only grows, so a drop stays valid: the proxy (kept parts, simplified)
// is within the limit of the input, and every dropped part within the limit of the proxy.
// Input: `partOfVertex` numbers every used vertex's connected part (0..partCount-1); the
// simplified triangles of a part use only that part's vertices (collapses never join parts).
// Output: one flag per part, 1 = keep. Single-threaded.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

namespace hlod {

// `simplified` indexes `simplifiedPositions` (vertices numbered as the input's; moved).
std::vector<std::uint8_t> keepUncoveredParts(std::span<const glm::vec3> positions,
                                             std::span<const std::uint32_t> input,
                                             std::span<const glm::vec3> simplifiedPositions,
                                             std::span<const std::uint32_t> simplified,
                                             std::span<const std::uint32_t> partOfVertex,
                                             std::size_t partCount, double limit);

} // namespace hlod
