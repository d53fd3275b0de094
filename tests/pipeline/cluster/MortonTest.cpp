// Morton codes and their sort (pipeline/cluster/Morton.h): the codes interleave the three
// axes' cells, and sortMorton orders any codes as a comparison sort of (code, position) does,
// for the small sizes it sorts by comparison and the large ones it sorts by radix.
#include <algorithm>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/cluster/Morton.h"

namespace hlod {
namespace {

TEST(Morton, CodesInterleaveTheAxesOverTheBoxOfThePoints) {
    // The box of the points is [0, 2]^3, so 2 is the last cell (2^21 - 1) of every axis and
    // 1 the middle one (2^20 - 1, rounded down).
    const std::vector<glm::dvec3> points{{0, 0, 0}, {2, 0, 0}, {0, 2, 0},
                                         {0, 0, 2}, {2, 2, 2}, {1, 1, 1}};
    std::vector<std::uint64_t> codes;
    mortonCodes(
        points.size(), [&](std::size_t i) { return points[i]; }, codes);
    const std::uint64_t x = 0x1249249249249249u; // every third bit of 63
    EXPECT_EQ(codes[0], 0u);
    EXPECT_EQ(codes[1], x);
    EXPECT_EQ(codes[2], x << 1);
    EXPECT_EQ(codes[3], x << 2);
    EXPECT_EQ(codes[4], x | x << 1 | x << 2);
    const std::uint64_t mid = morton::spreadBits((1u << 20) - 1);
    EXPECT_EQ(codes[5], mid | mid << 1 | mid << 2);
    // A NaN coordinate lands in cell 0 of its axis, the others keep theirs.
    const std::vector<glm::dvec3> withNan{
        {0, 0, 0}, {2, 2, 2}, {std::numeric_limits<double>::quiet_NaN(), 2, 2}};
    mortonCodes(
        withNan.size(), [&](std::size_t i) { return withNan[i]; }, codes);
    EXPECT_EQ(codes[2], x << 1 | x << 2);
}

TEST(Morton, SortIsTheComparisonSortOfCodeAndPosition) {
    std::mt19937_64 rng(11);
    for (std::size_t n : {0u, 1u, 7u, 511u, 512u, 5000u, 70000u}) {
        for (int variant = 0; variant < 3; ++variant) {
            std::vector<std::uint64_t> codes(n);
            for (std::uint64_t& c : codes) {
                const std::uint64_t r = rng() >> 1; // 63 bits, as codes have
                // 0: any codes; 1: few distinct codes (long runs of ties); 2: codes that differ
                // only in their middle bits (the passes over the low and high digits skipped).
                c = variant == 0   ? r
                    : variant == 1 ? r % 5
                                   : (r & 0xffffff000u) | 0x7000000000000001u;
            }
            std::vector<std::uint32_t> expected(n);
            for (std::uint32_t i = 0; i < n; ++i)
                expected[i] = i;
            std::sort(expected.begin(), expected.end(), [&](std::uint32_t a, std::uint32_t b) {
                return codes[a] < codes[b] || (codes[a] == codes[b] && a < b);
            });
            std::vector<std::uint64_t> sorted = codes;
            std::vector<std::uint32_t> order;
            sortMorton(sorted, order);
            ASSERT_EQ(order, expected) << "n=" << n << " variant " << variant;
            for (std::size_t i = 0; i < n; ++i)
                ASSERT_EQ(sorted[i], codes[order[i]]);
        }
    }
}

} // namespace
} // namespace hlod
