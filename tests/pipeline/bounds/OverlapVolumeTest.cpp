// Exact overlap volumes against hand-computed values (pipeline/bounds/OverlapVolume.h).
#include <numbers>

#include <gtest/gtest.h>

#include "pipeline/bounds/OverlapVolume.h"

namespace hlod {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(OverlapVolume, UnitSpheresOneApartShareFivePiOverTwelve) {
    // Two caps of height h = 1/2 each: 2 * pi h^2 (3r - h) / 3 = 2 * pi / 4 * 2.5 / 3 = 5 pi / 12.
    const Sphere a{{0, 0, 0}, 1.0};
    const Sphere b{{1, 0, 0}, 1.0};
    EXPECT_NEAR(sphereIntersectionVolume(a, b), 5.0 * kPi / 12.0, 1e-12);
    EXPECT_NEAR(sphereIntersectionVolume(b, a), 5.0 * kPi / 12.0, 1e-12);
}

TEST(OverlapVolume, UnequalSpheresMatchCapSum) {
    // R = 2 at 0, r = 1 at 2: the radical plane is at x = (d^2 + R^2 - r^2) / 2d = 7/4, so the
    // big sphere's cap has height 2 - 7/4 = 1/4 and the small one's 1 - 1/4 = 3/4.
    // V = pi/3 * (h1^2 (3R - h1) + h2^2 (3r - h2)) = pi/3 * (1/16 * 23/4 + 9/16 * 9/4)
    //   = pi/3 * (23 + 81) / 64 = 13 pi / 24.
    const Sphere a{{0, 0, 0}, 2.0};
    const Sphere b{{2, 0, 0}, 1.0};
    EXPECT_NEAR(sphereIntersectionVolume(a, b), 13.0 * kPi / 24.0, 1e-12);
}

TEST(OverlapVolume, ContainedSphereOverlapsWithItsWholeVolume) {
    const Sphere big{{0, 0, 0}, 2.0};
    const Sphere small{{0.5, 0, 0}, 1.0};
    EXPECT_NEAR(sphereIntersectionVolume(big, small), 4.0 / 3.0 * kPi, 1e-12);
}

TEST(OverlapVolume, TouchingOrApartSpheresDoNotOverlap) {
    EXPECT_EQ(sphereIntersectionVolume({{0, 0, 0}, 1.0}, {{2, 0, 0}, 1.0}), 0.0);
    EXPECT_EQ(sphereIntersectionVolume({{0, 0, 0}, 1.0}, {{0, 5, 0}, 1.0}), 0.0);
}

TEST(OverlapVolume, IdenticalSpheresOverlapCompletely) {
    EXPECT_NEAR(sphereIntersectionVolume({{3, 1, 2}, 1.5}, {{3, 1, 2}, 1.5}),
                4.0 / 3.0 * kPi * 3.375, 1e-12);
}

TEST(OverlapVolume, BoxesOverlapInTheirCommonCorner) {
    // [0,2]^3 and [1,3]^3 share [1,2]^3.
    const Aabb a{{0, 0, 0}, {2, 2, 2}};
    const Aabb b{{1, 1, 1}, {3, 3, 3}};
    EXPECT_DOUBLE_EQ(boxIntersectionVolume(a, b), 1.0);
    // [0,4]x[0,1]x[0,1] and [1,2]x[-5,5]x[0.5,3]: 1 x 1 x 0.5.
    EXPECT_DOUBLE_EQ(boxIntersectionVolume({{0, 0, 0}, {4, 1, 1}}, {{1, -5, 0.5}, {2, 5, 3}}), 0.5);
}

TEST(OverlapVolume, BoxesSharingAFaceOrApartDoNotOverlap) {
    EXPECT_EQ(boxIntersectionVolume({{0, 0, 0}, {1, 1, 1}}, {{1, 0, 0}, {2, 1, 1}}), 0.0);
    EXPECT_EQ(boxIntersectionVolume({{0, 0, 0}, {1, 1, 1}}, {{0, 3, 0}, {1, 4, 1}}), 0.0);
    EXPECT_EQ(boxIntersectionVolume({{0, 0, 0}, {1, 1, 1}}, Aabb{}), 0.0);
}

TEST(OverlapVolume, ContainedBoxOverlapsWithItsWholeVolume) {
    EXPECT_DOUBLE_EQ(boxIntersectionVolume({{0, 0, 0}, {10, 10, 10}}, {{1, 2, 3}, {2, 4, 6}}), 6.0);
}

TEST(OverlapVolume, SphereVolumeIsFourThirdsPiRCubed) {
    EXPECT_NEAR(Sphere({{0, 0, 0}, 3.0}).volume(), 36.0 * kPi, 1e-12);
}

} // namespace
} // namespace hlod
