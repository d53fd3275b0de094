// Welzl minimum bounding spheres (pipeline/bounds/BoundingSphere.h).
#include <cmath>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/bounds/BoundingSphere.h"

namespace hlod {
namespace {

// Every point inside up to rounding.
void expectContains(const Sphere& s, const std::vector<glm::dvec3>& pts) {
    for (const glm::dvec3& p : pts) {
        EXPECT_LE(glm::length(p - s.center), s.radius * (1.0 + 1e-12) + 1e-12);
    }
}

// Brute force: the minimum ball is the smallest ball through 2, 3 or 4 of the points that
// contains them all (a classic characterisation; fine for a dozen points).
double bruteForceRadius(const std::vector<glm::dvec3>& pts) {
    double best = 1e300;
    const std::size_t n = pts.size();
    auto consider = [&](const Sphere& s) {
        for (const glm::dvec3& p : pts) {
            if (glm::length(p - s.center) > s.radius * (1.0 + 1e-9) + 1e-12) return;
        }
        best = std::min(best, s.radius);
    };
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            consider(minimumBoundingSphere(std::vector<glm::dvec3>{pts[i], pts[j]}));
            for (std::size_t k = j + 1; k < n; ++k) {
                consider(minimumBoundingSphere(std::vector<glm::dvec3>{pts[i], pts[j], pts[k]}));
                for (std::size_t l = k + 1; l < n; ++l) {
                    consider(minimumBoundingSphere(
                        std::vector<glm::dvec3>{pts[i], pts[j], pts[k], pts[l]}));
                }
            }
        }
    }
    return best;
}

TEST(BoundingSphere, CubeCornersGiveCentreAndHalfDiagonal) {
    std::vector<glm::dvec3> pts;
    for (int i = 0; i < 8; ++i)
        pts.emplace_back(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1);
    const Sphere s = minimumBoundingSphere(pts);
    EXPECT_NEAR(glm::length(s.center), 0.0, 1e-12);
    EXPECT_NEAR(s.radius, std::sqrt(3.0), 1e-12); // half of the cube's diagonal 2 sqrt 3
}

TEST(BoundingSphere, RegularTetrahedronGivesCircumsphere) {
    // Alternate corners of the cube [-1,1]^3: circumradius sqrt 3 at the origin.
    const std::vector<glm::dvec3> pts{{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
    const Sphere s = minimumBoundingSphere(pts);
    EXPECT_NEAR(glm::length(s.center), 0.0, 1e-12);
    EXPECT_NEAR(s.radius, std::sqrt(3.0), 1e-12);
}

TEST(BoundingSphere, ObtuseTriangleUsesItsLongestEdge) {
    // The circumcircle of an obtuse triangle is larger than needed: the minimum ball is the
    // one on the longest edge, radius 2 around (0, 0, 0).
    const std::vector<glm::dvec3> pts{{-2, 0, 0}, {2, 0, 0}, {0, 0.5, 0}};
    const Sphere s = minimumBoundingSphere(pts);
    EXPECT_NEAR(s.radius, 2.0, 1e-12);
    EXPECT_NEAR(glm::length(s.center), 0.0, 1e-12);
}

TEST(BoundingSphere, CocircularPointsGiveTheCircle) {
    // 64 points on a circle of radius 3 in a tilted plane: the ball is the circle's, and every
    // four points are coplanar (the degenerate four-point case).
    std::vector<glm::dvec3> pts;
    const glm::dvec3 u = glm::normalize(glm::dvec3(1, 1, 0));
    const glm::dvec3 v = glm::normalize(glm::dvec3(-1, 1, 1));
    const glm::dvec3 w = glm::normalize(v - glm::dot(v, u) * u);
    for (int i = 0; i < 64; ++i) {
        const double a = i * 2.0 * 3.141592653589793 / 64.0;
        pts.push_back(glm::dvec3(5, -2, 7) + 3.0 * (std::cos(a) * u + std::sin(a) * w));
    }
    const Sphere s = minimumBoundingSphere(pts);
    EXPECT_NEAR(s.radius, 3.0, 1e-9);
    EXPECT_NEAR(glm::length(s.center - glm::dvec3(5, -2, 7)), 0.0, 1e-9);
    expectContains(s, pts);
}

TEST(BoundingSphere, CollinearPointsGiveHalfTheSpan) {
    std::vector<glm::dvec3> pts;
    for (int i = 0; i <= 10; ++i)
        pts.emplace_back(i, 2.0 * i, -i); // span length 10 sqrt 6
    const Sphere s = minimumBoundingSphere(pts);
    EXPECT_NEAR(s.radius, 5.0 * std::sqrt(6.0), 1e-9);
    EXPECT_NEAR(glm::length(s.center - glm::dvec3(5, 10, -5)), 0.0, 1e-9);
}

TEST(BoundingSphere, EmptyAndSinglePoint) {
    EXPECT_EQ(minimumBoundingSphere({}).radius, 0.0);
    const std::vector<glm::dvec3> one{{4, 5, 6}};
    const Sphere s = minimumBoundingSphere(one);
    EXPECT_EQ(s.radius, 0.0);
    EXPECT_EQ(s.center, glm::dvec3(4, 5, 6));
}

TEST(BoundingSphere, KilometreOffsetsKeepCentimetrePrecision) {
    // A 2 cm cube 1000 km from the origin: radius sqrt(3) cm, not swamped by the offset.
    std::vector<glm::dvec3> pts;
    for (int i = 0; i < 8; ++i) {
        pts.push_back(glm::dvec3(1e6, -2e6, 3e5) +
                      0.01 * glm::dvec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    }
    EXPECT_NEAR(minimumBoundingSphere(pts).radius, 0.01 * std::sqrt(3.0), 1e-9);
}

TEST(BoundingSphere, MatchesBruteForceOnRandomClouds) {
    std::mt19937_64 rng(7);
    std::normal_distribution<double> g(0.0, 1.0);
    for (int trial = 0; trial < 30; ++trial) {
        std::vector<glm::dvec3> pts;
        for (int i = 0; i < 10; ++i)
            pts.emplace_back(g(rng), 0.3 * g(rng), 2.0 * g(rng));
        const Sphere s = minimumBoundingSphere(pts);
        expectContains(s, pts);
        EXPECT_NEAR(s.radius, bruteForceRadius(pts), 1e-9) << "trial " << trial;
    }
}

TEST(BoundingSphere, SameInputGivesSameBits) {
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> u(-10.0, 10.0);
    std::vector<glm::dvec3> pts(5000);
    for (auto& p : pts)
        p = {u(rng), u(rng), u(rng)};
    const Sphere a = minimumBoundingSphere(pts);
    const Sphere b = minimumBoundingSphere(pts);
    EXPECT_EQ(a.center, b.center);
    EXPECT_EQ(a.radius, b.radius);
    expectContains(a, pts);
}

TEST(BoundingSphere, EnclosingTwoApartSpheres) {
    // Spheres of radius 1 at x = 0 and x = 4 span [-1, 5]: centre 2, radius 3.
    const Sphere s = enclosingSphere({{0, 0, 0}, 1.0}, {{4, 0, 0}, 1.0});
    EXPECT_NEAR(s.radius, 3.0, 1e-12);
    EXPECT_NEAR(glm::length(s.center - glm::dvec3(2, 0, 0)), 0.0, 1e-12);
    // Radii 1 at 0 and 2 at (0, 3, 0) span y in [-1, 5]: centre y = 2, radius 3.
    const Sphere t = enclosingSphere({{0, 0, 0}, 1.0}, {{0, 3, 0}, 2.0});
    EXPECT_NEAR(t.radius, 3.0, 1e-12);
    EXPECT_NEAR(glm::length(t.center - glm::dvec3(0, 2, 0)), 0.0, 1e-12);
}

TEST(BoundingSphere, EnclosingAContainedSphereIsTheContainer) {
    const Sphere big{{1, 1, 1}, 5.0};
    const Sphere small{{2, 1, 1}, 1.0};
    const Sphere s = enclosingSphere(small, big);
    EXPECT_EQ(s.center, big.center);
    EXPECT_EQ(s.radius, big.radius);
    EXPECT_TRUE(sphereContains(s, small));
}

} // namespace
} // namespace hlod
