// Tree quality metrics on a hand-built tree (pipeline/cluster/TreeMetrics.h).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "pipeline/cluster/TreeMetrics.h"

namespace hlod {
namespace {

// Leaves at x = -1, 1, 9, 11 (unit boxes centred there); N4 = {0, 1} (radius 2, box
// [-1.5, 1.5]^x), N5 = {2, 3}, root N6 = {4, 5} (radius 7 around x = 5).
ClusterTree fourLeaves() {
    ClusterTree t;
    const double xs[] = {-1, 1, 9, 11};
    for (Id i = 0; i < 4; ++i) {
        ClusterNode n;
        n.instance = i;
        n.box = Aabb{{xs[i] - 0.5, -0.5, -0.5}, {xs[i] + 0.5, 0.5, 0.5}};
        n.sphere = Sphere{{xs[i], 0, 0}, 0.5};
        t.nodes.push_back(n);
    }
    auto inner = [&](std::vector<Id> children, double cx, double r, double fill) {
        ClusterNode n;
        n.children = children;
        n.sphere = Sphere{{cx, 0, 0}, r};
        n.fill = fill;
        for (Id c : children) {
            n.box.expand(t.nodes[c].box);
            t.nodes[c].parent = static_cast<Id>(t.nodes.size());
            n.level = std::max(n.level, t.nodes[c].level + 1);
        }
        t.nodes.push_back(n);
    };
    inner({0, 1}, 0.0, 2.0, 0.5);
    inner({2, 3}, 10.0, 2.0, 0.25);
    inner({4, 5}, 5.0, 7.0, 0.75);
    t.root = 6;
    return t;
}

TEST(TreeMetrics, CountsDepthAndChildren) {
    const TreeMetrics m = computeTreeMetrics(fourLeaves());
    EXPECT_EQ(m.nodes, 7u);
    EXPECT_EQ(m.leaves, 4u);
    EXPECT_EQ(m.innerNodes, 3u);
    EXPECT_EQ(m.depth, 2);
    EXPECT_DOUBLE_EQ(m.meanLeafDepth, 2.0);
    EXPECT_EQ(m.minChildren, 2u);
    EXPECT_EQ(m.maxChildren, 2u);
    EXPECT_DOUBLE_EQ(m.meanChildren, 2.0);
    EXPECT_DOUBLE_EQ(m.meanFill, 0.5); // (0.5 + 0.25 + 0.75) / 3
}

TEST(TreeMetrics, VolumesSumInnerNodes) {
    const TreeMetrics m = computeTreeMetrics(fourLeaves());
    // Spheres: 4/3 pi (8 + 8 + 343); boxes: 3 x 1 x 1 twice and 13 x 1 x 1.
    EXPECT_NEAR(m.totalSphereVolume, 4.0 / 3.0 * std::numbers::pi * 359.0, 1e-9);
    EXPECT_DOUBLE_EQ(m.totalBoxVolume, 3.0 + 3.0 + 13.0);
}

TEST(TreeMetrics, SpreadIsRmsLeafDistanceOverRadius) {
    const TreeMetrics m = computeTreeMetrics(fourLeaves());
    // N4: leaves at -1, 1 around 0: RMS 1, radius 2 -> 0.5 (same for N5).
    // Root: leaves at -1, 1, 9, 11 around 5: distances 6, 4, 4, 6, RMS sqrt(26), radius 7.
    const double root = std::sqrt(26.0) / 7.0;
    EXPECT_NEAR(m.maxSpread, root, 1e-12);
    EXPECT_NEAR(m.meanSpread, (0.5 + 0.5 + root) / 3.0, 1e-12);
}

TEST(TreeMetrics, EmptyAndSingleLeafTrees) {
    EXPECT_EQ(computeTreeMetrics(ClusterTree{}).nodes, 0u);
    ClusterTree one;
    one.nodes.push_back(ClusterNode{});
    one.nodes[0].instance = 0;
    one.root = 0;
    const TreeMetrics m = computeTreeMetrics(one);
    EXPECT_EQ(m.leaves, 1u);
    EXPECT_EQ(m.depth, 0);
    EXPECT_EQ(m.innerNodes, 0u);
    EXPECT_EQ(m.minChildren, 0u);
}

} // namespace
} // namespace hlod
