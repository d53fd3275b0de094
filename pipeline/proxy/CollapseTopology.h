// Bookkeeping shared by the edge-collapse simplifiers (QuadricSimplify, CertifiedSimplify),
// which gather the inputs from their own adjacency:
// - the link condition (Dey, Edelsbrunner, Guha, Nekhayev 1999, for triangulated
//   2-manifolds): collapsing edge (u, v) keeps the surface a manifold when every vertex adjacent
//   to both u and v is the third corner of a face on the edge; otherwise the collapse would
//   pinch the surface or duplicate a face;
// - the representative chains of the collapses, resolved to the vertex each input became.
#pragma once

#include <algorithm>
#include <cstdint>
#include <span>
#include <vector>

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

// `rep[v]`: the vertex v collapsed into (v itself when it stayed). Afterwards every entry
// names the end of its chain, the vertex it finally became.
inline void resolveRepresentatives(std::vector<std::uint32_t>& rep) {
    for (std::uint32_t v = 0; v < rep.size(); ++v) {
        std::uint32_t r = v;
        while (rep[r] != r)
            r = rep[r];
        rep[v] = r; // later chains through v end at once
    }
}

} // namespace hlod
