// The link condition of an edge collapse (Dey, Edelsbrunner, Guha, Nekhayev 1999, for
// triangulated 2-manifolds): collapsing edge (u, v) keeps the surface a manifold when every
// vertex adjacent to both u and v is the third corner of a face on the edge; otherwise the
// collapse would pinch the surface or duplicate a face. Shared by the simplifiers
// (QuadricSimplify, CertifiedSimplify), which gather the inputs from their own adjacency.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>

namespace hlod {

// `aroundU`, `aroundV`: the neighbours of u and of v, each sorted ascending; `opposite`: the
// third corners of the faces on edge (u, v), in any order. True when the collapse is allowed.
inline bool linkConditionHolds(std::span<const std::uint32_t> aroundU,
                               std::span<const std::uint32_t> aroundV,
                               std::span<const std::uint32_t> opposite) {
    std::size_t i = 0, j = 0;
    while (i < aroundU.size() && j < aroundV.size()) {
        if (aroundU[i] < aroundV[j]) {
            ++i;
        } else if (aroundV[j] < aroundU[i]) {
            ++j;
        } else {
            if (std::find(opposite.begin(), opposite.end(), aroundU[i]) == opposite.end())
                return false;
            ++i, ++j;
        }
    }
    return true;
}

} // namespace hlod
