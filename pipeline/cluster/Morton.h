// Morton (Z-curve) codes of points, for the spatial layouts of level merging: the units'
// numbering inside a level (LevelMerger.cpp) and the shape of the BVH over them (MergeBvh.h).
// The codes interleave 21 bits per axis (x in bit 0, y in bit 1, z in bit 2 of each triple)
// of the point's cell in a 2^21-cell grid over the box of all the points, so points sorted by
// code follow the Z-curve, and the points whose codes share their highest bits lie in one cell
// of the octree over that box. Codes are only ever a layout: no result depends on them.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <numeric>
#include <utility>
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

// Orders positions into `codes` by (code, position): the order of sortMorton.
struct ByCode {
    const std::vector<std::uint64_t>& codes;
    bool operator()(std::uint32_t a, std::uint32_t b) const {
        return codes[a] < codes[b] || (codes[a] == codes[b] && a < b);
    }
};

// Sorts `codes` ascending and writes into `order` where each came from (order[i] = the
// position of the i-th smallest in the input), ties in input order: a stable LSD radix sort,
// 11 bits per pass over the 63 bits a code uses, skipping the passes whose digit is the same
// for every code (the counts of all passes come from one read of the codes). Linear in n,
// where a comparison sort of (code, position) pairs made log n passes of dependent compares.
inline void sortMorton(std::vector<std::uint64_t>& codes, std::vector<std::uint32_t>& order) {
    const std::size_t n = codes.size();
    order.resize(n);
    std::iota(order.begin(), order.end(), 0u);
    if (n < 512) {
        std::sort(order.begin(), order.end(), ByCode{codes});
        std::vector<std::uint64_t> sorted(n);
        for (std::size_t i = 0; i < n; ++i)
            sorted[i] = codes[order[i]];
        codes.swap(sorted);
        return;
    }
    constexpr int kBits = 11;
    constexpr int kPasses = 6; // 66 bits
    constexpr std::size_t kBuckets = std::size_t{1} << kBits;
    std::vector<std::uint32_t> count(kPasses * kBuckets, 0);
    for (const std::uint64_t c : codes) {
        for (int p = 0; p < kPasses; ++p)
            ++count[p * kBuckets + ((c >> (p * kBits)) & (kBuckets - 1))];
    }
    std::vector<std::uint64_t> codesOut(n);
    std::vector<std::uint32_t> orderOut(n);
    for (int p = 0; p < kPasses; ++p) {
        std::uint32_t* start = count.data() + p * kBuckets;
        if (std::find(start, start + kBuckets, static_cast<std::uint32_t>(n)) != start + kBuckets)
            continue; // one digit for all
        std::uint32_t sum = 0;
        for (std::size_t b = 0; b < kBuckets; ++b)
            sum += std::exchange(start[b], sum);
        const int shift = p * kBits;
        for (std::size_t i = 0; i < n; ++i) {
            const std::uint32_t at = start[(codes[i] >> shift) & (kBuckets - 1)]++;
            codesOut[at] = codes[i];
            orderOut[at] = order[i];
        }
        codes.swap(codesOut);
        order.swap(orderOut);
    }
}

} // namespace hlod
