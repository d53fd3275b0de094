// buildHlod (pipeline/doc/HlodBuild.h), what the editor builds with: hand edits give the same
// tree as the pipeline graph's Cluster node (what `hlod build PROJECT.hlodproj` runs), splits
// included, and a rebuild that changes only bake parameters reuses the previous tree. The scene
// is the seven cubes of DocumentFixture.h (AABB, k = 0: ABC {0,1,2}, DE {3,4}, FG {5,6},
// {ABC, DE}, root).
#include <gtest/gtest.h>

#include "DocumentFixture.h"
#include "pipeline/doc/Commands.h"
#include "pipeline/doc/HlodBuild.h"

namespace hlod {
namespace {

using HlodBuildTest = test::DocumentFixture;

HlodSettings settingsOf(const Document& doc) {
    const GraphNode& cluster = doc.graph().node(doc.clusterNode());
    HlodSettings s = hlodSettingsFrom(cluster.params, doc.graph().node(doc.bakeNode()).params);
    applyConstraints(cluster.edits, s.cluster);
    s.dissolved = cluster.edits.dissolved;
    return s;
}

// The tree of buildHlod equals the Cluster node's, node by node.
void expectSameTree(const ClusterTree& build, const ClusterTree& graph) {
    ASSERT_EQ(build.nodes.size(), graph.nodes.size());
    for (Id n = 0; n < graph.nodes.size(); ++n) {
        EXPECT_EQ(leafSet(build, n), leafSet(graph, n)) << n;
        EXPECT_EQ(build.nodes[n].locked, graph.nodes[n].locked) << n;
    }
}

TEST_F(HlodBuildTest, HandEditsGiveTheGraphsTreeSplitsIncluded) {
    tree();
    doc.execute(std::make_unique<SplitCluster>(doc.clusterNode(), InstanceSet{0, 1, 2}));
    const Scene& scene = *doc.graph().output(doc.clusterNode())->scene;
    const HlodBuild split = buildHlod(scene, settingsOf(doc));
    // ABC is dissolved: A, B and C hang from {ABC, DE}, which is now {A, B, C, DE}.
    EXPECT_EQ(findCluster(split.tree, {0, 1, 2}), kNoId);
    EXPECT_EQ(split.tree.nodes[0].parent, findCluster(split.tree, {0, 1, 2, 3, 4}));
    expectSameTree(split.tree, tree());
    EXPECT_EQ(split.bake.nodes.size(), split.tree.nodes.size());
    EXPECT_FALSE(split.treeReused);

    doc.execute(
        std::make_unique<MergeClusters>(doc.clusterNode(), std::vector<InstanceSet>{{0}, {5}}));
    const HlodBuild merged = buildHlod(scene, settingsOf(doc));
    const Id group = findCluster(merged.tree, {0, 5});
    ASSERT_NE(group, kNoId);
    EXPECT_TRUE(merged.tree.nodes[group].locked);
    expectSameTree(merged.tree, tree());
}

TEST_F(HlodBuildTest, OnlyABakeChangeReusesThePreviousTree) {
    tree();
    const Scene& scene = *doc.graph().output(doc.clusterNode())->scene;
    const HlodSettings settings = settingsOf(doc);
    const HlodBuild first = buildHlod(scene, settings);

    HlodSettings bakeOnly = settings;
    bakeOnly.bake.screen.screenSize = 600.0;
    EXPECT_TRUE(sameClustering(settings, bakeOnly));
    EXPECT_FALSE(sameBaking(settings, bakeOnly));
    const HlodBuild second = buildHlod(scene, bakeOnly, {}, &first);
    EXPECT_TRUE(second.treeReused);
    ASSERT_EQ(second.tree.nodes.size(), first.tree.nodes.size());
    for (Id n = 0; n < first.tree.nodes.size(); ++n)
        EXPECT_EQ(leafSet(second.tree, n), leafSet(first.tree, n)) << n;
    EXPECT_EQ(second.settings.bake.screen.screenSize, 600.0);

    // Any clustering change reclusters: a parameter, a lock, a split.
    HlodSettings otherK = settings;
    otherK.cluster.k = 2.0;
    EXPECT_FALSE(buildHlod(scene, otherK, {}, &first).treeReused);
    HlodSettings split = settings;
    split.dissolved = {{0, 1, 2}};
    EXPECT_FALSE(sameClustering(settings, split));
    const HlodBuild splitBuild = buildHlod(scene, split, {}, &first);
    EXPECT_FALSE(splitBuild.treeReused);
    EXPECT_EQ(findCluster(splitBuild.tree, {0, 1, 2}), kNoId);
    HlodSettings locked = settings;
    locked.cluster.lockedGroups = {{0, 5}};
    EXPECT_FALSE(sameClustering(settings, locked));
}

} // namespace
} // namespace hlod
