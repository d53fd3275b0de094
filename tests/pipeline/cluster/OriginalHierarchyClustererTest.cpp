// Original hierarchy baseline, leaf-only conversion of thesis figure 5.2
// (pipeline/cluster/OriginalHierarchyClusterer.h).
#include <gtest/gtest.h>

#include "HandScenes.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterValidate.h"

namespace hlod {
namespace {

ClusterParams original() {
    ClusterParams p;
    p.volume = VolumeType::Original;
    p.maxChildren = 2; // ignored: the scene's grouping is kept
    return p;
}

TEST(OriginalHierarchyClusterer, MeshesOfInnerNodesBecomeLeafSiblings) {
    // Figure 5.2 (a): A has a mesh and children B, C, D (meshes); B has E, F; D has G, H.
    // Expected (b): A -> {a, B', C-leaf, D'}, B' -> {b, e, f}, D' -> {d, g, h}; C has no
    // children so its mesh is a plain leaf under A.
    Scene s;
    s.addMesh(test::makeBoxMesh({0, 0, 0}, {1, 1, 1}, "cube"));
    const Id A = s.addNode("A", 0);
    const Id B = s.addNode("B", A);
    const Id C = s.addNode("C", A);
    const Id D = s.addNode("D", A);
    const Id E = s.addNode("E", B);
    const Id F = s.addNode("F", B);
    const Id G = s.addNode("G", D);
    const Id H = s.addNode("H", D);
    for (Id n : {A, B, C, D, E, F, G, H})
        s.addInstance(0, n); // instance i on the i-th node
    const ClusterTree t = buildClusterTree(s, original());
    ASSERT_EQ(validateClusterTree(t, 8), "");
    // Leaves 0..7, B' = 8 {1, 4, 5}, D' = 9 {3, 6, 7}, A' = 10 {0, 2, 8, 9}.
    ASSERT_EQ(t.nodes.size(), 11u);
    EXPECT_EQ(t.nodes[8].children, (std::vector<Id>{1, 4, 5}));
    EXPECT_EQ(t.nodes[9].children, (std::vector<Id>{3, 6, 7}));
    EXPECT_EQ(t.root, 10u);
    EXPECT_EQ(t.nodes[10].children, (std::vector<Id>{0, 2, 8, 9}));
    EXPECT_EQ(t.height(), 2);
}

TEST(OriginalHierarchyClusterer, TransformOnlyChainsAndEmptyBranchesVanish) {
    // root -> X -> Y -> Z (one mesh), root -> W (two meshes), root -> Empty -> Empty2.
    // X, Y and the empty branch make no nodes: root' = {z, W'}, W' = {w1, w2}.
    Scene s;
    s.addMesh(test::makeBoxMesh({0, 0, 0}, {1, 1, 1}, "cube"));
    const Id X = s.addNode("X", 0);
    const Id Y = s.addNode("Y", X);
    const Id Z = s.addNode("Z", Y);
    const Id W = s.addNode("W", 0);
    s.addNode("Empty2", s.addNode("Empty", 0));
    s.addInstance(0, Z);
    s.addInstance(0, W);
    s.addInstance(0, W);
    const ClusterTree t = buildClusterTree(s, original());
    ASSERT_EQ(validateClusterTree(t, 3), "");
    ASSERT_EQ(t.nodes.size(), 5u);
    EXPECT_EQ(t.nodes[3].children, (std::vector<Id>{1, 2}));
    EXPECT_EQ(t.nodes[4].children, (std::vector<Id>{0, 3}));
    EXPECT_EQ(t.root, 4u);
}

TEST(OriginalHierarchyClusterer, FlatSceneIsOneNode) {
    // All instances directly under the scene root: one root with every leaf.
    const ClusterTree t =
        buildClusterTree(test::cubesAt({{0, 0, 0}, {3, 0, 0}, {6, 0, 0}, {9, 0, 0}}), original());
    ASSERT_EQ(t.nodes.size(), 5u);
    EXPECT_EQ(t.nodes[t.root].children, (std::vector<Id>{0, 1, 2, 3}));
}

} // namespace
} // namespace hlod
