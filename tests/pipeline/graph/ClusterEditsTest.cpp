// Cluster hand edits as constraints (pipeline/graph/ClusterEdits.h) and the split of a rebuilt
// tree (SplitClusters.h), on the seven cubes of LevelMergerTest (AABB, k = 0): ABC = node 7
// {0,1,2}, DE = 8 {3,4}, FG = 9 {5,6}, 10 = {ABC, DE}, root 11 = {10, FG}.
#include <gtest/gtest.h>

#include "cluster/HandScenes.h"
#include "pipeline/cluster/ClusterValidate.h"
#include "pipeline/core/Error.h"
#include "pipeline/graph/ClusterEdits.h"
#include "pipeline/graph/SplitClusters.h"

namespace hlod {
namespace {

Scene sevenCubes() {
    return test::cubesAt(
        {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {100, 0, 0}, {102, 0, 0}, {200, 0, 0}, {202, 0, 0}});
}

ClusterTree clustered(const HandEdits& e) {
    ClusterParams p;
    p.volume = VolumeType::Aabb;
    p.k = 0.0;
    applyConstraints(e, p);
    return splitClusters(buildClusterTree(sevenCubes(), p), e.dissolved);
}

ErrorCode codeOf(const std::function<void()>& f) {
    try {
        f();
    } catch (const Error& e) {
        return e.code();
    }
    return ErrorCode::Io; // "no error" never expected here
}

TEST(ClusterEdits, FindClusterNamesNodesByLeafSet) {
    const ClusterTree t = clustered({});
    EXPECT_EQ(findCluster(t, {0, 1, 2}), 7u);
    EXPECT_EQ(findCluster(t, {3, 4}), 8u);
    EXPECT_EQ(findCluster(t, {0, 1, 2, 3, 4}), 10u);
    EXPECT_EQ(findCluster(t, {0, 1}), kNoId); // A and B share no node of their own
    EXPECT_EQ(leafSet(t, t.root), (InstanceSet{0, 1, 2, 3, 4, 5, 6}));
}

TEST(ClusterEdits, MergeMakesOneLockedGroupTakingMembersFromOthers) {
    HandEdits e;
    e.locked = {{3, 4}};
    e.excluded = {5};
    // Merge {4} (out of DE), {5} (excluded) and {0}: one group; DE shrinks to {3}.
    const HandEdits m = mergeClusters(e, {{4}, {5}, {0}});
    EXPECT_EQ(m.locked, (std::vector<InstanceSet>{{0, 4, 5}, {3}}));
    EXPECT_TRUE(m.excluded.empty());
    EXPECT_EQ(codeOf([&] { mergeClusters(e, {{1}}); }), ErrorCode::InvalidArgument);
    EXPECT_EQ(codeOf([&] { mergeClusters(e, {{0, 1}, {1}}); }), ErrorCode::InvalidArgument);
}

TEST(ClusterEdits, SplitDissolvesTheClusterIntoItsParent) {
    const ClusterTree before = clustered({});
    const HandEdits e = splitCluster({}, before, {0, 1, 2});
    EXPECT_EQ(e.dissolved, (std::vector<InstanceSet>{{0, 1, 2}}));
    const ClusterTree t = clustered(e);
    ASSERT_EQ(validateClusterTree(t, 7), "");
    // ABC is gone: A, B, C hang from {ABC, DE}, which keeps DE as its fourth child.
    EXPECT_EQ(t.nodes.size(), 11u);
    const Id parent = findCluster(t, {0, 1, 2, 3, 4});
    ASSERT_NE(parent, kNoId);
    EXPECT_EQ(t.nodes[parent].children.size(), 4u);
    EXPECT_EQ(t.nodes[0].parent, parent);
    EXPECT_EQ(t.nodes[parent].level, 2); // 1 + level of DE
    EXPECT_EQ(codeOf([&] {
                  splitCluster({}, before, {0, 1, 2, 3, 4, 5, 6});
              }),
              ErrorCode::InvalidArgument); // the root
    EXPECT_EQ(codeOf([&] { splitCluster({}, before, {3}); }), ErrorCode::InvalidArgument);
}

TEST(ClusterEdits, SplittingALockedClusterLocksItsInnerChildren) {
    HandEdits e;
    e.locked = {{0, 1, 2, 3, 4}};
    const ClusterTree t = clustered(e);
    const HandEdits s = splitCluster(e, t, {0, 1, 2, 3, 4});
    // Its children are ABC and DE (both inner): each stays whole.
    EXPECT_EQ(s.locked, (std::vector<InstanceSet>{{0, 1, 2}, {3, 4}}));
    EXPECT_EQ(s.dissolved, (std::vector<InstanceSet>{{0, 1, 2, 3, 4}}));
}

TEST(ClusterEdits, MoveAddsItemsToTheTargetAsALockedGroup) {
    const HandEdits m = moveToCluster({}, {{2}}, {3, 4});
    EXPECT_EQ(m.locked, (std::vector<InstanceSet>{{2, 3, 4}}));
    const ClusterTree t = clustered(m);
    ASSERT_EQ(validateClusterTree(t, 7), "");
    const Id g = findCluster(t, {2, 3, 4});
    ASSERT_NE(g, kNoId);
    EXPECT_TRUE(t.nodes[g].locked);
    // Target inside a locked group: the items join that group.
    HandEdits inside;
    inside.locked = {{3, 4, 5, 6}};
    EXPECT_EQ(moveToCluster(inside, {{0}}, {3, 4}).locked,
              (std::vector<InstanceSet>{{0, 3, 4, 5, 6}}));
    EXPECT_EQ(codeOf([] {
                  moveToCluster({}, {{0, 1, 2, 3, 4}}, {3, 4});
              }),
              ErrorCode::InvalidArgument); // into its own part
}

TEST(ClusterEdits, LockUnlockExcludeInclude) {
    HandEdits e = lockCluster({}, {3, 4});
    EXPECT_EQ(e.locked, (std::vector<InstanceSet>{{3, 4}}));
    EXPECT_EQ(codeOf([&] { lockCluster(e, {3, 4}); }), ErrorCode::InvalidArgument);
    EXPECT_EQ(codeOf([&] { lockCluster(e, {3}); }), ErrorCode::InvalidArgument);
    e = excludeInstances(e, {4, 6});
    EXPECT_EQ(e.locked, (std::vector<InstanceSet>{{3}}));
    EXPECT_EQ(e.excluded, (InstanceSet{4, 6}));
    e = includeInstances(e, {6});
    EXPECT_EQ(e.excluded, (InstanceSet{4}));
    EXPECT_EQ(codeOf([&] { includeInstances(e, {6}); }), ErrorCode::InvalidArgument);
    e = unlockCluster(e, {3});
    EXPECT_TRUE(e.locked.empty());
    EXPECT_EQ(codeOf([&] { unlockCluster(e, {3}); }), ErrorCode::InvalidArgument);
}

TEST(ClusterEdits, ValidationRefusesIdsOfAnotherScene) {
    HandEdits e;
    e.excluded = {9};
    EXPECT_EQ(codeOf([&] { validateHandEdits(e, 7); }), ErrorCode::InvalidArgument);
    e.excluded = {6};
    EXPECT_NO_THROW(validateHandEdits(e, 7));
}

} // namespace
} // namespace hlod
