#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <span>
#include <vector>

#include "pipeline/proxy/SurfaceQuery.h"

using namespace hlod;
using namespace hlod::surface;

namespace {

// Triangles of every shape the simplifier meets: ordinary, slivers, needles, collinear and
// point-like (degenerate), at small and large coordinates.
Triangle randomTriangle(std::mt19937& rng) {
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    std::uniform_int_distribution<int> kind(0, 5);
    const float scale = std::pow(10.0f, std::uniform_real_distribution<float>(-2.0f, 2.0f)(rng));
    const glm::vec3 at = glm::vec3(unit(rng), unit(rng), unit(rng)) *
                         std::pow(10.0f, std::uniform_real_distribution<float>(-1.0f, 3.0f)(rng));
    const glm::vec3 a = at + glm::vec3(unit(rng), unit(rng), unit(rng)) * scale;
    glm::vec3 b = at + glm::vec3(unit(rng), unit(rng), unit(rng)) * scale;
    glm::vec3 c = at + glm::vec3(unit(rng), unit(rng), unit(rng)) * scale;
    switch (kind(rng)) {
    case 1:
        c = a + (b - a) * 0.37f + glm::vec3(unit(rng)) * scale * 1e-4f;
        break; // sliver
    case 2:
        c = a + (b - a) * 0.61f;
        break; // collinear
    case 3:
        b = a;
        break; // two equal
    case 4:
        b = a, c = a;
        break; // a point
    default:
        break;
    }
    return makeTriangle(a, b, c);
}

// A point about `limit` from the triangle (on it, beyond its corners, off its plane).
glm::vec3 pointNear(std::mt19937& rng, const Triangle& tri, float limit) {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f), side(-1.0f, 1.0f);
    float u = unit(rng) * 1.4f - 0.2f, v = unit(rng) * 1.4f - 0.2f;
    const glm::vec3 onPlane = tri.a + (tri.b - tri.a) * u + (tri.c - tri.a) * v;
    const glm::vec3 off = glm::vec3(side(rng), side(rng), side(rng)) * limit * 1.2f;
    return onPlane + off;
}

// A Coverage test at `limit` over a triangle list: queries at the limit less the slack, as the
// simplifiers run them.
struct CoverageAt {
    NearSurface surface;
    Coverage coverage;
    CoverageAt(std::span<const glm::vec3> positions, std::span<const std::uint32_t> indices,
               float limit)
        : coverage(surface, limit * kSlackFraction) {
        surface.reset(positions, indices, limit * (1.0f - kSlackFraction));
    }
};

} // namespace

TEST(SurfaceQuery, WithinMask4AnswersAsWithinLaneByLane) {
    std::mt19937 rng(7);
    std::size_t inside = 0, total = 0;
    for (int i = 0; i < 40000; ++i) {
        const Triangle tri = randomTriangle(rng);
        const float extent = glm::length(tri.b - tri.a) + glm::length(tri.c - tri.a) + 1e-3f;
        const float limit =
            extent * std::pow(10.0f, std::uniform_real_distribution<float>(-3.0f, 0.5f)(rng));
        for (int round = 0; round < 8; ++round) {
            Points4 p;
            glm::vec3 q[4];
            for (int k = 0; k < 4; ++k) {
                q[k] = pointNear(rng, tri, limit);
                p.x[k] = q[k].x, p.y[k] = q[k].y, p.z[k] = q[k].z;
            }
            const unsigned mask = withinMask4(tri, p, limit * limit);
            for (int k = 0; k < 4; ++k) {
                const bool scalar = within(tri, q[k], limit * limit);
                ASSERT_EQ(scalar, (mask >> k & 1u) != 0) << "triangle " << i << " lane " << k;
                inside += scalar ? 1 : 0;
                ++total;
            }
        }
    }
    // Both answers occur often, so the lanes were really compared.
    EXPECT_GT(inside, total / 10);
    EXPECT_LT(inside, total * 9 / 10);
}

namespace {

// A wavy sheet of n x n quads, with some triangles folded up.
struct Sheet {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
};

Sheet sheet(int n) {
    Sheet s;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            s.positions.push_back(glm::vec3(x, y, 0.3f * std::sin(0.7f * x) * std::cos(0.4f * y)));
    for (int y = 0; y < n; ++y) {
        for (int x = 0; x < n; ++x) {
            const std::uint32_t v = static_cast<std::uint32_t>(y * (n + 1) + x);
            const std::uint32_t w = v + static_cast<std::uint32_t>(n + 1);
            s.indices.insert(s.indices.end(), {v, v + 1, w + 1, v, w + 1, w});
        }
    }
    return s;
}

bool bruteNear(const Sheet& s, const glm::vec3& p, float limit) {
    for (std::size_t t = 0; t < s.indices.size(); t += 3) {
        const Triangle tri = makeTriangle(s.positions[s.indices[t]], s.positions[s.indices[t + 1]],
                                          s.positions[s.indices[t + 2]]);
        if (within(tri, p, limit * limit)) return true;
    }
    return false;
}

} // namespace

TEST(SurfaceQuery, NearEachIsNearPointByPoint) {
    const Sheet s = sheet(24);
    const float limit = 0.21f;
    NearSurface batch, single;
    batch.reset(s.positions, s.indices, limit);
    single.reset(s.positions, s.indices, limit);
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> xy(-1.0f, 25.0f), z(-0.6f, 0.6f), step(-0.3f, 0.3f);
    std::size_t failures = 0;
    for (int run = 0; run < 3000; ++run) {
        // Walks of nearby points (the hint answers most), some leaving the surface.
        std::vector<glm::vec3> points;
        glm::vec3 p(xy(rng), xy(rng), z(rng) * 0.5f);
        const int count = 1 + static_cast<int>(rng() % 40);
        for (int k = 0; k < count; ++k) {
            points.push_back(p);
            p += glm::vec3(step(rng), step(rng), step(rng) * 0.3f);
        }
        bool expected = true;
        for (const glm::vec3& q : points) {
            if (!single.near(q)) {
                expected = false;
                break;
            }
        }
        ASSERT_EQ(expected, batch.nearEach(points)) << "run " << run;
        ASSERT_EQ(single.lastFound(), batch.lastFound()) << "run " << run;
        failures += expected ? 0 : 1;
    }
    EXPECT_GT(failures, 100u);
    EXPECT_LT(failures, 2900u);
}

TEST(SurfaceQuery, GridQueriesAnswerAsEveryTriangle) {
    const Sheet s = sheet(16);
    const float limit = 0.17f;
    NearSurface surface;
    surface.reset(s.positions, s.indices, limit);
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> xy(-1.0f, 17.0f), z(-0.7f, 0.7f), d(-0.15f, 0.15f);
    for (int i = 0; i < 20000; ++i) {
        const glm::vec3 p(xy(rng), xy(rng), z(rng));
        ASSERT_EQ(bruteNear(s, p, limit), surface.near(p)) << i;
        const glm::vec3 q = p + glm::vec3(d(rng), d(rng), d(rng));
        const glm::vec3 r = p + glm::vec3(d(rng), d(rng), d(rng));
        bool common = false;
        for (std::size_t t = 0; t < s.indices.size() && !common; t += 3) {
            const Triangle tri =
                makeTriangle(s.positions[s.indices[t]], s.positions[s.indices[t + 1]],
                             s.positions[s.indices[t + 2]]);
            common = within(tri, p, limit * limit) && within(tri, q, limit * limit) &&
                     within(tri, r, limit * limit);
        }
        ASSERT_EQ(common, surface.nearAll(p, q, r)) << i;
    }
}

TEST(SurfaceQuery, CoverageWithKnownCornersLocatesOnlyTheUnknownOnes) {
    // A 2 x 1 strip of two triangles in z = 0; the limit 0.1 (queries at 31/32 of it).
    const std::vector<glm::vec3> positions{{0, 0, 0}, {1, 0, 0}, {2, 0, 0},
                                           {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
    const std::vector<std::uint32_t> indices{0, 1, 4, 0, 4, 3, 1, 2, 5, 1, 5, 4};
    const float limit = 0.1f;
    CoverageAt at(positions, indices, limit);
    Coverage& coverage = at.coverage;
    NearSurface& surface = at.surface;
    glm::vec3 failAt;
    // 5 cm above the strip, spanning both halves: covered. The first corner comes with a
    // triangle it lies above (kept as given); the others are located and written back, each
    // one within the limit of its corner.
    const glm::vec3 above[3] = {{0.1f, 0.1f, 0.05f}, {1.9f, 0.2f, 0.05f}, {1.0f, 0.9f, 0.05f}};
    std::uint32_t near[3] = {1, kNoTriangle, kNoTriangle};
    EXPECT_TRUE(coverage.covers(above, near, failAt));
    EXPECT_EQ(near[0], 1u);
    for (int k = 0; k < 3; ++k) {
        ASSERT_NE(near[k], kNoTriangle) << k;
        EXPECT_TRUE(surface.nearTriangle(near[k], above[k])) << k;
    }
    // 20 cm above: the first corner is already too far, so nothing is covered and the point
    // that failed is that corner.
    const glm::vec3 high[3] = {{0.5f, 0.5f, 0.2f}, {1.5f, 0.5f, 0.05f}, {1.0f, 0.9f, 0.05f}};
    std::uint32_t unknown[3] = {kNoTriangle, kNoTriangle, kNoTriangle};
    EXPECT_FALSE(coverage.covers(high, unknown, failAt));
    EXPECT_EQ(failAt, high[0]);
}

// A CAD-like curved surface: a half cylinder of radius 1 tessellated into 48 strips 6 long,
// each two long thin triangles. Triangles near it (chords across many strips, some lifted off
// it) are certified by Coverage; every one it certifies lies within the limit at all points of
// a dense barycentric grid (brute force over every strip), and every one that lies well within
// it (0.9 of the limit at every grid point) is certified: the cuts across the strips
// (SurfaceQuery.h piece()) lose no answer.
TEST(SurfaceQuery, CoverageOverLongStripsAgreesWithDenseSampling) {
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    const int strips = 48;
    for (int i = 0; i <= strips; ++i) {
        const float angle = 3.14159265f * static_cast<float>(i) / strips;
        positions.emplace_back(std::cos(angle), std::sin(angle), 0.0f);
        positions.emplace_back(std::cos(angle), std::sin(angle), 6.0f);
    }
    for (std::uint32_t i = 0; i < strips; ++i) {
        const std::uint32_t a = 2 * i, b = a + 1, c = a + 2, d = a + 3;
        indices.insert(indices.end(), {a, c, d, a, d, b});
    }
    std::vector<Triangle> tris;
    for (std::size_t t = 0; t < indices.size(); t += 3)
        tris.push_back(makeTriangle(positions[indices[t]], positions[indices[t + 1]],
                                    positions[indices[t + 2]]));
    auto distance = [&](const glm::vec3& p) {
        float best = INFINITY;
        for (const Triangle& tri : tris)
            best = std::min(best, std::sqrt(distanceSquared(p, tri.a, tri.b, tri.c)));
        return best;
    };
    const float limit = 0.05f;
    CoverageAt at(positions, indices, limit);
    Coverage& coverage = at.coverage;
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> angle(0.05f, 3.09f), along(0.2f, 5.8f),
        lift(-0.04f, 0.08f), span(0.05f, 0.6f);
    int certified = 0, clearlyWithin = 0;
    for (int i = 0; i < 300; ++i) {
        glm::vec3 corner[3];
        const float a0 = angle(rng), z0 = along(rng);
        for (int k = 0; k < 3; ++k) {
            const float a = std::clamp(a0 + (k == 0 ? 0.0f : span(rng) * (k == 1 ? 1.0f : -1.0f)),
                                       0.0f, 3.14159265f);
            const float z = std::clamp(z0 + (k == 2 ? span(rng) * 6.0f : 0.0f), 0.0f, 6.0f);
            const float r = 1.0f + lift(rng);
            corner[k] = glm::vec3(r * std::cos(a), r * std::sin(a), z);
        }
        float worst = 0.0f;
        for (int u = 0; u <= 40; ++u)
            for (int v = 0; u + v <= 40; ++v) {
                const glm::vec3 p = corner[0] + (corner[1] - corner[0]) * (u / 40.0f) +
                                    (corner[2] - corner[0]) * (v / 40.0f);
                worst = std::max(worst, distance(p));
            }
        std::uint32_t near[3] = {kNoTriangle, kNoTriangle, kNoTriangle};
        glm::vec3 failAt;
        const bool covered = coverage.covers(corner, near, failAt);
        if (covered) {
            ++certified;
            EXPECT_LE(worst, limit * 1.0001f) << i;
        }
        if (worst <= 0.9f * limit) {
            ++clearlyWithin;
            EXPECT_TRUE(covered) << i << " worst " << worst;
        }
    }
    EXPECT_GT(certified, 40);     // 67 of the 300
    EXPECT_GT(clearlyWithin, 40); // 58
    EXPECT_LT(certified, 200);    // and most stray from the limit somewhere
}

// A face much wider than the limit over a surface of triangles about the limit's size (a
// remeshed box's face over its voxel shell): its certificate must cut it into tens of
// thousands of pieces, so its piece budget grows with its area instead of stopping at 2^14.
TEST(SurfaceQuery, CoverageOfAWideFaceOverAFineSurfaceIsNotCutShort) {
    // The unit square in z = 0 as 250 x 250 cells of two triangles (4 mm).
    const int n = 250;
    std::vector<glm::vec3> positions;
    std::vector<std::uint32_t> indices;
    for (int y = 0; y <= n; ++y)
        for (int x = 0; x <= n; ++x)
            positions.emplace_back(static_cast<float>(x) / n, static_cast<float>(y) / n, 0.0f);
    for (std::uint32_t y = 0; y < static_cast<std::uint32_t>(n); ++y)
        for (std::uint32_t x = 0; x < static_cast<std::uint32_t>(n); ++x) {
            const std::uint32_t a = y * (n + 1) + x;
            indices.insert(indices.end(), {a, a + 1, a + n + 2, a, a + n + 2, a + n + 1});
        }
    const float limit = 0.005f;
    CoverageAt at(positions, indices, limit);
    glm::vec3 failAt;
    // Half the square, its far corner at `height`, the others 2 mm above the square.
    auto halfSquare = [&](float height) {
        const glm::vec3 corner[3] = {{0, 0, 0.002f}, {1, 0, 0.002f}, {1, 1, height}};
        std::uint32_t near[3] = {kNoTriangle, kNoTriangle, kNoTriangle};
        return at.coverage.covers(corner, near, failAt);
    };
    EXPECT_TRUE(halfSquare(0.002f)); // within the limit everywhere
    // One corner 1 cm above: refused, at a point beyond the limit.
    EXPECT_FALSE(halfSquare(0.01f));
    EXPECT_GT(failAt.z, limit * (1.0f - kSlackFraction));
}
