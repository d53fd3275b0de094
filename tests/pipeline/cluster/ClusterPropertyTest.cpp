// Property test: the fast level merger (pipeline/cluster/LevelMerger) builds exactly the tree
// of the naive all-pairs reference (NaiveClusterer.h) on random scenes, for every cost model,
// several sizes, seeds, layouts and children caps, with and without hand-edit constraints.
#include <tuple>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include "NaiveClusterer.h"
#include "RandomScenes.h"
#include "TreeCompare.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterDriver.h"
#include "pipeline/cluster/ClusterValidate.h"
#include "pipeline/cluster/LevelMerger.h"

namespace hlod {
namespace {

struct Model {
    VolumeType volume;
    double k;
};

const Model kModels[] = {{VolumeType::Sphere, 0.0},
                         {VolumeType::Aabb, 0.0},
                         {VolumeType::Aabb, 1.0},
                         {VolumeType::Aabb, 2.0}};

ClusterTree naiveTree(const Scene& scene, const ClusterParams& p) {
    return buildConstrainedTree(scene, p,
                                CostModel(p.volume, p.volume == VolumeType::Aabb ? p.k : 0.0),
                                [](TreeBuilder& b, std::vector<Id> u, int c, const Progress& g) {
                                    return test::naiveMergeLevels(b, std::move(u), c, g);
                                });
}

// Structural promises of the rule on top of the ClusterTree invariants.
void expectRuleShape(const ClusterTree& t, const ClusterParams& p) {
    for (Id i = 0; i < t.nodes.size(); ++i) {
        const ClusterNode& n = t.nodes[i];
        if (n.isLeaf()) continue;
        EXPECT_GE(n.children.size(), 2u) << "single-child node " << i;
        // Hand edits win over the cap: the root over excluded meshes, locked clusters
        // (LocalConstraints.h).
        if ((p.excluded.empty() || i != t.root) && !n.locked) {
            EXPECT_LE(n.children.size(), static_cast<std::size_t>(p.maxChildren)) << i;
        }
    }
}

class FastEqualsNaive
    : public ::testing::TestWithParam<std::tuple<std::size_t, std::uint64_t, int>> {};

TEST_P(FastEqualsNaive, SameTreeForEveryModel) {
    const auto [n, seed, modelIndex] = GetParam();
    const Model model = kModels[modelIndex];
    const test::Layout layout = seed % 2 ? test::Layout::Clumped : test::Layout::Uniform;
    const Scene scene = test::makeRandomScene({n, layout, seed, 0.08});
    ClusterParams p;
    p.volume = model.volume;
    p.k = model.k;
    p.maxChildren = seed == 1 ? 8 : (seed == 2 ? 2 : 4);
    const ClusterTree fast = buildClusterTree(scene, p);
    const ClusterTree reference = naiveTree(scene, p);
    EXPECT_EQ(test::treeDifference(fast, reference), "");
    EXPECT_EQ(validateClusterTree(fast, scene.instances.size()), "");
    EXPECT_EQ(fast.leafCount(), n);
    expectRuleShape(fast, p);
}

INSTANTIATE_TEST_SUITE_P(RandomScenes, FastEqualsNaive,
                         ::testing::Combine(::testing::Values<std::size_t>(2, 3, 9, 40, 130, 300),
                                            ::testing::Values<std::uint64_t>(1, 2, 3),
                                            ::testing::Values(0, 1, 2, 3)));

TEST(ClusterProperty, FastEqualsNaiveForFractionalK) {
    // k = 0.5 takes the pow() path of the proportion term.
    const Scene scene = test::makeRandomScene({150, test::Layout::Clumped, 9, 0.05});
    ClusterParams p;
    p.volume = VolumeType::Aabb;
    p.k = 0.5;
    p.maxChildren = 5;
    EXPECT_EQ(test::treeDifference(buildClusterTree(scene, p), naiveTree(scene, p)), "");
}

TEST(ClusterProperty, FastEqualsNaiveForOtherRuleConstants) {
    // Budget samples smaller than the unit count (production uses 256, near the sizes the
    // naive reference can handle), short or long neighbour lists, graphs rebuilt at every level
    // or inherited until the budget or the fallback forces a rebuild (R = 1000), with graph
    // budgets from B to 8 B; and the production constants on the baseline vector width (the
    // other runs use AVX2 where the processor has it).
    const Scene scene = test::makeRandomScene({250, test::Layout::Clumped, 12, 0.05});
    for (const Model& model : kModels) {
        for (const LevelMergeOptions options :
             {LevelMergeOptions{1, 8, 2, 1.0}, LevelMergeOptions{7, 1, 1, 1.0},
              LevelMergeOptions{64, 3, 4, 8.0}, LevelMergeOptions{1000, 40, 1, 2.0},
              LevelMergeOptions{256, 2, 1000, 1.0}, LevelMergeOptions{256, 8, 1000, 4.0},
              LevelMergeOptions{256, 8, 2, 2.0, true}}) {
            ClusterParams p;
            p.volume = model.volume;
            p.k = model.k;
            p.maxChildren = 6;
            const CostModel cost(p.volume, p.k);
            const ClusterTree fast = buildConstrainedTree(
                scene, p, cost, [&](TreeBuilder& b, std::vector<Id> u, int c, const Progress& g) {
                    return mergeLevelsWith(b, std::move(u), c, g, options);
                });
            const ClusterTree reference = buildConstrainedTree(
                scene, p, cost, [&](TreeBuilder& b, std::vector<Id> u, int c, const Progress& g) {
                    return test::naiveMergeLevels(b, std::move(u), c, g, options);
                });
            EXPECT_EQ(test::treeDifference(fast, reference), "")
                << "S " << options.budgetSample << " K " << options.neighbours << " R "
                << options.rebuildRatio << " G " << options.graphBudgetFactor
                << (options.baselineSimd ? " baseline" : "");
            EXPECT_EQ(validateClusterTree(fast, scene.instances.size()), "");
        }
    }
}

TEST(ClusterProperty, FastEqualsNaiveWithConstraints) {
    for (const Model& model : kModels) {
        const Scene scene = test::makeRandomScene({120, test::Layout::Uniform, 21, 0.05});
        ClusterParams p;
        p.volume = model.volume;
        p.k = model.k;
        p.maxChildren = 6;
        p.lockedGroups = {{3, 50, 97, 11}, {7}, {60, 61, 62, 63, 64, 65, 66, 67, 68, 69}};
        p.excluded = {0, 119, 42};
        const ClusterTree fast = buildClusterTree(scene, p);
        EXPECT_EQ(test::treeDifference(fast, naiveTree(scene, p)), "");
        EXPECT_EQ(validateClusterTree(fast, scene.instances.size()), "");
        expectRuleShape(fast, p);
    }
}

TEST(ClusterProperty, TreeDoesNotDependOnThreadCount) {
    const Scene scene = test::makeRandomScene({3000, test::Layout::Clumped, 4, 0.05});
    ClusterParams p;
    p.volume = VolumeType::Aabb;
    p.k = 1.0;
    ClusterTree one, two;
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = buildClusterTree(scene, p);
    }
    {
        tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 2);
        two = buildClusterTree(scene, p);
    }
    EXPECT_EQ(test::treeDifference(one, two), "");
    EXPECT_EQ(validateClusterTree(one, scene.instances.size()), "");
}

} // namespace
} // namespace hlod
