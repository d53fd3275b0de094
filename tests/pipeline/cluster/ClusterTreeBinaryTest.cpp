// The exact binary form of a cluster tree (ClusterTreeBinary.h): every field survives bit for
// bit, and damaged bytes are refused naming the file.
#include <gtest/gtest.h>

#include "TestUtil.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterTreeBinary.h"
#include "pipeline/io/SampleScene.h"

using namespace hlod;

TEST(ClusterTreeBinary, RoundTripsEveryFieldExactly) {
    const Scene scene = makeSampleScene();
    ClusterParams params;
    params.volume = VolumeType::Aabb;
    params.k = 2.0;
    ClusterTree tree = buildClusterTree(scene, params);
    tree.nodes[tree.root].locked = true;
    const std::string bytes = writeClusterTreeBinary(tree);
    const ClusterTree back = readClusterTreeBinary(bytes, "t.bin");
    ASSERT_EQ(back.nodes.size(), tree.nodes.size());
    EXPECT_EQ(back.root, tree.root);
    EXPECT_EQ(back.volume, VolumeType::Aabb);
    EXPECT_EQ(back.k, 2.0);
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        const ClusterNode& a = tree.nodes[i];
        const ClusterNode& b = back.nodes[i];
        EXPECT_EQ(a.parent, b.parent);
        EXPECT_EQ(a.children, b.children);
        EXPECT_EQ(a.instance, b.instance);
        EXPECT_EQ(a.box.min, b.box.min);
        EXPECT_EQ(a.box.max, b.box.max);
        EXPECT_EQ(a.sphere.center, b.sphere.center);
        EXPECT_EQ(a.sphere.radius, b.sphere.radius);
        EXPECT_EQ(a.fill, b.fill);
        EXPECT_EQ(a.cost, b.cost);
        EXPECT_EQ(a.level, b.level);
        EXPECT_EQ(a.locked, b.locked);
    }
    EXPECT_EQ(writeClusterTreeBinary(back), bytes);
}

TEST(ClusterTreeBinary, DamagedBytesAreRefusedNamingTheFile) {
    const Scene scene = makeSampleScene();
    const std::string bytes = writeClusterTreeBinary(buildClusterTree(scene, ClusterParams{}));
    EXPECT_EQ(
        test::problemOf([&] { readClusterTreeBinary(bytes.substr(0, bytes.size() / 2), "t.bin"); }),
        "t.bin: cluster tree data is truncated");
    EXPECT_EQ(test::problemOf([&] { readClusterTreeBinary("nonsense", "t.bin"); }),
              "t.bin: cluster tree data is not a cluster tree (bad magic)");
    EXPECT_EQ(test::problemOf([&] { readClusterTreeBinary(bytes + "x", "t.bin"); }),
              "t.bin: cluster tree data is followed by trailing bytes");
    // A child id pointing at the root: the links no longer make a tree.
    ClusterTree tree = buildClusterTree(scene, ClusterParams{});
    const Id inner = tree.nodes[tree.root].children.front();
    tree.nodes[tree.root].children.front() = tree.root;
    EXPECT_NE(test::problemOf([&] {
                  readClusterTreeBinary(writeClusterTreeBinary(tree), "t.bin");
              }).find("inconsistent"),
              std::string::npos);
    (void)inner;
}
