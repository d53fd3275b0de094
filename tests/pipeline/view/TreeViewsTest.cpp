// Views of a hand-built cluster tree: level cuts, the cluster of each instance, depths, leaves
// below a node and subtree triangle counts, each checked against values worked out by hand.
#include <gtest/gtest.h>

#include "pipeline/view/TreeViews.h"

using namespace hlod;

namespace {

// Levels deliberately jump by more than one (root 3 above a level-1 child) to check the cut:
//   0 root (L3) ── 1 (L1) ── 2 leaf inst 0
//               │         └─ 3 leaf inst 1
//               └─ 5 (L2) ── 4 leaf inst 2
//                         └─ 6 (L1) ── 7 leaf inst 3
//                                   └─ 8 leaf inst 4
ClusterTree makeTree() {
    ClusterTree t;
    t.nodes.resize(9);
    auto link = [&](Id parent, std::vector<Id> children) {
        t.nodes[parent].children = children;
        for (Id c : children)
            t.nodes[c].parent = parent;
    };
    link(0, {1, 5});
    link(1, {2, 3});
    link(5, {4, 6});
    link(6, {7, 8});
    t.nodes[0].level = 3;
    t.nodes[1].level = 1;
    t.nodes[5].level = 2;
    t.nodes[6].level = 1;
    t.nodes[2].instance = 0;
    t.nodes[3].instance = 1;
    t.nodes[4].instance = 2;
    t.nodes[7].instance = 3;
    t.nodes[8].instance = 4;
    t.root = 0;
    return t;
}

} // namespace

TEST(TreeViews, LevelZeroIsTheLeavesAndTheTopLevelIsTheRoot) {
    const ClusterTree t = makeTree();
    EXPECT_EQ(nodesAtLevel(t, 0), (std::vector<Id>{2, 3, 4, 7, 8}));
    EXPECT_EQ(nodesAtLevel(t, -4), (std::vector<Id>{2, 3, 4, 7, 8})); // clamped to 0
    EXPECT_EQ(nodesAtLevel(t, 3), (std::vector<Id>{0}));
    EXPECT_EQ(nodesAtLevel(t, 9), (std::vector<Id>{0}));
}

TEST(TreeViews, LevelCutTakesTheHighestNodeAtOrBelowTheLevel) {
    const ClusterTree t = makeTree();
    // Level 1: node 1 (parent L3), leaf 4 (parent 5 is L2 > 1) and node 6 (parent L2).
    EXPECT_EQ(nodesAtLevel(t, 1), (std::vector<Id>{1, 4, 6}));
    // Level 2: node 1 stays (its parent is L3), node 5 now covers 4, 6, 7, 8.
    EXPECT_EQ(nodesAtLevel(t, 2), (std::vector<Id>{1, 5}));
}

TEST(TreeViews, EveryInstanceMapsToItsCutNode) {
    const ClusterTree t = makeTree();
    const std::vector<Id> cut = nodesAtLevel(t, 1); // {1, 4, 6}
    // Instances 0, 1 lie below node 1 (index 0), 2 is leaf 4 (index 1), 3 and 4 below node 6
    // (index 2); instance 5 is in no leaf.
    EXPECT_EQ(clusterOfInstances(t, cut, 6), (std::vector<int>{0, 0, 1, 2, 2, -1}));
}

TEST(TreeViews, DepthsLeavesAndSubtrees) {
    const ClusterTree t = makeTree();
    EXPECT_EQ(nodeDepths(t), (std::vector<int>{0, 1, 2, 2, 2, 1, 2, 3, 3}));
    EXPECT_EQ(instancesBelow(t, 5), (std::vector<Id>{2, 3, 4})); // child order: 4, then 6's
    EXPECT_EQ(instancesBelow(t, 3), (std::vector<Id>{1}));
    EXPECT_TRUE(instancesBelow(t, kNoId).empty());
    EXPECT_EQ(leafOfInstance(t, 3), 7u);
    EXPECT_EQ(leafOfInstance(t, 9), kNoId);
    EXPECT_TRUE(isInSubtree(t, 7, 5));
    EXPECT_TRUE(isInSubtree(t, 5, 5));
    EXPECT_FALSE(isInSubtree(t, 2, 5));
}

TEST(TreeViews, SubtreeTrianglesSumTheLeafMeshes) {
    const ClusterTree t = makeTree();
    Scene scene;
    Mesh one;
    one.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
    one.normals.assign(4, {0, 0, 1});
    one.indices = {0, 1, 2};
    Mesh two = one;
    two.indices = {0, 1, 2, 2, 1, 3};
    const Id a = scene.addMesh(one), b = scene.addMesh(two);
    for (Id mesh : {a, b, a, b, b})
        scene.addInstance(mesh, 0);
    // Leaves: 1, 2, 1, 2, 2 triangles; node 1 = 1 + 2, node 6 = 2 + 2, node 5 = 1 + 4, root 8.
    EXPECT_EQ(subtreeTriangles(t, scene), (std::vector<std::uint64_t>{8, 3, 1, 2, 1, 5, 4, 2, 2}));
}

TEST(TreeViews, EmptyTreeGivesEmptyViews) {
    const ClusterTree t;
    EXPECT_TRUE(nodesAtLevel(t, 1).empty());
    EXPECT_EQ(clusterOfInstances(t, {}, 2), (std::vector<int>{-1, -1}));
    EXPECT_TRUE(nodeDepths(t).empty());
}
