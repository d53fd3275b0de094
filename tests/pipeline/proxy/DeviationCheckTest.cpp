#include <gtest/gtest.h>

#include <vector>

#include "pipeline/proxy/DeviationCheck.h"
#include "pipeline/proxy/PartwiseSimplify.h"

using namespace hlod;

namespace {

// A 2 x 2 square of 3 x 3 vertices whose middle vertex is raised by `h` (a flat tent, 8
// triangles), and its simplification to the two triangles of the flat square. The largest
// deviation is h, at the removed middle vertex: every other sample of either surface is closer.
struct Tent {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> original, simplified;
};

Tent tent(float h, const glm::vec3& at = glm::vec3(0.0f)) {
    Tent t;
    for (int y = 0; y < 3; ++y) {
        for (int x = 0; x < 3; ++x) {
            const float z = (x == 1 && y == 1) ? h : 0.0f;
            t.positions.push_back(at + glm::vec3(float(x), float(y), z));
        }
    }
    for (std::uint32_t y = 0; y < 2; ++y) {
        for (std::uint32_t x = 0; x < 2; ++x) {
            const std::uint32_t v = y * 3 + x;
            t.original.insert(t.original.end(), {v, v + 1, v + 4, v, v + 4, v + 3});
        }
    }
    t.simplified = {0, 2, 8, 0, 8, 6};
    return t;
}

} // namespace

TEST(DeviationCheck, AcceptsJustAboveTheLargestDeviationAndRejectsJustBelow) {
    // The tent's apex is 0.1 from the flattened square. The certificate works at 31/32 of the
    // limit (the rest is its slack, DeviationCheck.h), so it accepts from 0.1 * 32 / 31 = 0.1033
    // on and never accepts below 0.1.
    const Tent t = tent(0.1f);
    EXPECT_TRUE(withinDeviation(t.positions, t.original, t.simplified, 0.1034));
    EXPECT_FALSE(withinDeviation(t.positions, t.original, t.simplified, 0.1));
    EXPECT_FALSE(withinDeviation(t.positions, t.original, t.simplified, 0.099));
    // The unchanged mesh is within any limit of itself.
    EXPECT_TRUE(withinDeviation(t.positions, t.original, t.original, 1e-6));
}

TEST(DeviationCheck, ReusedCheckerAnswersLikeAFreshOne) {
    // One checker reset over meshes of different size and place (as PartwiseSimplify reuses
    // it for every part) must not keep anything of the previous mesh.
    const Tent low = tent(0.05f), high = tent(0.3f, glm::vec3(100.0f, -20.0f, 5.0f));
    DeviationChecker checker;
    for (int round = 0; round < 2; ++round) {
        checker.reset(high.positions, high.original, 0.2);
        EXPECT_FALSE(checker.accepts(high.simplified));
        checker.reset(low.positions, low.original, 0.2);
        EXPECT_TRUE(checker.accepts(low.simplified));
        checker.reset(high.positions, high.original, 0.31);
        EXPECT_TRUE(checker.accepts(high.simplified));
    }
}

TEST(PartwiseSimplify, DropsPartsBelowTheMinimumDiagonalAndKeepsTheRest) {
    // Two tents: a 2 m one (diagonal sqrt(8) = 2.83 m) and the same scaled to 1 cm
    // (diagonal 2.8 cm). With a 5 cm minimum only the large one remains; its flat-enough tent
    // (h = 1 mm against a 1 cm budget) collapses to the two triangles of its square.
    ProxyMesh mesh;
    const Tent big = tent(0.001f);
    mesh.positions = big.positions;
    mesh.indices = big.original;
    const auto offset = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::vec3& p : big.positions)
        mesh.positions.push_back(p * 0.01f + glm::vec3(10.0f, 0.0f, 0.0f));
    for (std::uint32_t v : big.original)
        mesh.indices.push_back(v + offset);
    mesh.colors.assign(mesh.positions.size(), glm::u8vec4(255));
    const std::vector<std::uint32_t> out = simplifyPartsWithinError(mesh, 0.01, 0.05f);
    ASSERT_EQ(out.size(), 6u);
    for (std::uint32_t v : out)
        EXPECT_LT(v, offset);
    EXPECT_TRUE(withinDeviation(mesh.positions, big.original, out, 0.01));
    // Without a minimum, the small tent stays (collapsed or not, it is not dropped).
    const std::vector<std::uint32_t> all = simplifyPartsWithinError(mesh, 0.01);
    std::size_t small = 0;
    for (std::uint32_t v : all)
        small += v >= offset ? 1 : 0;
    EXPECT_GE(small, 6u);
}
