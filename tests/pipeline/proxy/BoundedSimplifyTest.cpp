#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "pipeline/proxy/BoundedSimplify.h"
#include "pipeline/proxy/ProxyTestUtil.h"

using namespace hlod;

namespace {

struct Soup {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

// A 1.2 m x 1.2 m terrain of 12 x 12 cells, heights 0-5 cm from an integer hash (the same on
// every platform): rough at the scale of a 2-3 cm budget, so the simplifier's samples miss a
// few input triangles between them and the repair has work to do.
Soup roughTerrain(std::uint32_t seed) {
    constexpr int n = 12;
    Soup s;
    for (int i = 0; i <= n; ++i) {
        for (int j = 0; j <= n; ++j) {
            std::uint32_t h =
                seed * 0x9e3779b9u ^ static_cast<std::uint32_t>(i * 73856093 ^ j * 19349663);
            h ^= h >> 15, h *= 0x2c1b3c6du, h ^= h >> 12, h *= 0x297a2d39u, h ^= h >> 15;
            s.positions.emplace_back(i * 0.1f, j * 0.1f,
                                     0.05f * static_cast<float>(h % 1000) / 1000.0f);
        }
    }
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = 0; j < n; ++j) {
            const std::uint32_t a = i * (n + 1) + j, b = a + 1, c = a + n + 1, d = c + 1;
            s.indices.insert(s.indices.end(), {a, c, b, b, c, d});
        }
    }
    return s;
}

// Largest distance from points spread over every triangle of `from` (a 12 x 12 barycentric
// grid, corners and edges included) to the surface of `to`, brute force.
double sampledDistance(std::span<const glm::vec3> fromPositions,
                       std::span<const std::uint32_t> from, std::span<const glm::vec3> toPositions,
                       std::span<const std::uint32_t> to) {
    constexpr int k = 12;
    double worst = 0.0;
    for (std::size_t t = 0; t + 2 < from.size(); t += 3) {
        const glm::dvec3 a(fromPositions[from[t]]), b(fromPositions[from[t + 1]]),
            c(fromPositions[from[t + 2]]);
        for (int i = 0; i <= k; ++i) {
            for (int j = 0; i + j <= k; ++j) {
                const glm::dvec3 p = a + (b - a) * (double(i) / k) + (c - a) * (double(j) / k);
                double best = 1e300;
                for (std::size_t u = 0; u + 2 < to.size(); u += 3) {
                    const glm::dvec3 q = test::closestPointOnTriangle(
                        p, glm::dvec3(toPositions[to[u]]), glm::dvec3(toPositions[to[u + 1]]),
                        glm::dvec3(toPositions[to[u + 2]]));
                    best = std::min(best, glm::length(q - p));
                }
                worst = std::max(worst, best);
            }
        }
    }
    return worst;
}

} // namespace

TEST(BoundedSimplify, RoughTerrainStaysWithinTheLimitBothWaysWithPatches) {
    constexpr double limit = 0.02;
    int withPatches = 0;
    for (std::uint32_t seed = 0; seed < 12; ++seed) {
        const Soup in = roughTerrain(seed);
        BoundedSimplifyStats stats;
        const BoundedSimplifyResult r =
            simplifyWithinDeviation(in.positions, in.indices, limit, {}, &stats);
        ASSERT_FALSE(stats.unchanged) << seed;
        withPatches += stats.patched > 0 ? 1 : 0;
        // 288 input triangles; heights within 5 cm at a 2 cm budget leave well over half to go.
        EXPECT_LT(r.indices.size() / 3, in.indices.size() / 3 / 2) << seed;
        // Certified both ways; the samples here are denser than the simplifier's own (1e-6:
        // float rounding of the positions).
        EXPECT_LE(sampledDistance(r.positions, r.indices, in.positions, in.indices), limit + 1e-6)
            << seed;
        EXPECT_LE(sampledDistance(in.positions, in.indices, r.positions, r.indices), limit + 1e-6)
            << seed;
        // Copies stand at their vertex's input position, past the input's vertices.
        ASSERT_EQ(r.positions.size(), in.positions.size() + r.copies.size()) << seed;
        for (std::size_t i = 0; i < r.copies.size(); ++i)
            EXPECT_EQ(r.positions[in.positions.size() + i], in.positions[r.copies[i]]) << seed;
        // The patches are the last triangles, each an input triangle exactly as it was.
        const std::size_t first = r.indices.size() - 3 * stats.patched;
        for (std::size_t t = first; t < r.indices.size(); t += 3) {
            bool found = false;
            for (std::size_t u = 0; u < in.indices.size() && !found; u += 3) {
                found = true;
                for (int k = 0; k < 3; ++k)
                    found =
                        found && r.positions[r.indices[t + k]] == in.positions[in.indices[u + k]];
            }
            EXPECT_TRUE(found) << seed << " triangle " << t / 3;
        }
    }
    // The repair is exercised: on these terrains the samples miss input triangles (measured: 8
    // of the 12 seeds, 2-12 triangles each).
    EXPECT_GE(withPatches, 4);
}

TEST(BoundedSimplify, FlatGridCollapsesWithoutPatches) {
    // A flat grid is its own best simplification: two triangles hold it exactly (the corners
    // are where four feature planes meet), and nothing strays, so nothing is patched.
    Soup in = roughTerrain(0);
    for (glm::vec3& p : in.positions)
        p.z = 0.0f;
    BoundedSimplifyStats stats;
    const BoundedSimplifyResult r =
        simplifyWithinDeviation(in.positions, in.indices, 0.02, {}, &stats);
    EXPECT_EQ(stats.patched, 0u);
    EXPECT_TRUE(r.copies.empty());
    EXPECT_EQ(r.indices.size(), 6u);
}

TEST(BoundedSimplify, ZeroLimitReturnsTheInputUnchanged) {
    const Soup in = roughTerrain(1);
    BoundedSimplifyStats stats;
    const BoundedSimplifyResult r =
        simplifyWithinDeviation(in.positions, in.indices, 0.0, {}, &stats);
    EXPECT_TRUE(stats.unchanged);
    EXPECT_EQ(r.indices, in.indices);
    EXPECT_EQ(r.positions, in.positions);
}
