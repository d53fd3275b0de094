// Who a cluster is across rebuilds (widgets/ClusterIdentity.h): the key of a leaf set does not
// depend on node ids or child order, and a cluster keeps its label while its meshes are the
// same; new leaf sets get numbers never used before.
#include <gtest/gtest.h>

#include "widgets/ClusterIdentity.h"

namespace hlod::widgets {
namespace {

// Leaves 0..3 (instances 0..3), then inner nodes from `groups` (children ids), last = root.
ClusterTree treeOf(const std::vector<std::vector<Id>>& groups) {
    ClusterTree t;
    for (Id i = 0; i < 4; ++i) {
        ClusterNode leaf;
        leaf.instance = i;
        t.nodes.push_back(leaf);
    }
    for (const auto& children : groups) {
        ClusterNode n;
        n.children = children;
        for (Id c : children)
            t.nodes[c].parent = static_cast<Id>(t.nodes.size());
        t.nodes.push_back(n);
    }
    t.root = static_cast<Id>(t.nodes.size() - 1);
    return t;
}

TEST(ClusterIdentity, SameLeavesSameKeyWhateverTheNodeIds) {
    // {0,1} is node 4 in one tree and node 5 in the other.
    const ClusterTree a = treeOf({{0, 1}, {2, 3}, {4, 5}});
    const ClusterTree b = treeOf({{2, 3}, {1, 0}, {4, 5}});
    const auto ka = clusterKeys(a), kb = clusterKeys(b);
    EXPECT_EQ(ka[4], kb[5]);
    EXPECT_EQ(ka[5], kb[4]);
    EXPECT_EQ(ka[6], kb[6]); // the root: all four
    EXPECT_NE(ka[4], ka[5]);
}

TEST(ClusterIdentity, LabelsStayWithTheirLeafSetsAndNewOnesAreFresh) {
    ClusterLabels labels;
    const ClusterTree first = treeOf({{0, 1}, {2, 3}, {4, 5}});
    const auto l1 = labels.assign(first, clusterKeys(first));
    EXPECT_EQ(l1[4], 4); // the first tree: node ids
    EXPECT_EQ(l1[6], 6);
    EXPECT_EQ(l1[2], 2); // leaves: their instance
    // A rebuild numbering the same clusters differently: {0,1} is now node 5, {2,3} node 4.
    const ClusterTree second = treeOf({{2, 3}, {0, 1}, {4, 5}});
    const auto l2 = labels.assign(second, clusterKeys(second));
    EXPECT_EQ(l2[5], 4); // {0,1} keeps its label
    EXPECT_EQ(l2[4], 5); // {2,3} too
    // An edit: mesh 3 leaves the cluster {0,1,2,3}'s first child: {0,1,2} is new.
    const ClusterTree third = treeOf({{0, 1, 2}, {4, 3}});
    const auto l3 = labels.assign(third, clusterKeys(third));
    EXPECT_EQ(l3[4], 7); // {0,1,2} is new: the next unused number
    EXPECT_EQ(l3[5], 6); // the root holds the same four meshes
    // Undo: the first tree's labels come back.
    EXPECT_EQ(labels.assign(first, clusterKeys(first)), l1);
}

} // namespace
} // namespace hlod::widgets
