// Hand edits change the automatic tree only locally (pipeline/cluster/LocalConstraints.h,
// issue 20): every cluster outside the edited subtree is unchanged, node for node.
#include <gtest/gtest.h>

#include <algorithm>
#include <iterator>
#include <map>
#include <set>

#include "HandScenes.h"
#include "RandomScenes.h"
#include "pipeline/cluster/Cluster.h"
#include "pipeline/cluster/ClusterValidate.h"

namespace hlod {
namespace {

using Set = std::vector<Id>;

// Every cluster of a tree by its leaf set: children (as leaf sets), fill, cost, locked.
struct Shape {
    std::set<Set> children;
    double fill = 0.0;
    double cost = 0.0;
    bool locked = false;
    bool operator==(const Shape&) const = default;
};

std::map<Set, Shape> shapes(const ClusterTree& t) {
    std::map<Set, Shape> out;
    for (Id n = 0; n < t.nodes.size(); ++n) {
        if (t.nodes[n].isLeaf()) continue;
        Shape s{{}, t.nodes[n].fill, t.nodes[n].cost, t.nodes[n].locked};
        for (Id c : t.nodes[n].children)
            s.children.insert(test::leavesBelow(t, c));
        out[test::leavesBelow(t, n)] = s;
    }
    return out;
}

// Leaf sets of `node` and all its ancestors.
std::set<Set> pathToRoot(const ClusterTree& t, Id node) {
    std::set<Set> out;
    for (Id n = node; n != kNoId; n = t.nodes[n].parent)
        out.insert(test::leavesBelow(t, n));
    return out;
}

// `set` without the leaves in `moved` (both sorted).
Set minus(const Set& set, const Set& moved) {
    Set out;
    std::set_difference(set.begin(), set.end(), moved.begin(), moved.end(),
                        std::back_inserter(out));
    return out;
}

// The clusters an edit may touch: in the edited tree, `node` and its ancestors; in the
// automatic tree, the ancestors of where the `moved` leaves were (`from`: their old parents),
// and those same clusters without the moved leaves in the edited tree.
struct Allowed {
    std::set<Set> before, after;
};

Allowed allowedFor(const ClusterTree& before, const ClusterTree& after, Id node,
                   const std::vector<Id>& from, const Set& moved) {
    Allowed a;
    a.after = pathToRoot(after, node);
    for (Id f : from)
        for (const Set& s : pathToRoot(before, f)) {
            a.before.insert(s);
            a.after.insert(minus(s, moved));
        }
    return a;
}

// Every cluster of `after` that is new or differs from its namesake in `before` (other
// children, fill or cost) must be allowed; so must every cluster of `before` that is gone.
void expectOnlyChanged(const ClusterTree& before, const ClusterTree& after, const Allowed& ok) {
    const auto a = shapes(before);
    const auto b = shapes(after);
    std::size_t same = 0;
    for (const auto& [set, shape] : b) {
        const auto it = a.find(set);
        Shape unlocked = shape;
        unlocked.locked = false;
        if (it != a.end() && it->second == unlocked) {
            ++same;
            continue;
        }
        EXPECT_TRUE(ok.after.count(set)) << "changed cluster of " << set.size() << " leaves";
    }
    for (const auto& [set, shape] : a) {
        if (!b.count(set)) {
            EXPECT_TRUE(ok.before.count(set)) << "lost cluster of " << set.size() << " leaves";
        }
    }
    // Most of the tree is untouched (a 300-instance tree has dozens of clusters).
    EXPECT_GE(2 * same, a.size());
}

Scene randomScene() {
    test::RandomSceneOptions o;
    o.instances = 300;
    o.layout = test::Layout::Clumped;
    o.seed = 20;
    return test::makeRandomScene(o);
}

// The first cluster (by id, not the root) with exactly `children` children of which at least
// `clusters` are clusters themselves.
Id clusterWith(const ClusterTree& t, std::size_t children, std::size_t clusters) {
    for (Id n = 0; n < t.nodes.size(); ++n) {
        const auto& c = t.nodes[n].children;
        const auto inner =
            std::count_if(c.begin(), c.end(), [&](Id x) { return !t.nodes[x].isLeaf(); });
        if (n != t.root && c.size() == children && std::size_t(inner) >= clusters) return n;
    }
    return kNoId;
}

TEST(LocalConstraints, LockingTheOnlyTwoChildrenOfAClusterChangesNothingButTheLock) {
    // A merge of the only two children of C names exactly C's leaves: the tree already holds
    // that cluster, so it is only marked locked (issue 20: the engine went from height 10 and
    // 188 nodes to 12 and 201).
    const Scene scene = randomScene();
    for (VolumeType v : {VolumeType::Sphere, VolumeType::Aabb, VolumeType::Octree}) {
        ClusterParams p;
        p.volume = v;
        const ClusterTree automatic = buildClusterTree(scene, p);
        const Id c = clusterWith(automatic, 2, 0);
        ASSERT_NE(c, kNoId) << toString(v);
        p.lockedGroups = {test::leavesBelow(automatic, c)};
        const ClusterTree edited = buildClusterTree(scene, p);
        ASSERT_EQ(validateClusterTree(edited, scene.instances.size()), "") << toString(v);
        EXPECT_EQ(edited.height(), automatic.height()) << toString(v);
        ASSERT_EQ(edited.nodes.size(), automatic.nodes.size()) << toString(v);
        for (Id n = 0; n < edited.nodes.size(); ++n) {
            EXPECT_EQ(edited.nodes[n].children, automatic.nodes[n].children) << n;
            EXPECT_EQ(edited.nodes[n].cost, automatic.nodes[n].cost) << n;
            EXPECT_EQ(edited.nodes[n].locked, n == c) << n;
        }
    }
}

TEST(LocalConstraints, MergingTwoClustersMakesANewClusterOverThemAndTouchesOnlyAncestors) {
    const Scene scene = randomScene();
    ClusterParams p;
    const ClusterTree automatic = buildClusterTree(scene, p);
    // Two clusters with different parents, neither inside the other.
    const Id a = clusterWith(automatic, 3, 0);
    ASSERT_NE(a, kNoId);
    const Set aSet = test::leavesBelow(automatic, a);
    Id b = kNoId;
    for (Id n = a + 1; n < automatic.nodes.size() && b == kNoId; ++n) {
        const Set nSet = test::leavesBelow(automatic, n);
        if (!automatic.nodes[n].isLeaf() && n != automatic.root &&
            automatic.nodes[n].parent != automatic.nodes[a].parent && minus(nSet, aSet) == nSet &&
            minus(aSet, nSet) == aSet)
            b = n;
    }
    ASSERT_NE(b, kNoId);
    const Set bSet = test::leavesBelow(automatic, b);
    Set group = aSet;
    group.insert(group.end(), bSet.begin(), bSet.end());
    std::sort(group.begin(), group.end());
    p.lockedGroups = {group};
    const ClusterTree edited = buildClusterTree(scene, p);
    ASSERT_EQ(validateClusterTree(edited, scene.instances.size()), "");

    // The new cluster holds exactly the two merged clusters, unchanged.
    Id merged = kNoId;
    for (Id n = 0; n < edited.nodes.size(); ++n)
        if (!edited.nodes[n].isLeaf() && test::leavesBelow(edited, n) == group) merged = n;
    ASSERT_NE(merged, kNoId);
    EXPECT_TRUE(edited.nodes[merged].locked);
    std::set<Set> children;
    for (Id c : edited.nodes[merged].children)
        children.insert(test::leavesBelow(edited, c));
    EXPECT_EQ(children, (std::set<Set>{aSet, bSet}));
    expectOnlyChanged(automatic, edited,
                      allowedFor(automatic, edited, merged,
                                 {automatic.nodes[a].parent, automatic.nodes[b].parent}, group));
}

TEST(LocalConstraints, MovedMeshesJoinTheTargetClusterAndNothingElseMoves) {
    // moveToCluster locks target + items; with one cluster among the fragments the meshes
    // become its extra children.
    const Scene scene = randomScene();
    ClusterParams p;
    const ClusterTree automatic = buildClusterTree(scene, p);
    const Id target = clusterWith(automatic, 3, 0);
    ASSERT_NE(target, kNoId);
    Set group = test::leavesBelow(automatic, target);
    // Two meshes from elsewhere: the first leaves not below the target's parent.
    const Set parentSet = test::leavesBelow(automatic, automatic.nodes[target].parent);
    Set items;
    for (Id i = 0; i < scene.instances.size() && items.size() < 2; ++i)
        if (!std::binary_search(parentSet.begin(), parentSet.end(), i)) items.push_back(i);
    ASSERT_EQ(items.size(), 2u);
    group.insert(group.end(), items.begin(), items.end());
    std::sort(group.begin(), group.end());
    p.lockedGroups = {group};
    const ClusterTree edited = buildClusterTree(scene, p);
    ASSERT_EQ(validateClusterTree(edited, scene.instances.size()), "");

    const Id joined = edited.nodes[items[0]].parent;
    EXPECT_EQ(test::leavesBelow(edited, joined), group);
    EXPECT_TRUE(edited.nodes[joined].locked);
    EXPECT_EQ(edited.nodes[items[1]].parent, joined);
    // The target's own children are still there, next to the two meshes.
    EXPECT_EQ(edited.nodes[joined].children.size(), automatic.nodes[target].children.size() + 2);
    expectOnlyChanged(
        automatic, edited,
        allowedFor(automatic, edited, joined,
                   {automatic.nodes[items[0]].parent, automatic.nodes[items[1]].parent, target},
                   items));
}

TEST(LocalConstraints, AnExcludedMeshLeavesOnlyItsAncestorsChanged) {
    const Scene scene = randomScene();
    ClusterParams p;
    const ClusterTree automatic = buildClusterTree(scene, p);
    p.excluded = {42};
    const ClusterTree edited = buildClusterTree(scene, p);
    ASSERT_EQ(validateClusterTree(edited, scene.instances.size()), "");
    EXPECT_EQ(edited.nodes[42].parent, edited.root);
    // The new root holds the excluded mesh and the rest of the tree.
    ASSERT_EQ(edited.nodes[edited.root].children.size(), 2u);
    expectOnlyChanged(
        automatic, edited,
        allowedFor(automatic, edited, edited.root, {automatic.nodes[42].parent}, {42}));
}

TEST(LocalConstraints, AClusterLeftWithOneChildIsReplacedByThatChild) {
    // Seven cubes, AABB k = 0: ABC {0,1,2}, DE {3,4}, FG {5,6}, {ABC, DE}, root {., FG}
    // (LevelMergerTest). Excluding D leaves DE with E alone: E takes DE's place.
    const Scene scene = test::cubesAt(
        {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {100, 0, 0}, {102, 0, 0}, {200, 0, 0}, {202, 0, 0}});
    ClusterParams p;
    p.volume = VolumeType::Aabb;
    p.k = 0.0;
    const ClusterTree automatic = buildClusterTree(scene, p);
    ASSERT_EQ(automatic.nodes.size(), 12u);
    p.excluded = {3};
    const ClusterTree edited = buildClusterTree(scene, p);
    ASSERT_EQ(validateClusterTree(edited, 7), "");
    // 7 leaves, ABC, {ABC, E}, FG, the old root and the new root over it and D.
    EXPECT_EQ(edited.nodes.size(), 12u);
    EXPECT_EQ(edited.nodes[3].parent, edited.root);
    const Id abce = edited.nodes[4].parent;
    EXPECT_EQ(test::leavesBelow(edited, abce), (std::vector<Id>{0, 1, 2, 4}));
    EXPECT_EQ(test::leavesBelow(edited, edited.nodes[0].parent), (std::vector<Id>{0, 1, 2}));
}

} // namespace
} // namespace hlod
