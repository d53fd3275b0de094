// Hand-edit constraints: locked groups kept whole, excluded instances as root leaves
// (pipeline/cluster/ClusterDriver.h).
#include <gtest/gtest.h>

#include "HandScenes.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterValidate.h"
#include "pipeline/core/Error.h"

namespace hlod {
namespace {

// The seven cubes of LevelMergerTest: a row of three and two far pairs.
Scene sevenCubes() {
    return test::cubesAt(
        {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {100, 0, 0}, {102, 0, 0}, {200, 0, 0}, {202, 0, 0}});
}

Id lockedNode(const ClusterTree& t) {
    Id found = kNoId;
    for (Id i = 0; i < t.nodes.size(); ++i) {
        if (t.nodes[i].locked) {
            EXPECT_EQ(found, kNoId) << "more than one locked node";
            found = i;
        }
    }
    return found;
}

TEST(ClusterConstraints, LockedGroupStaysWholeEvenWhenFarApart) {
    // A (x = 0) and F (x = 200) would never pair on cost; locked, they form one subtree that
    // holds exactly these two leaves, for every clusterer.
    for (VolumeType v :
         {VolumeType::Sphere, VolumeType::Aabb, VolumeType::Octree, VolumeType::Original}) {
        ClusterParams p;
        p.volume = v;
        p.lockedGroups = {{5, 0}};
        const ClusterTree t = buildClusterTree(sevenCubes(), p);
        ASSERT_EQ(validateClusterTree(t, 7), "") << toString(v);
        const Id locked = lockedNode(t);
        ASSERT_NE(locked, kNoId) << toString(v);
        EXPECT_EQ(test::leavesBelow(t, locked), (std::vector<Id>{0, 5})) << toString(v);
    }
}

TEST(ClusterConstraints, LockedGroupOfOneIsALockedLeaf) {
    ClusterParams p;
    p.lockedGroups = {{3}};
    const ClusterTree t = buildClusterTree(sevenCubes(), p);
    EXPECT_EQ(lockedNode(t), 3u);
    EXPECT_TRUE(t.nodes[3].isLeaf());
}

TEST(ClusterConstraints, ExcludedInstancesHangFromTheRoot) {
    // B sits in the middle of the row but, excluded, is never merged: it is a direct leaf
    // child of the root, beside the clustered rest.
    for (VolumeType v :
         {VolumeType::Sphere, VolumeType::Aabb, VolumeType::Octree, VolumeType::Original}) {
        ClusterParams p;
        p.volume = v;
        p.excluded = {1, 4};
        const ClusterTree t = buildClusterTree(sevenCubes(), p);
        ASSERT_EQ(validateClusterTree(t, 7), "") << toString(v);
        EXPECT_EQ(t.nodes[1].parent, t.root) << toString(v);
        EXPECT_EQ(t.nodes[4].parent, t.root) << toString(v);
        // Root = {1, 4, clustered rest}.
        ASSERT_EQ(t.nodes[t.root].children.size(), 3u) << toString(v);
        EXPECT_EQ(test::leavesBelow(t, t.nodes[t.root].children[2]),
                  (std::vector<Id>{0, 2, 3, 5, 6}));
    }
}

TEST(ClusterConstraints, EverythingExcludedGivesAFlatRoot) {
    ClusterParams p;
    p.excluded = {0, 1, 2};
    const ClusterTree t = buildClusterTree(test::cubesAt({{0, 0, 0}, {5, 0, 0}, {9, 0, 0}}), p);
    ASSERT_EQ(t.nodes.size(), 4u);
    EXPECT_EQ(t.nodes[t.root].children, (std::vector<Id>{0, 1, 2}));
    EXPECT_EQ(validateClusterTree(t, 3), "");
}

TEST(ClusterConstraints, RejectsContradictions) {
    const Scene s = sevenCubes();
    auto expectInvalid = [&](const ClusterParams& p) {
        try {
            buildClusterTree(s, p);
            ADD_FAILURE() << "expected InvalidArgument";
        } catch (const Error& e) {
            EXPECT_EQ(e.code(), ErrorCode::InvalidArgument);
        }
    };
    ClusterParams p;
    p.lockedGroups = {{0, 1}, {1, 2}}; // instance 1 twice
    expectInvalid(p);
    p = {};
    p.lockedGroups = {{0, 1}};
    p.excluded = {1}; // locked and excluded
    expectInvalid(p);
    p = {};
    p.excluded = {7}; // out of range
    expectInvalid(p);
    p = {};
    p.lockedGroups = {{}}; // empty
    expectInvalid(p);
}

} // namespace
} // namespace hlod
