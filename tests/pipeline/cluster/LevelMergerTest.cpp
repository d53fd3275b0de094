// Level merging on hand-built scenes (rule in pipeline/cluster/LevelMerger.h). Unit cubes with
// the AABB model and k = 0, where cost = V^2 / (F V) is easy to work out by hand.
#include <atomic>

#include <gtest/gtest.h>

#include "HandScenes.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterValidate.h"
#include "pipeline/core/Error.h"

namespace hlod {
namespace {

ClusterParams boxParams(int maxChildren = 8) {
    ClusterParams p;
    p.volume = VolumeType::Aabb;
    p.k = 0.0;
    p.maxChildren = maxChildren;
    return p;
}

TEST(LevelMerger, ClusterAbsorbsAThirdMemberWithinTheLevelBudget) {
    // A, B, C touch in a row at x = 0, 1, 2; D, E and F, G are pairs with a 1 m gap, far away.
    // Cheapest partners: A, B, C cost 2 (a 2 x 1 x 1 full box); D..G cost 3^2 / 2 = 4.5.
    // Lower median of [2, 2, 2, 4.5, 4.5, 4.5, 4.5] = 4.5 = level 1 budget. Level 1 merges AB
    // (2), then AB + C (a full 3 x 1 x 1 box: 3), then DE and FG (4.5 each).
    const Scene s = test::cubesAt(
        {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {100, 0, 0}, {102, 0, 0}, {200, 0, 0}, {202, 0, 0}});
    const ClusterTree t = buildClusterTree(s, boxParams());
    ASSERT_EQ(validateClusterTree(t, 7), "");
    ASSERT_EQ(t.nodes.size(), 12u);
    // New nodes in key order: ABC = 7, DE = 8, FG = 9.
    EXPECT_EQ(t.nodes[7].children, (std::vector<Id>{0, 1, 2}));
    EXPECT_DOUBLE_EQ(t.nodes[7].fill, 1.0);
    EXPECT_DOUBLE_EQ(t.nodes[7].cost, 3.0);
    EXPECT_EQ(t.nodes[8].children, (std::vector<Id>{3, 4}));
    EXPECT_DOUBLE_EQ(t.nodes[8].fill, 2.0 / 3.0);
    EXPECT_DOUBLE_EQ(t.nodes[8].cost, 4.5);
    EXPECT_EQ(t.nodes[9].children, (std::vector<Id>{5, 6}));
    // Level 2: 7-8 span 103 m (cost 103^2 / 5), 8-9 103 m (103^2 / 4), 7-9 203 m. Budget =
    // lower median = 103^2 / 5: only ABC + DE merge (adding FG would cost 203^2 / 7).
    EXPECT_EQ(t.nodes[10].children, (std::vector<Id>{7, 8}));
    EXPECT_DOUBLE_EQ(t.nodes[10].cost, 103.0 * 103.0 / 5.0);
    EXPECT_EQ(t.nodes[10].level, 2);
    // Level 3 joins the last two units.
    EXPECT_EQ(t.root, 11u);
    EXPECT_EQ(t.nodes[11].children, (std::vector<Id>{9, 10}));
    EXPECT_EQ(t.nodes[11].level, 3);
    EXPECT_EQ(t.height(), 3);
}

TEST(LevelMerger, EqualCostsMergeInIdOrder) {
    // Four identical cubes in one place: every pair costs 1 (the same full unit box), so only
    // the id tie-break decides. (0,1) first, then the group {0,1} (key 0) takes 2, then 3.
    const Scene s = test::cubesAt({{5, 5, 5}, {5, 5, 5}, {5, 5, 5}, {5, 5, 5}});
    const ClusterTree t = buildClusterTree(s, boxParams(8));
    ASSERT_EQ(t.nodes.size(), 5u);
    EXPECT_EQ(t.root, 4u);
    EXPECT_EQ(t.nodes[4].children, (std::vector<Id>{0, 1, 2, 3}));
    EXPECT_DOUBLE_EQ(t.nodes[4].cost, 1.0);
}

TEST(LevelMerger, ChildrenCapStopsAbsorption) {
    // Same four cubes with at most 3 children: {0,1,2} fills up, 3 waits for level 2.
    const Scene s = test::cubesAt({{5, 5, 5}, {5, 5, 5}, {5, 5, 5}, {5, 5, 5}});
    const ClusterTree t3 = buildClusterTree(s, boxParams(3));
    ASSERT_EQ(t3.nodes.size(), 6u);
    EXPECT_EQ(t3.nodes[4].children, (std::vector<Id>{0, 1, 2}));
    EXPECT_EQ(t3.nodes[5].children, (std::vector<Id>{3, 4}));
    // Binary: {0,1} is full, so the next cheapest valid pair is (2,3).
    const ClusterTree t2 = buildClusterTree(s, boxParams(2));
    ASSERT_EQ(t2.nodes.size(), 7u);
    EXPECT_EQ(t2.nodes[4].children, (std::vector<Id>{0, 1}));
    EXPECT_EQ(t2.nodes[5].children, (std::vector<Id>{2, 3}));
    EXPECT_EQ(t2.nodes[6].children, (std::vector<Id>{4, 5}));
}

TEST(LevelMerger, SphereModelPairsNeighboursFirst) {
    // Unit cubes at 0, 1.5 (close pair) and 10, 11.5 (close pair): the sphere tree pairs the
    // neighbours, then joins the pairs.
    const Scene s = test::cubesAt({{0, 0, 0}, {1.5, 0, 0}, {10, 0, 0}, {11.5, 0, 0}});
    ClusterParams p;
    p.volume = VolumeType::Sphere;
    const ClusterTree t = buildClusterTree(s, p);
    ASSERT_EQ(t.nodes.size(), 7u);
    EXPECT_EQ(t.nodes[4].children, (std::vector<Id>{0, 1}));
    EXPECT_EQ(t.nodes[5].children, (std::vector<Id>{2, 3}));
    EXPECT_EQ(t.nodes[6].children, (std::vector<Id>{4, 5}));
    EXPECT_EQ(t.volume, VolumeType::Sphere);
    EXPECT_EQ(t.k, 0.0);
}

TEST(LevelMerger, SingleInstanceIsARootLeaf) {
    const ClusterTree t = buildClusterTree(test::cubesAt({{1, 2, 3}}), boxParams());
    ASSERT_EQ(t.nodes.size(), 1u);
    EXPECT_EQ(t.root, 0u);
    EXPECT_EQ(t.nodes[0].instance, 0u);
    EXPECT_EQ(t.height(), 0);
}

TEST(LevelMerger, EmptySceneGivesEmptyTree) {
    const ClusterTree t = buildClusterTree(Scene{}, boxParams());
    EXPECT_TRUE(t.nodes.empty());
    EXPECT_EQ(t.root, kNoId);
    EXPECT_EQ(validateClusterTree(t, 0), "");
}

TEST(LevelMerger, SameInputSameTree) {
    const Scene s = test::makeRandomScene({500, test::Layout::Clumped, 8, 0.05});
    ClusterParams p;
    const ClusterTree a = buildClusterTree(s, p);
    const ClusterTree b = buildClusterTree(s, p);
    ASSERT_EQ(a.nodes.size(), b.nodes.size());
    for (std::size_t i = 0; i < a.nodes.size(); ++i) {
        EXPECT_EQ(a.nodes[i].children, b.nodes[i].children);
        EXPECT_EQ(a.nodes[i].cost, b.nodes[i].cost);
    }
}

TEST(LevelMerger, CancelFlagStopsClustering) {
    const Scene s = test::makeRandomScene({200, test::Layout::Uniform, 1, 0.0});
    std::atomic<bool> cancel{true};
    Progress progress;
    progress.cancel = &cancel;
    try {
        buildClusterTree(s, ClusterParams{}, progress);
        FAIL() << "expected Cancelled";
    } catch (const Error& e) {
        EXPECT_EQ(e.code(), ErrorCode::Cancelled);
    }
}

TEST(LevelMerger, ReportsProgressUpToAllMerges) {
    const Scene s = test::makeRandomScene({100, test::Layout::Uniform, 1, 0.0});
    std::uint64_t lastDone = 0, lastTotal = 0;
    Progress progress;
    progress.report = [&](const ProgressInfo& info) {
        if (info.stage != "cluster") return;
        lastDone = info.done;
        lastTotal = info.total;
    };
    buildClusterTree(s, ClusterParams{}, progress);
    EXPECT_EQ(lastTotal, 99u); // n - 1 merges of pairs join 100 units
    EXPECT_EQ(lastDone, 99u);
}

TEST(LevelMerger, RejectsBadParameters) {
    const Scene s = test::cubesAt({{0, 0, 0}, {2, 0, 0}});
    ClusterParams p;
    p.maxChildren = 1;
    EXPECT_THROW(buildClusterTree(s, p), Error);
    p = ClusterParams{};
    p.k = -1.0;
    p.volume = VolumeType::Aabb;
    EXPECT_THROW(buildClusterTree(s, p), Error);
}

} // namespace
} // namespace hlod
