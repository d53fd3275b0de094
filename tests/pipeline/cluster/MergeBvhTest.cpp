// The 4-wide BVH of level merging (pipeline/cluster/MergeBvh.h) and its vector bounds
// (pipeline/cluster/WideBounds.h): each lane answers as the scalar packed test does (two or
// four lanes per vector), the self-join reports every pair within the threshold once and
// nothing its item test rejects, and the search finds the cheapest partner, with the baseline
// code and, where the processor has it, the AVX2 code.
#include <algorithm>
#include <random>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "pipeline/cluster/MergeBvh.h"

#include "ScalarBounds.h"

namespace hlod {
namespace {

struct Model {
    VolumeType volume;
    double k;
};

const Model kModels[] = {{VolumeType::Sphere, 0.0}, {VolumeType::Aabb, 0.0},
                         {VolumeType::Aabb, 0.5},   {VolumeType::Aabb, 1.0},
                         {VolumeType::Aabb, 1.5},   {VolumeType::Aabb, 2.0}};

// Leaves of mixed size (three decades, some flat or long) in a cube of side `side`.
std::vector<ClusterUnit> randomUnits(const CostModel& m, std::size_t n, double side,
                                     std::uint64_t seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<ClusterUnit> out;
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec3 lo(unit(rng) * side, unit(rng) * side, unit(rng) * side);
        const double s = 0.05 * std::pow(10.0, 3.0 * unit(rng));
        glm::dvec3 e(s * (0.2 + unit(rng)), s * (0.2 + unit(rng)), s * (0.2 + unit(rng)));
        if (i % 7 == 0) e[i % 3] = 0.0; // flat: padded by leaf()
        if (i % 11 == 0) e[(i + 1) % 3] *= 20.0;
        const Aabb box{lo, lo + e};
        out.push_back(m.leaf(Sphere{box.center(), glm::length(e) * 0.5}, box, 1e-3));
    }
    return out;
}

// The vector widths this machine can run: the baseline always, AVX2 where the processor has it.
std::vector<MergeBvh::Simd> simds() {
    std::vector<MergeBvh::Simd> out{MergeBvh::Simd::Baseline};
    if (MergeBvh::bestSimd() == MergeBvh::Simd::Avx2) out.push_back(MergeBvh::Simd::Avx2);
    return out;
}

const char* nameOf(MergeBvh::Simd s) { return s == MergeBvh::Simd::Avx2 ? "avx2" : "baseline"; }

MergeBvh buildOver(const CostModel& m, const std::vector<ClusterUnit>& units) {
    std::vector<Region> regions;
    std::vector<int> classes;
    for (const ClusterUnit& u : units) {
        regions.push_back(regionOf(m, u));
        classes.push_back(sizeClass(m, u));
    }
    MergeBvh bvh;
    bvh.build(regions, classes, m);
    return bvh;
}

double cost(const CostModel& m, const std::vector<ClusterUnit>& u, std::size_t i, std::size_t j) {
    return i < j ? m.mergeCost(u[i], u[j]) : m.mergeCost(u[j], u[i]);
}

// The region of `count` units drawn at random (with repetition) from `units`.
Region unionOf(const CostModel& m, const std::vector<ClusterUnit>& units, std::size_t count,
               std::mt19937_64& rng) {
    Region r = emptyRegion();
    for (std::size_t c = 0; c < count; ++c)
        includeRegion(r, regionOf(m, units[rng() % units.size()]));
    return r;
}

// unionOf(...) packed (PackedRegion, and PackedExtra for the box model).
struct PackedUnion {
    PackedRegion r{};
    PackedExtra e{};
};
PackedUnion packedUnion(const CostModel& m, const std::vector<ClusterUnit>& units,
                        std::size_t count, std::mt19937_64& rng) {
    PackedUnion out;
    packRegion(unionOf(m, units, count, rng), m.volume() == VolumeType::Aabb, out.r, out.e);
    return out;
}

// The query compiled for the model's bound kind (what MergeBvh runs) answers as the generic
// one (K = Any) that the test below checks against the scalar test: same verdicts, same bounds.
template <int W, BoundKind K>
void expectKindAsAny(const CostModel& m, const PackedRegion& qr, const PackedExtra& qe,
                     const WideRegions& w, double threshold) {
    const WideQueryT<W> any(m, qr, qe);
    const WideQueryT<W, K> fixed(m, qr, qe);
    EXPECT_EQ(fixed.exceeds(w, threshold), any.exceeds(w, threshold));
    double a[4];
    double f[4];
    any.bounds(w, a);
    fixed.bounds(w, f);
    for (int l = 0; l < 4; ++l)
        EXPECT_EQ(f[l], a[l]);
}

template <int W>
void expectModelKindAsAny(const CostModel& m, const PackedRegion& qr, const PackedExtra& qe,
                          const WideRegions& w, double threshold) {
    withKind(boundKindOf(m), [&](auto kind) {
        // (Any is what the fixed kinds are compared with.)
        if constexpr (kind.value != BoundKind::Any && kind.value != BoundKind::BoxK0Single) {
            expectKindAsAny<W, kind.value>(m, qr, qe, w, threshold);
        }
    });
}

TEST(MergeBvh, BoundKindOfNamesTheModel) {
    EXPECT_EQ(boundKindOf(CostModel(VolumeType::Sphere, 0.0)), BoundKind::Sphere);
    EXPECT_EQ(boundKindOf(CostModel(VolumeType::Aabb, 0.0)), BoundKind::BoxK0);
    EXPECT_EQ(boundKindOf(CostModel(VolumeType::Aabb, 1.0)), BoundKind::BoxK1);
    EXPECT_EQ(boundKindOf(CostModel(VolumeType::Aabb, 2.0)), BoundKind::BoxK2);
    EXPECT_EQ(boundKindOf(CostModel(VolumeType::Aabb, 1.5)), BoundKind::Any);
}

TEST(MergeBvh, WideLanesAnswerAsTheScalarTest) {
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const Model& model : kModels) {
        const CostModel m(model.volume, model.k);
        const bool boxModel = model.volume == VolumeType::Aabb;
        const std::vector<ClusterUnit> units = randomUnits(m, 400, 30.0, 9);
        for (int round = 0; round < 300; ++round) {
            // A query region (one unit or the union of a few) against four slot regions.
            const auto [qr, qe] = packedUnion(m, units, 1 + rng() % 3, rng);
            WideRegions w{};
            PackedRegion sr[4]{};
            PackedExtra se[4]{};
            for (int l = 0; l < 4; ++l) {
                const PackedUnion slot = packedUnion(m, units, 1 + rng() % 4, rng);
                sr[l] = slot.r;
                se[l] = slot.e;
                setLane(w, l, sr[l], se[l]);
                PackedRegion back{};
                PackedExtra backExtra{};
                getLane(w, l, back, backExtra);
                EXPECT_EQ(back.maxFv, sr[l].maxFv);
                EXPECT_EQ(back.lo[2], sr[l].lo[2]);
            }
            const WideQueryT<2> query(m, qr, qe);
            const WideQueryT<4> query4(m, qr, qe);
            double bounds[4];
            double bounds4[4];
            query.bounds(w, bounds);
            query4.bounds(w, bounds4);
            const PackedRef q{&qr, boxModel ? &qe : nullptr};
            for (int l = 0; l < 4; ++l) {
                const PackedRef s{&sr[l], boxModel ? &se[l] : nullptr};
                const double scalar = pairLowerBound(m, q, s);
                EXPECT_NEAR(bounds[l], scalar, 1e-12 * scalar);
                EXPECT_EQ(bounds4[l], bounds[l]);
                // Thresholds around the bound, where the verdict flips.
                for (double f : {0.5, 0.999999, 1.000001, 2.0, 1e3 * unit(rng)}) {
                    const double t = scalar * f;
                    const bool lane = (query.exceeds(w, t) >> l & 1u) != 0;
                    EXPECT_EQ(lane, PackedPairTest(m, t).exceeds(q, s))
                        << toString(model.volume) << " k=" << model.k << " lane " << l;
                    EXPECT_EQ((query4.exceeds(w, t) >> l & 1u) != 0, lane);
                    expectModelKindAsAny<2>(m, qr, qe, w, t);
                    expectModelKindAsAny<4>(m, qr, qe, w, t);
                }
            }
        }
    }
}

// The single-precision k = 0 test against the double one: it never rejects a lane the double
// test keeps, and away from the threshold (beyond its margin) the two agree. Also with values
// at the ends of single precision's range, where the threshold itself still is in range.
TEST(MergeBvh, SingleK0TestIsTheDoubleTestWithAMargin) {
    const CostModel m(VolumeType::Aabb, 0.0);
    std::mt19937_64 rng(11);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::size_t rejected = 0;
    for (const double scale : {1.0, 1e-4, 1e4}) {
        std::vector<ClusterUnit> units = randomUnits(m, 300, 30.0, 13);
        for (ClusterUnit& u : units) {
            u.box.min *= scale;
            u.box.max *= scale;
            u.volume *= scale * scale * scale;
            u.fv *= scale * scale * scale;
        }
        for (int round = 0; round < 400; ++round) {
            const auto [qr, qe] = packedUnion(m, units, 1 + rng() % 3, rng);
            WideRegions a{};
            WideRegions b{};
            for (int l = 0; l < 4; ++l) {
                const PackedUnion ua = packedUnion(m, units, 1 + rng() % 4, rng);
                setLane(a, l, ua.r, ua.e);
                const PackedUnion ub = packedUnion(m, units, 1 + rng() % 4, rng);
                setLane(b, l, ub.r, ub.e);
            }
            const WideQueryT<2, BoundKind::BoxK0> exact(m, qr, qe);
            const WideQueryT<2, BoundKind::BoxK0Single> single(m, qr, qe);
            const WideQueryT<4, BoundKind::BoxK0Single> single4(m, qr, qe);
            double bounds[4];
            double boundsB[4];
            exact.bounds(a, bounds);
            exact.bounds(b, boundsB);
            for (double f : {1e-3, 0.5, 0.9999, 1.0001, 2.0, 1e3}) {
                const double t = bounds[rng() % 4] * f * (0.5 + unit(rng));
                if (!singleUsable(t)) continue;
                const unsigned both = single.exceeds2(a, b, t);
                EXPECT_EQ(single4.exceeds2(a, b, t), both);
                EXPECT_EQ(single.exceeds(a, t), both & 0xfu);
                for (int l = 0; l < 8; ++l) {
                    const double bound = l < 4 ? bounds[l] : boundsB[l - 4];
                    const bool singleExceeds = (both >> l & 1u) != 0;
                    const bool exactExceeds =
                        ((l < 4 ? exact.exceeds(a, t) : exact.exceeds(b, t)) >> (l % 4) & 1u) != 0;
                    if (!exactExceeds) {
                        EXPECT_FALSE(singleExceeds) << "lane " << l << " scale " << scale;
                    }
                    // (Far from 1, squared volumes leave single precision's range: the test
                    // rejects less there, but still nothing the double test keeps.)
                    if (scale == 1.0 && bound > t * 1.001) {
                        EXPECT_TRUE(singleExceeds) << "lane " << l;
                    }
                    rejected += singleExceeds ? 1 : 0;
                }
            }
        }
    }
    EXPECT_GT(rejected, 1000u);
}

// The threshold near the 5th percentile pair cost of `units`, so some pairs are in and most
// are out.
double lowPairCost(const CostModel& m, const std::vector<ClusterUnit>& units) {
    std::vector<double> costs;
    for (std::size_t i = 0; i < units.size(); ++i) {
        for (std::size_t j = i + 1; j < units.size(); ++j)
            costs.push_back(cost(m, units, i, j));
    }
    std::sort(costs.begin(), costs.end());
    return costs.empty() ? 1.0 : costs[costs.size() / 20];
}

// The join over `units` reports each pair within `threshold` once, nothing its item test
// rejects, the same pairs with every vector width, and if `prunes` (and there are enough
// units) not every pair; returns how many pairs are within.
std::size_t expectJoinFindsThePairs(const CostModel& m, const std::vector<ClusterUnit>& units,
                                    double threshold, const std::string& what, bool prunes = true) {
    const bool boxModel = m.volume() == VolumeType::Aabb;
    const auto n = static_cast<std::uint32_t>(units.size());
    const MergeBvh bvh = buildOver(m, units);
    std::multiset<std::pair<std::uint32_t, std::uint32_t>> seen;
    for (MergeBvh::Simd simd : simds()) {
        std::multiset<std::pair<std::uint32_t, std::uint32_t>> pairs;
        bvh.join(
            threshold,
            [&](std::uint32_t i, std::uint32_t j) {
                EXPECT_NE(i, j);
                pairs.emplace(std::min(i, j), std::max(i, j));
            },
            simd);
        if (simd != MergeBvh::Simd::Baseline) {
            EXPECT_EQ(pairs, seen) << what << ": the " << nameOf(simd) << " join differs";
        }
        seen = std::move(pairs);
    }
    // The k = 0 join tests in single precision (WideBounds.h), which may keep a pair whose
    // bound exceeds the threshold by less than its margin (1 - 2^-12), never one above that.
    const double margin = boundKindOf(m) == BoundKind::BoxK0 ? 1.0 + 1e-3 : 1.0;
    const PackedPairTest test(m, threshold * margin);
    std::size_t within = 0;
    for (std::uint32_t i = 0; i < n; ++i) {
        for (std::uint32_t j = i + 1; j < n; ++j) {
            const std::size_t count = seen.count({i, j});
            EXPECT_LE(count, 1u) << what << ": pair " << i << "," << j << " reported twice";
            if (cost(m, units, i, j) <= threshold) {
                ++within;
                EXPECT_EQ(count, 1u) << what << " misses pair " << i << "," << j;
            }
            if (count == 1) {
                PackedRegion a{}, b{};
                PackedExtra ae{}, be{};
                packRegion(regionOf(m, units[i]), boxModel, a, ae);
                packRegion(regionOf(m, units[j]), boxModel, b, be);
                EXPECT_FALSE(test.exceeds(PackedRef{&a, boxModel ? &ae : nullptr},
                                          PackedRef{&b, boxModel ? &be : nullptr}))
                    << what;
            }
        }
    }
    if (prunes && n >= 17) {
        EXPECT_LT(seen.size(), n * (n - 1) / 2) << what << ": nothing was pruned";
    }
    return within;
}

// The search finds the cheapest partner of every `stride`-th unit with every vector width and,
// if `prunes`, without visiting everything.
void expectSearchFindsTheCheapest(const CostModel& m, const std::vector<ClusterUnit>& units,
                                  std::uint32_t stride, const std::string& what,
                                  bool prunes = true) {
    const MergeBvh bvh = buildOver(m, units);
    for (std::uint32_t u = 0; u < units.size(); u += stride) {
        double expected = std::numeric_limits<double>::infinity();
        for (std::uint32_t v = 0; v < units.size(); ++v) {
            if (v != u) expected = std::min(expected, cost(m, units, u, v));
        }
        for (MergeBvh::Simd simd : simds()) {
            double best = std::numeric_limits<double>::infinity();
            std::size_t visited = 0;
            bvh.search(
                u, best,
                [&](std::uint32_t v) {
                    ++visited;
                    if (v != u) best = std::min(best, cost(m, units, u, v));
                },
                simd);
            EXPECT_EQ(best, expected) << what << " " << nameOf(simd);
            if (prunes) {
                EXPECT_LT(visited, units.size()) << what << ": the search visited everything";
            }
        }
    }
}

std::string nameOf(const Model& model) {
    return std::string(toString(model.volume)) + " k=" + std::to_string(model.k).substr(0, 3);
}

TEST(MergeBvh, JoinReportsEveryPairWithinTheThresholdOnce) {
    for (const Model& model : kModels) {
        const CostModel m(model.volume, model.k);
        for (std::size_t n : {1u, 2u, 5u, 17u, 300u}) {
            const std::vector<ClusterUnit> units = randomUnits(m, n, 40.0, 20 + n);
            const std::size_t within =
                expectJoinFindsThePairs(m, units, lowPairCost(m, units), nameOf(model));
            if (n >= 17) {
                EXPECT_GT(within, 0u);
            }
        }
    }
}

TEST(MergeBvh, SearchFindsTheCheapestPartner) {
    for (const Model& model : kModels) {
        const CostModel m(model.volume, model.k);
        expectSearchFindsTheCheapest(m, randomUnits(m, 500, 60.0, 77), 7, nameOf(model));
    }
}

// The hierarchy's shape follows the items' Morton codes (MergeBvh.h): layouts that make the
// splits uneven or the codes equal build deep or lopsided hierarchies, which answer as well.
TEST(MergeBvh, DegenerateLayoutsAnswerAsWell) {
    for (const Model& model : kModels) {
        const CostModel m(model.volume, model.k);
        const auto cube = [&](const glm::dvec3& lo, double side) {
            const Aabb box{lo, lo + glm::dvec3(side)};
            return m.leaf(Sphere{box.center(), side * 0.87}, box, 1e-9);
        };
        // Every centre the same: equal codes, split by count.
        std::vector<ClusterUnit> same;
        for (int i = 0; i < 40; ++i) {
            const double side = 1.0 + 0.01 * i;
            same.push_back(cube(glm::dvec3(-side / 2), side));
        }
        // Centres at halving distances along each axis: the codes of the near ones differ in
        // ever lower bits, so split after split peels off one item, down to equal codes.
        std::vector<ClusterUnit> halving;
        for (int i = 0; i < 70; ++i) {
            glm::dvec3 at(0.0);
            at[i % 3] = std::ldexp(1000.0, -i / 3);
            halving.push_back(cube(at, 1e-3 * (1.0 + 0.1 * (i % 5))));
        }
        // A clump and a few items far away: lopsided splits at the top.
        std::vector<ClusterUnit> clump = randomUnits(m, 120, 2.0, 5);
        for (int i = 0; i < 3; ++i)
            clump.push_back(cube(glm::dvec3(1e4 * (i + 1), -1e4 * i, 3e3), 0.5));
        // (Nested items: nothing to prune, every pair is near.)
        const std::string name = nameOf(model);
        EXPECT_GT(expectJoinFindsThePairs(m, same, lowPairCost(m, same), name + " same", false),
                  0u);
        expectSearchFindsTheCheapest(m, same, 1, name + " same", false);
        for (const auto& [layout, units] :
             {std::pair{"halving", &halving}, std::pair{"clump", &clump}}) {
            const std::string what = name + " " + layout;
            EXPECT_GT(expectJoinFindsThePairs(m, *units, lowPairCost(m, *units), what), 0u);
            expectSearchFindsTheCheapest(m, *units, 1, what);
        }
    }
}

TEST(MergeBvh, EmptyAndSingleItemHierarchies) {
    const CostModel m(VolumeType::Aabb, 1.0);
    MergeBvh empty;
    empty.build({}, {}, m);
    int calls = 0;
    empty.join(1e9, [&](std::uint32_t, std::uint32_t) { ++calls; });
    EXPECT_EQ(calls, 0);
    const std::vector<ClusterUnit> one = randomUnits(m, 1, 1.0, 1);
    const MergeBvh single = buildOver(m, one);
    single.join(1e30, [&](std::uint32_t, std::uint32_t) { ++calls; });
    double best = std::numeric_limits<double>::infinity();
    single.search(0, best, [&](std::uint32_t v) { EXPECT_EQ(v, 0u); });
    EXPECT_EQ(calls, 0);
}

} // namespace
} // namespace hlod
