// Hand edits are constraints that survive a rerun with other parameters, and after an edit
// only the proxies of what changed are baked again (pipeline/doc/Commands.h). The scene is the
// seven cubes (DocumentFixture.h); with AABB and k = 0 its five inner nodes are ABC {0,1,2},
// DE {3,4}, FG {5,6}, {ABC, DE} and the root.
#include <gtest/gtest.h>

#include "DocumentFixture.h"
#include "pipeline/cluster/ClusterValidate.h"
#include "pipeline/doc/Commands.h"

namespace hlod {
namespace {

using HandEditRerun = test::DocumentFixture;

TEST_F(HandEditRerun, MergedClusterStaysOneLockedSubtreeWhenKAndVolumeChange) {
    // A (x = 0) and F (x = 200) never pair on cost; merged by hand they must stay one subtree.
    doc.execute(
        std::make_unique<MergeClusters>(kDefaultCluster, std::vector<InstanceSet>{{0}, {5}}));
    for (const auto& [volume, k] : std::vector<std::pair<std::string, double>>{
             {"aabb", 0.0}, {"aabb", 2.0}, {"sphere", 1.0}, {"octree", 1.0}}) {
        doc.execute(std::make_unique<SetParameter>(kDefaultCluster, "volume", volume));
        doc.execute(std::make_unique<SetParameter>(kDefaultCluster, "k", k));
        const ClusterTree& t = tree();
        ASSERT_EQ(validateClusterTree(t, 7), "") << volume;
        const Id g = findCluster(t, {0, 5});
        ASSERT_NE(g, kNoId) << volume << " k=" << k;
        EXPECT_TRUE(t.nodes[g].locked);
    }
}

TEST_F(HandEditRerun, SplitHoldsAfterARerunWithNewParameters) {
    tree();
    doc.execute(std::make_unique<SplitCluster>(kDefaultCluster, InstanceSet{0, 1, 2}));
    doc.execute(std::make_unique<SetParameter>(kDefaultCluster, "max_children", 4));
    const ClusterTree& t = tree();
    ASSERT_EQ(validateClusterTree(t, 7), "");
    EXPECT_EQ(findCluster(t, {0, 1, 2}), kNoId); // dissolved again in the new tree
    EXPECT_EQ(t.nodes[0].parent, findCluster(t, {0, 1, 2, 3, 4}));
}

TEST_F(HandEditRerun, ExcludedAndMovedInstancesKeepTheirPlace) {
    doc.execute(std::make_unique<ExcludeInstance>(kDefaultCluster, InstanceSet{1}));
    doc.execute(std::make_unique<MoveToCluster>(kDefaultCluster, std::vector<InstanceSet>{{2}},
                                                InstanceSet{5, 6}));
    doc.execute(std::make_unique<SetParameter>(kDefaultCluster, "k", 1.0));
    const ClusterTree& t = tree();
    ASSERT_EQ(validateClusterTree(t, 7), "");
    EXPECT_EQ(t.nodes[1].parent, t.root);
    EXPECT_NE(findCluster(t, {2, 5, 6}), kNoId);
}

TEST_F(HandEditRerun, OnlyTheEditedClustersAndTheirAncestorsAreRebaked) {
    // DE and FG are translated copies (two cubes 2 m apart): one bake serves both (BakeFrame.h).
    EXPECT_EQ(bake().baked, 4u);
    EXPECT_EQ(bake().reused, 1u);
    // Merging DE and FG changes the tree only there (LocalConstraints.h): DE and FG stay and a
    // locked {DE, FG} takes their place under the root. 5 inner nodes: ABC, DE, FG, {DE, FG}
    // and the root; {DE, FG} and the root are new, ABC, DE and FG come from the cache.
    doc.execute(
        std::make_unique<MergeClusters>(kDefaultCluster, std::vector<InstanceSet>{{3, 4}, {5, 6}}));
    const BakeResult& merged = bake();
    EXPECT_EQ(merged.innerNodes, 5u);
    EXPECT_EQ(merged.baked, 2u);
    EXPECT_EQ(merged.reused, 3u);
    EXPECT_TRUE(merged.nodes[findCluster(tree(), {3, 4})].reused);
    EXPECT_FALSE(merged.nodes[findCluster(tree(), {3, 4, 5, 6})].reused);
    // Undo brings the original tree back: every proxy is in the cache.
    doc.undo();
    const BakeResult& undone = bake();
    EXPECT_EQ(undone.baked, 0u);
    EXPECT_EQ(undone.reused, 5u);
    // Splitting ABC: {ABC, DE} now holds A, B, C and DE, so it and the root are rebaked; DE and
    // FG are reused; ABC is gone (4 inner nodes).
    tree();
    doc.execute(std::make_unique<SplitCluster>(kDefaultCluster, InstanceSet{0, 1, 2}));
    const BakeResult& split = bake();
    EXPECT_EQ(split.innerNodes, 4u);
    EXPECT_EQ(split.baked, 2u);
    EXPECT_EQ(split.reused, 2u);
}

} // namespace
} // namespace hlod
