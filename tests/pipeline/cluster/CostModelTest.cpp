// Cluster cost and fill factor against hand-computed values (pipeline/cluster/CostModel.h).
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/cluster/CostBounds.h"
#include "pipeline/core/Error.h"

#include "ScalarBounds.h"

namespace hlod {
namespace {

constexpr double kPi = std::numbers::pi;

ClusterUnit sphereLeaf(const CostModel& m, glm::dvec3 c, double r) {
    const Aabb box{c - glm::dvec3(r), c + glm::dvec3(r)};
    return m.leaf(Sphere{c, r}, box, 1e-6);
}

ClusterUnit boxLeaf(const CostModel& m, glm::dvec3 lo, glm::dvec3 hi) {
    const Aabb box{lo, hi};
    return m.leaf(Sphere{box.center(), glm::length(hi - lo) * 0.5}, box, 1e-6);
}

TEST(CostModel, SphereLeafCostIsRadiusCubed) {
    const CostModel m(VolumeType::Sphere, 0.0);
    const ClusterUnit u = sphereLeaf(m, {0, 0, 0}, 2.0);
    EXPECT_DOUBLE_EQ(u.cost, 8.0); // r^3 / F with F = 1
    EXPECT_DOUBLE_EQ(u.fill(), 1.0);
}

TEST(CostModel, OverlappingUnitSpheresFillHalfTheirCluster) {
    // Unit spheres at x = 0 and x = 1: enclosing radius (1 + 1 + 1) / 2 = 1.5, V = 4.5 pi.
    // Overlap 5 pi / 12, so F V = 8 pi / 3 - 5 pi / 12 = 9 pi / 4 and F = (9/4) / 4.5 = 0.5.
    // Cost r^3 / F = 3.375 / 0.5 = 6.75.
    const CostModel m(VolumeType::Sphere, 0.0);
    const ClusterUnit a = sphereLeaf(m, {0, 0, 0}, 1.0);
    const ClusterUnit b = sphereLeaf(m, {1, 0, 0}, 1.0);
    const ClusterUnit ab = m.merge(a, b);
    EXPECT_NEAR(ab.sphere.radius, 1.5, 1e-12);
    EXPECT_NEAR(ab.sphere.center.x, 0.5, 1e-12);
    EXPECT_NEAR(ab.volume, 4.5 * kPi, 1e-12);
    EXPECT_NEAR(ab.fill(), 0.5, 1e-12);
    EXPECT_NEAR(ab.cost, 6.75, 1e-12);
    EXPECT_EQ(m.mergeCost(a, b), ab.cost); // same arithmetic, same bits
}

TEST(CostModel, SeparatedBoxesCostVolumeOverFillTimesProportion) {
    // [0,1]^3 and [2,3]x[0,1]^2: hull 3 x 1 x 1, V = 3, no overlap, F = 2 / 3, ratio 3.
    // Cost V / F * 3^k = 4.5, 13.5, 40.5 for k = 0, 1, 2.
    const double expected[] = {4.5, 13.5, 40.5};
    for (int k = 0; k <= 2; ++k) {
        const CostModel m(VolumeType::Aabb, k);
        const ClusterUnit a = boxLeaf(m, {0, 0, 0}, {1, 1, 1});
        const ClusterUnit b = boxLeaf(m, {2, 0, 0}, {3, 1, 1});
        const ClusterUnit ab = m.merge(a, b);
        EXPECT_NEAR(ab.fill(), 2.0 / 3.0, 1e-12);
        EXPECT_NEAR(ab.cost, expected[k], 1e-12) << "k = " << k;
        EXPECT_EQ(m.mergeCost(a, b), ab.cost);
    }
}

TEST(CostModel, OverlappingBoxesSubtractTheOverlapOnce) {
    // [0,2]^3 and [1,3]x[0,2]^2 overlap in 1 x 2 x 2 = 4: F V = 8 + 8 - 4 = 12 = the hull's
    // volume 3 x 2 x 2, so F = 1; ratio 3 / 2, cost with k = 1: 12 * 1.5 = 18.
    const CostModel m(VolumeType::Aabb, 1.0);
    const ClusterUnit ab =
        m.merge(boxLeaf(m, {0, 0, 0}, {2, 2, 2}), boxLeaf(m, {1, 0, 0}, {3, 2, 2}));
    EXPECT_NEAR(ab.fill(), 1.0, 1e-12);
    EXPECT_NEAR(ab.cost, 18.0, 1e-12);
}

TEST(CostModel, FillOfThreeMembersChainsEquationThreeOne) {
    // Three unit cubes in a row: AB fills [0,2] (F = 1), then (AB)C fills [0,3] (F = 1):
    // cost with k = 0 is V = 3.
    const CostModel m(VolumeType::Aabb, 0.0);
    const ClusterUnit ab =
        m.merge(boxLeaf(m, {0, 0, 0}, {1, 1, 1}), boxLeaf(m, {1, 0, 0}, {2, 1, 1}));
    const ClusterUnit abc = m.merge(ab, boxLeaf(m, {2, 0, 0}, {3, 1, 1}));
    EXPECT_NEAR(abc.fill(), 1.0, 1e-12);
    EXPECT_NEAR(abc.cost, 3.0, 1e-12);
}

TEST(CostModel, SparseOverlapClampsFillToTheFullerPart) {
    // Two clusters with the same box [0,2]^3 (V = 8), each only 1/16 full (F V = 0.5): eq. 3.1
    // gives 0.5 + 0.5 - 8 < 0; the clamp keeps F V = max(0.5, 0.5), F = 1/16, cost 8 * 16.
    const CostModel m(VolumeType::Aabb, 0.0);
    ClusterUnit a = boxLeaf(m, {0, 0, 0}, {2, 2, 2});
    a.fv = 0.5;
    const ClusterUnit ab = m.merge(a, a);
    EXPECT_DOUBLE_EQ(ab.fv, 0.5);
    EXPECT_DOUBLE_EQ(ab.fill(), 1.0 / 16.0);
    EXPECT_DOUBLE_EQ(ab.cost, 128.0);
}

TEST(CostModel, FlatLeafIsPaddedToTheMinimumExtent) {
    // A 4 x 0 x 2 quad padded to 0.01: volume 4 * 0.01 * 2 = 0.08, ratio 4 / 0.01 = 400.
    const CostModel m(VolumeType::Aabb, 1.0);
    const Aabb flat{{0, 5, 0}, {4, 5, 2}};
    const ClusterUnit u = m.leaf(Sphere{flat.center(), std::sqrt(5.0)}, flat, 0.01);
    EXPECT_NEAR(u.box.min.y, 4.995, 1e-15);
    EXPECT_NEAR(u.box.max.y, 5.005, 1e-15);
    EXPECT_NEAR(u.volume, 0.08, 1e-14);
    EXPECT_NEAR(u.cost, 0.08 * 400.0, 1e-9);
    const ClusterUnit point = m.leaf(Sphere{{1, 1, 1}, 0.0}, Aabb{{1, 1, 1}, {1, 1, 1}}, 0.01);
    EXPECT_NEAR(point.volume, 1e-6, 1e-18); // a 1 cm cube
}

TEST(CostModel, LowerBoundNeverExceedsARealCost) {
    // For random pairs, the bound over the region of g alone must not exceed the real merge
    // cost, for every model (spheres of every size, boxes far apart and overlapping).
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> pos(-20.0, 20.0), size(0.01, 5.0);
    for (auto [vol, k] : {std::pair{VolumeType::Sphere, 0.0},
                          {VolumeType::Aabb, 0.0},
                          {VolumeType::Aabb, 1.0},
                          {VolumeType::Aabb, 2.0},
                          {VolumeType::Aabb, 0.5}}) {
        const CostModel m(vol, k);
        for (int i = 0; i < 2000; ++i) {
            const glm::dvec3 pa(pos(rng), pos(rng), pos(rng)), pb(pos(rng), pos(rng), pos(rng));
            const ClusterUnit a = boxLeaf(m, pa, pa + glm::dvec3(size(rng), size(rng), size(rng)));
            const ClusterUnit b = boxLeaf(m, pb, pb + glm::dvec3(size(rng), size(rng), size(rng)));
            EXPECT_LE(pairLowerBound(m, regionOf(m, a), regionOf(m, b)), m.mergeCost(a, b));
            EXPECT_LE(pairLowerBound(m, regionOf(m, b), regionOf(m, a)), m.mergeCost(a, b));
        }
    }
}

TEST(CostModel, SetBoundsNeverExceedARealCost) {
    // Regions of several clusters (as BVH nodes hold them): for every pair of members, neither
    // the query bound of one member against the other set nor the set-against-set bound may
    // exceed the real cost, and the self-join's test must not reject a pair at its own cost.
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> pos(-15.0, 15.0), size(0.001, 4.0), flat(0.0, 1.0);
    for (auto [vol, k] : {std::pair{VolumeType::Sphere, 0.0},
                          {VolumeType::Aabb, 0.0},
                          {VolumeType::Aabb, 1.0},
                          {VolumeType::Aabb, 2.0},
                          {VolumeType::Aabb, 0.5}}) {
        const CostModel m(vol, k);
        auto randomSet = [&](std::vector<ClusterUnit>& units) {
            Region r = emptyRegion();
            const glm::dvec3 base(pos(rng), pos(rng), pos(rng));
            for (int i = 0; i < 4; ++i) {
                const glm::dvec3 lo = base + glm::dvec3(pos(rng), pos(rng), pos(rng)) * 0.3;
                glm::dvec3 e(size(rng), size(rng), size(rng));
                if (flat(rng) < 0.3) e[i % 3] = 0.0; // flat parts get the minimum extent
                units.push_back(boxLeaf(m, lo, lo + e));
                includeRegion(r, regionOf(m, units.back()));
            }
            return r;
        };
        for (int trial = 0; trial < 400; ++trial) {
            std::vector<ClusterUnit> as, bs;
            const Region ra = randomSet(as);
            const Region rb = randomSet(bs);
            for (const ClusterUnit& a : as) {
                for (const ClusterUnit& b : bs) {
                    const double cost = m.mergeCost(a, b);
                    EXPECT_LE(pairLowerBound(m, ra, rb), cost);
                    EXPECT_FALSE(pairBoundExceeds(m, ra, rb, cost));
                    EXPECT_LE(pairLowerBound(m, regionOf(m, a), rb), cost);
                    EXPECT_EQ(m.mergeCostWithin(a, b, cost), cost);
                    EXPECT_GT(m.mergeCostWithin(a, b, cost * 0.5), cost * 0.5);
                }
            }
        }
    }
}

TEST(CostModel, RejectsBaselineVolumesAndNegativeK) {
    EXPECT_THROW(CostModel(VolumeType::Octree, 0.0), Error);
    EXPECT_THROW(CostModel(VolumeType::Aabb, -1.0), Error);
}

} // namespace
} // namespace hlod
