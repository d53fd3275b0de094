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
        std::make_unique<MergeClusters>(doc.clusterNode(), std::vector<InstanceSet>{{0}, {5}}));
    for (const auto& [volume, k] : std::vector<std::pair<std::string, double>>{
             {"aabb", 0.0}, {"aabb", 2.0}, {"sphere", 1.0}, {"octree", 1.0}}) {
        doc.execute(std::make_unique<SetParameter>(doc.clusterNode(), "volume", volume));
        doc.execute(std::make_unique<SetParameter>(doc.clusterNode(), "k", k));
        const ClusterTree& t = tree();
        ASSERT_EQ(validateClusterTree(t, 7), "") << volume;
        const Id g = findCluster(t, {0, 5});
        ASSERT_NE(g, kNoId) << volume << " k=" << k;
        EXPECT_TRUE(t.nodes[g].locked);
    }
}

TEST_F(HandEditRerun, SplitHoldsAfterARerunWithNewParameters) {
    tree();
    doc.execute(std::make_unique<SplitCluster>(doc.clusterNode(), InstanceSet{0, 1, 2}));
    doc.execute(std::make_unique<SetParameter>(doc.clusterNode(), "max_children", 4));
    const ClusterTree& t = tree();
    ASSERT_EQ(validateClusterTree(t, 7), "");
    EXPECT_EQ(findCluster(t, {0, 1, 2}), kNoId); // dissolved again in the new tree
    EXPECT_EQ(t.nodes[0].parent, findCluster(t, {0, 1, 2, 3, 4}));
}

TEST_F(HandEditRerun, ExcludedAndMovedInstancesKeepTheirPlace) {
    doc.execute(std::make_unique<ExcludeInstance>(doc.clusterNode(), InstanceSet{1}));
    doc.execute(std::make_unique<MoveToCluster>(doc.clusterNode(), std::vector<InstanceSet>{{2}},
                                                InstanceSet{5, 6}));
    doc.execute(std::make_unique<SetParameter>(doc.clusterNode(), "k", 1.0));
    const ClusterTree& t = tree();
    ASSERT_EQ(validateClusterTree(t, 7), "");
    EXPECT_EQ(t.nodes[1].parent, t.root);
    EXPECT_NE(findCluster(t, {2, 5, 6}), kNoId);
}

TEST_F(HandEditRerun, OnlyTheEditedClustersAndTheirAncestorsAreRebaked) {
    EXPECT_EQ(bake().baked, 5u);
    // Merging DE and FG: the locked group is clustered on its own into DE, FG and {DE, FG};
    // DE and FG keep their content (reused), {DE, FG} is new. The rest are A, B, C and the
    // group: the level budget is now the median partner cost 2 (A-B, B-A, C-B), so AB forms
    // first and C joins one level up (LevelMergerTest's rule), then the root: AB, {AB, C} and
    // the root are new. 6 inner nodes: 4 baked, 2 reused.
    doc.execute(std::make_unique<MergeClusters>(doc.clusterNode(),
                                                std::vector<InstanceSet>{{3, 4}, {5, 6}}));
    const BakeResult& merged = bake();
    EXPECT_EQ(merged.innerNodes, 6u);
    EXPECT_EQ(merged.baked, 4u);
    EXPECT_EQ(merged.reused, 2u);
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
    doc.execute(std::make_unique<SplitCluster>(doc.clusterNode(), InstanceSet{0, 1, 2}));
    const BakeResult& split = bake();
    EXPECT_EQ(split.innerNodes, 4u);
    EXPECT_EQ(split.baked, 2u);
    EXPECT_EQ(split.reused, 2u);
}

} // namespace
} // namespace hlod
