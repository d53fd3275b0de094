// Set bounds of the clustering cost in their packed (single precision) form and the coupled
// shape and volume bound of the box model (pipeline/cluster/CostBounds.h).
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/cluster/CostBounds.h"

#include "ScalarBounds.h"

namespace hlod {
namespace {

ClusterUnit boxLeaf(const CostModel& m, glm::dvec3 lo, glm::dvec3 hi) {
    const Aabb box{lo, hi};
    return m.leaf(Sphere{box.center(), glm::length(hi - lo) * 0.5}, box, 1e-6);
}

struct Packed {
    PackedRegion r;
    PackedExtra e;
    PackedRef ref(bool boxModel) const { return PackedRef{&r, boxModel ? &e : nullptr}; }
};

Packed pack(const Region& r, bool boxModel) {
    Packed p{};
    packRegion(r, boxModel, p.r, p.e);
    return p;
}

TEST(CostBounds, PackedRegionHoldsTheExactOne) {
    // Rounding outward: the widened box contains the exact one, the largest F*V is not smaller
    // and every smallest size not larger, so a bound from the packed region stays a bound.
    // Coordinates far from the origin make the float rounding visible.
    std::mt19937_64 rng(3);
    std::uniform_real_distribution<double> pos(-1e4, 1e4), size(1e-5, 3.0);
    for (VolumeType vol : {VolumeType::Sphere, VolumeType::Aabb}) {
        const CostModel m(vol, 1.0);
        const bool boxModel = vol == VolumeType::Aabb;
        for (int i = 0; i < 2000; ++i) {
            const glm::dvec3 lo(pos(rng), pos(rng), pos(rng));
            const ClusterUnit u = boxLeaf(m, lo, lo + glm::dvec3(size(rng), size(rng), size(rng)));
            const Region exact = regionOf(m, u);
            const Packed p = pack(exact, boxModel);
            const Region wide = unpackRegion(p.ref(boxModel));
            for (int a = 0; a < 3; ++a) {
                EXPECT_LE(wide.box.min[a], exact.box.min[a]);
                EXPECT_GE(wide.box.max[a], exact.box.max[a]);
                if (boxModel) {
                    EXPECT_LE(wide.minExtent[a], exact.minExtent[a]);
                    EXPECT_LE(wide.minArea[a], exact.minArea[a]);
                }
            }
            EXPECT_GE(wide.maxFv, exact.maxFv);
            EXPECT_LE(boxModel ? wide.minVolume : wide.minRadius,
                      boxModel ? exact.minVolume : exact.minRadius);
        }
    }
}

TEST(CostBounds, PackedPairTestNeverRejectsARealPair) {
    // The self-join's test on packed regions of clusters (leaves and merged pairs with a fill
    // below 1, some flat): for every pair of members it must not reject the pair at its own
    // cost, the query bound of one member against the other packed set must not exceed that
    // cost either, and at any threshold it must agree with the generic pairBoundExceeds.
    std::mt19937_64 rng(17);
    std::uniform_real_distribution<double> pos(-15.0, 15.0), size(0.001, 4.0), coin(0.0, 1.0);
    for (auto [vol, k] : {std::pair{VolumeType::Sphere, 0.0},
                          {VolumeType::Aabb, 0.0},
                          {VolumeType::Aabb, 1.0},
                          {VolumeType::Aabb, 2.0},
                          {VolumeType::Aabb, 0.5},
                          {VolumeType::Aabb, 1.5}}) {
        const CostModel m(vol, k);
        const bool boxModel = vol == VolumeType::Aabb;
        auto randomUnit = [&](const glm::dvec3& base) {
            const glm::dvec3 lo = base + glm::dvec3(pos(rng), pos(rng), pos(rng)) * 0.3;
            glm::dvec3 e(size(rng), size(rng), size(rng));
            if (coin(rng) < 0.3) e[static_cast<int>(coin(rng) * 3.0) % 3] = 0.0;
            return boxLeaf(m, lo, lo + e);
        };
        auto randomSet = [&](std::vector<ClusterUnit>& units) {
            Region r = emptyRegion();
            const glm::dvec3 base(pos(rng), pos(rng), pos(rng));
            for (int i = 0; i < 4; ++i) {
                ClusterUnit u = randomUnit(base);
                if (coin(rng) < 0.4) u = m.merge(u, randomUnit(base));
                units.push_back(u);
                includeRegion(r, regionOf(m, u));
            }
            return pack(r, boxModel);
        };
        for (int trial = 0; trial < 300; ++trial) {
            std::vector<ClusterUnit> as, bs;
            const Packed pa = randomSet(as);
            const Packed pb = randomSet(bs);
            for (const ClusterUnit& a : as) {
                const Packed item = pack(regionOf(m, a), boxModel);
                for (const ClusterUnit& b : bs) {
                    const double cost = m.mergeCost(a, b);
                    const PackedPairTest test(m, cost);
                    EXPECT_FALSE(test.exceeds(pa.ref(boxModel), pb.ref(boxModel)));
                    EXPECT_FALSE(test.exceeds(item.ref(boxModel), pb.ref(boxModel)));
                    EXPECT_FALSE(pairBoundExceeds(m, pa.ref(boxModel), pb.ref(boxModel), cost));
                    EXPECT_LE(pairLowerBound(m, item.ref(boxModel), pb.ref(boxModel)), cost);
                    // Written out per component, it answers as the generic test does.
                    for (double t : {cost * 0.25, cost * 0.9, cost * 4.0}) {
                        EXPECT_EQ(PackedPairTest(m, t).exceeds(pa.ref(boxModel), pb.ref(boxModel)),
                                  pairBoundExceeds(m, pa.ref(boxModel), pb.ref(boxModel), t));
                    }
                }
            }
        }
    }
}

TEST(CostBounds, CoupledShapeBoundIsTightForBoxesAlignedAlongAnAxis) {
    // Sets A = unit cubes at (0,0,0) and (0,10,10), B = the same shifted by 20 along x. The
    // cheapest pair is two aligned cubes: a 21 x 1 x 1 box, V = 21, F*V = 2 (no overlap), so
    // cost = V^2 / fv * 21^k: 4630.5 for k = 1 and 97240.5 for k = 2. The coupled bound gives
    // exactly that from the regions (extents >= 21, 1, 1; volume >= 21), while the separate
    // shape factor is bounded by the hulls' smallest extent, 11, so it alone gives ~10x less.
    for (double k : {1.0, 2.0}) {
        const CostModel m(VolumeType::Aabb, k);
        const std::vector<ClusterUnit> as = {boxLeaf(m, {0, 0, 0}, {1, 1, 1}),
                                             boxLeaf(m, {0, 10, 10}, {1, 11, 11})};
        const std::vector<ClusterUnit> bs = {boxLeaf(m, {20, 0, 0}, {21, 1, 1}),
                                             boxLeaf(m, {20, 10, 10}, {21, 11, 11})};
        Region ra = emptyRegion(), rb = emptyRegion();
        for (const ClusterUnit& u : as)
            includeRegion(ra, regionOf(m, u));
        for (const ClusterUnit& u : bs)
            includeRegion(rb, regionOf(m, u));
        const double cheapest = k == 1.0 ? 4630.5 : 97240.5;
        EXPECT_NEAR(m.mergeCost(as[0], bs[0]), cheapest, cheapest * 1e-12);
        const double bound = pairLowerBound(m, ra, rb);
        EXPECT_LE(bound, cheapest);
        EXPECT_GT(bound, cheapest * (1.0 - 1e-6));
        EXPECT_NEAR(shapeVolumeBound(k, glm::dvec3(21, 1, 1), 21.0, 2.0), cheapest, 1e-9);
        // Just below the cheapest cost the whole node pair is pruned, packed or not.
        const PackedPairTest test(m, cheapest * 0.999);
        EXPECT_TRUE(test.exceeds(pack(ra, true).ref(true), pack(rb, true).ref(true)));
    }
}

TEST(CostBounds, SizeClassIsTheExponentOfTheSize) {
    // Sphere: the radius' binary exponent; box: that of the volume's cube root, taken as the
    // volume's exponent over three, rounded down (no root).
    const CostModel sphere(VolumeType::Sphere, 0.0);
    const CostModel box(VolumeType::Aabb, 0.0);
    ClusterUnit u;
    for (int e = -70; e <= 70; ++e) {
        u.sphere.radius = std::ldexp(1.5, e);
        u.volume = std::ldexp(1.0, e);
        EXPECT_EQ(sizeClass(sphere, u), e);
        const int expected = static_cast<int>(std::floor(e / 3.0));
        EXPECT_EQ(sizeClass(box, u), expected) << "volume 2^" << e;
        u.volume = std::ldexp(1.99, e); // the same exponent up to the next power of two
        EXPECT_EQ(sizeClass(box, u), expected) << "volume 1.99 * 2^" << e;
    }
    // Sides within a factor of two share a class only if their cubes' exponents do.
    u.volume = 1.0 * 1.0 * 1.0;
    const int one = sizeClass(box, u);
    u.volume = 1.9 * 1.9 * 1.9;
    EXPECT_EQ(sizeClass(box, u), one);
    u.volume = 2.0 * 2.0 * 2.0;
    EXPECT_EQ(sizeClass(box, u), one + 1);
    // Nothing to take an exponent of: the lowest class.
    u.volume = 0.0;
    EXPECT_EQ(sizeClass(box, u), std::numeric_limits<int>::min());
    u.volume = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(sizeClass(box, u), std::numeric_limits<int>::min());
    u.sphere.radius = 0.0;
    EXPECT_EQ(sizeClass(sphere, u), std::numeric_limits<int>::min());
}

} // namespace
} // namespace hlod
