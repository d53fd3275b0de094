// Morton (Z-curve) codes of points, for the spatial layouts of level merging: the units'
// numbering inside a level (LevelMerger.cpp) and the shape of the BVH over them (MergeBvh.h).
// The codes interleave 21 bits per axis (x in bit 0, y in bit 1, z in bit 2 of each triple)
// of the point's cell in a 2^21-cell grid over the box of all the points, so points sorted by
// code follow the Z-curve, and the points whose codes share their highest bits lie in one cell
// of the octree over that box. Codes are only ever a layout: no result depends on them.
#pragma once

#include <algorithm>
#include <cstdint>
#include <vector>

#include <glm/glm.hpp>

#include "pipeline/scene/Aabb.h"

namespace hlod {

namespace morton {

// Spreads the low 21 bits of x to every third bit.
inline std::uint64_t spreadBits(std::uint64_t x) {
    x &= 0x1fffffu;
    x = (x | x << 32) & 0x1f00000000ffffu;
    x = (x | x << 16) & 0x1f0000ff0000ffu;
    x = (x | x << 8) & 0x100f00f00f00f00fu;
    x = (x | x << 4) & 0x10c30c30c30c30c3u;
    x = (x | x << 2) & 0x1249249249249249u;
    return x;
}

} // namespace morton

// out[i] = the code of point(i), i = 0..n-1 (a NaN coordinate lands in cell 0).
template <class Point>
void mortonCodes(std::size_t n, Point&& point, std::vector<std::uint64_t>& out) {
    Aabb all;
    for (std::size_t i = 0; i < n; ++i)
        all.expand(point(i));
    constexpr double kCells = double((1u << 21) - 1);
    const glm::dvec3 extent = glm::max(all.max - all.min, glm::dvec3(1e-300));
    const glm::dvec3 scale = glm::dvec3(kCells) / extent;
    const auto cell = [&](double x) -> std::uint64_t {
        return x >= 0.0 ? static_cast<std::uint64_t>(std::min(x, kCells)) : 0u;
    };
    out.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 q = (point(i) - all.min) * scale;
        out[i] = morton::spreadBits(cell(q.x)) | morton::spreadBits(cell(q.y)) << 1 |
                 morton::spreadBits(cell(q.z)) << 2;
    }
}

} // namespace hlod
