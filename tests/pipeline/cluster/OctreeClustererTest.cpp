// Loose octree baseline (pipeline/cluster/OctreeClusterer.h).
#include <gtest/gtest.h>

#include "HandScenes.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterValidate.h"

namespace hlod {
namespace {

ClusterParams octree(int maxChildren) {
    ClusterParams p;
    p.volume = VolumeType::Octree;
    p.maxChildren = maxChildren;
    return p;
}

std::vector<glm::dvec3> cornerCubes() {
    // Unit cubes in the eight corners of [0, 10]^3.
    std::vector<glm::dvec3> c;
    for (int i = 0; i < 8; ++i)
        c.emplace_back(i & 1 ? 9 : 0, i & 2 ? 9 : 0, i & 4 ? 9 : 0);
    return c;
}

TEST(OctreeClusterer, EightCornersSplitIntoEightOctants) {
    // More than 4 units: the root cell splits; each octant holds one cube, which collapses
    // into its leaf, so the root's children are the 8 leaves.
    const ClusterTree t = buildClusterTree(test::cubesAt(cornerCubes()), octree(4));
    ASSERT_EQ(validateClusterTree(t, 8), "");
    ASSERT_EQ(t.nodes.size(), 9u);
    EXPECT_EQ(t.nodes[t.root].children, (std::vector<Id>{0, 1, 2, 3, 4, 5, 6, 7}));
    EXPECT_EQ(t.volume, VolumeType::Octree);
}

TEST(OctreeClusterer, FewUnitsStayInOneCell) {
    // 8 units and a threshold of 8: no split, one flat node.
    const ClusterTree t = buildClusterTree(test::cubesAt(cornerCubes()), octree(8));
    ASSERT_EQ(t.nodes.size(), 9u);
    EXPECT_EQ(t.nodes[t.root].children.size(), 8u);
}

TEST(OctreeClusterer, PartLargerThanTheOctantsStaysAtTheRoot) {
    // Instance 8 is a 10 m cube over the whole scene: it fits no octant (5 m, loose 10 m but
    // not where it sits), so it stays in the root cell beside the eight octants' leaves.
    std::vector<glm::dvec3> c = cornerCubes();
    Scene s = test::cubesAt(c);
    const glm::dmat4 big = glm::scale(glm::dmat4(1.0), glm::dvec3(10.0));
    s.addInstance(0, s.addNode("big", 0, big));
    const ClusterTree t = buildClusterTree(s, octree(4));
    ASSERT_EQ(validateClusterTree(t, 9), "");
    EXPECT_EQ(t.nodes[t.root].children, (std::vector<Id>{0, 1, 2, 3, 4, 5, 6, 7, 8}));
}

TEST(OctreeClusterer, LooseCellsTakePartsOnTheSplitPlane) {
    // Two clumps of three small cubes, one straddling the x = 5 split plane of the root cell
    // (a plain octree would keep it at the root). The looseness lets it move down with its
    // neighbours: the root has two children, each holding one clump.
    const Scene s = test::cubesAt({{4.9, 0, 0},
                                   {4.9, 0.5, 0},
                                   {4.9, 1.0, 0},
                                   {4.9, 9.0, 9.0},
                                   {4.9, 9.0, 8.5},
                                   {4.9, 9.0, 8.0}},
                                  0.2);
    const ClusterTree t = buildClusterTree(s, octree(3));
    ASSERT_EQ(validateClusterTree(t, 6), "");
    ASSERT_EQ(t.nodes[t.root].children.size(), 2u);
    EXPECT_EQ(test::leavesBelow(t, t.nodes[t.root].children[0]), (std::vector<Id>{0, 1, 2}));
    EXPECT_EQ(test::leavesBelow(t, t.nodes[t.root].children[1]), (std::vector<Id>{3, 4, 5}));
}

TEST(OctreeClusterer, CoincidentPartsStayInOneCell) {
    // Ten identical cubes fill the root cell; none fits an octant (each is as large as the
    // cell), so subdivision stops with one flat node.
    const Scene s = test::cubesAt(std::vector<glm::dvec3>(10, glm::dvec3(3, 3, 3)));
    const ClusterTree t = buildClusterTree(s, octree(4));
    ASSERT_EQ(validateClusterTree(t, 10), "");
    EXPECT_EQ(t.nodes.size(), 11u);
    EXPECT_EQ(t.nodes[t.root].children.size(), 10u);
}

TEST(OctreeClusterer, RandomSceneIsAValidTree) {
    const Scene s = test::makeRandomScene({2000, test::Layout::Clumped, 3, 0.05});
    const ClusterTree t = buildClusterTree(s, octree(8));
    EXPECT_EQ(validateClusterTree(t, 2000), "");
    for (const ClusterNode& n : t.nodes) {
        if (!n.isLeaf()) {
            EXPECT_GE(n.children.size(), 2u);
        }
    }
}

} // namespace
} // namespace hlod
