#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <vector>

#include "pipeline/proxy/CertifiedSimplify.h"
#include "pipeline/proxy/ProxyTestUtil.h"
#include "pipeline/scene/Primitives.h"

using namespace hlod;

namespace {

float largest(const std::vector<float>& v) {
    return v.empty() ? 0.0f : *std::max_element(v.begin(), v.end());
}

} // namespace

// Rough terrains (heights 0-5 cm on 10 cm cells) at a 2 cm limit: the mapping certificate is a
// proof, so a dense brute-force sampling finds every result within the limit both ways, and no
// vertex claims more than the limit.
TEST(CertifiedSimplify, RoughTerrainStaysWithinTheLimitBothWays) {
    constexpr double limit = 0.02;
    std::size_t in = 0, out = 0;
    for (std::uint32_t seed = 1; seed <= 8; ++seed) {
        const test::Soup s = test::roughTerrain(seed);
        const CertifiedSimplifyResult r = simplifyCertified(s.positions, s.indices, {}, limit);
        in += s.indices.size() / 3;
        out += r.indices.size() / 3;
        EXPECT_LE(largest(r.vertexBounds), limit);
        EXPECT_LE(test::sampledDistance(r.positions, r.indices, s.positions, s.indices), limit);
        EXPECT_LE(test::sampledDistance(s.positions, s.indices, r.positions, r.indices), limit);
    }
    EXPECT_LT(out, in); // it simplifies (288 triangles each)
}

// A flat grid: every collapse keeps the surface where it is (bounds stay 0), down to the two
// triangles of its outline; the outline's corners never move.
TEST(CertifiedSimplify, FlatGridCollapsesToItsTwoCornerTriangles) {
    test::Soup s = test::roughTerrain(1);
    for (glm::vec3& p : s.positions)
        p.z = 0.0f;
    const CertifiedSimplifyResult r = simplifyCertified(s.positions, s.indices, {}, 0.001);
    EXPECT_EQ(r.indices.size(), 6u);
    EXPECT_LE(largest(r.vertexBounds), 1e-6f);
    for (std::uint32_t v : r.indices) {
        const glm::vec3 q = r.positions[v];
        EXPECT_TRUE((q.x < 1e-6f || q.x > 1.2f - 1e-6f) && (q.y < 1e-6f || q.y > 1.2f - 1e-6f))
            << q.x << " " << q.y;
    }
}

// A sphere of radius 1 with 2,048 faces at a 1 cm limit: within the limit both ways, and far
// fewer faces (a chord of a unit sphere sags 1 cm over 28 cm).
TEST(CertifiedSimplify, SphereStaysWithinTheLimitAndLosesMostFaces) {
    const Mesh m = makeSphere(1.0f, 64, 32);
    const CertifiedSimplifyResult r = simplifyCertified(m.positions, m.indices, {}, 0.01);
    EXPECT_LT(r.indices.size(), m.indices.size() / 2);
    EXPECT_LE(test::sampledDistance(r.positions, r.indices, m.positions, m.indices), 0.01);
    EXPECT_LE(test::sampledDistance(m.positions, m.indices, r.positions, r.indices), 0.01);
}

// A vertex that starts near the limit (its surroundings already used most of the budget)
// hands its bound on to the vertex it becomes, and no vertex ends past the limit: the bounds
// compose (a removed vertex's bound is covered by the new vertex's, MappingBound.h).
TEST(CertifiedSimplify, InputBoundsCarryOverAndNoVertexEndsPastTheLimit) {
    const test::Soup s = test::roughTerrain(2);
    std::vector<float> bounds(s.positions.size(), 0.0f);
    bounds[84] = 0.009f; // an inner vertex (row 6, column 6)
    const CertifiedSimplifyResult r = simplifyCertified(s.positions, s.indices, bounds, 0.01);
    EXPECT_LT(r.indices.size(), s.indices.size());
    const std::uint32_t to = r.representative[84];
    EXPECT_GE(r.vertexBounds[to], 0.009f);
    for (std::size_t t = 0; t < r.indices.size(); ++t)
        EXPECT_LE(r.vertexBounds[r.indices[t]], 0.01f);
}

// The same input gives the same output, to the bit.
TEST(CertifiedSimplify, IsDeterministic) {
    const test::Soup s = test::roughTerrain(5);
    const CertifiedSimplifyResult a = simplifyCertified(s.positions, s.indices, {}, 0.02);
    const CertifiedSimplifyResult b = simplifyCertified(s.positions, s.indices, {}, 0.02);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.vertexBounds, b.vertexBounds);
}
