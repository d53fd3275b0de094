// Cluster hand edits as constraint updates (see ClusterEdits.h).
#include "pipeline/graph/ClusterEdits.h"

#include <algorithm>
#include <iterator>
#include <string>

#include "pipeline/core/Error.h"

namespace hlod {

namespace {

[[noreturn]] void refuse(const std::string& why) { throw Error(ErrorCode::InvalidArgument, why); }

bool contains(const InstanceSet& outer, const InstanceSet& inner) {
    return std::includes(outer.begin(), outer.end(), inner.begin(), inner.end());
}

bool intersects(const InstanceSet& a, const InstanceSet& b) {
    auto i = a.begin();
    auto j = b.begin();
    while (i != a.end() && j != b.end()) {
        if (*i == *j) return true;
        if (*i < *j) {
            ++i;
        } else {
            ++j;
        }
    }
    return false;
}

InstanceSet minus(const InstanceSet& a, const InstanceSet& b) {
    InstanceSet out;
    std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

InstanceSet unite(const InstanceSet& a, const InstanceSet& b) {
    InstanceSet out;
    std::set_union(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(out));
    return out;
}

// The locked group that strictly contains `set`, or nullptr.
const InstanceSet* lockedAround(const HandEdits& e, const InstanceSet& set) {
    for (const InstanceSet& g : e.locked) {
        if (g.size() > set.size() && contains(g, set)) return &g;
    }
    return nullptr;
}

// `group` becomes a locked group: its members leave every other group and the exclusions; a
// split of exactly this set is dropped (a lock wins).
HandEdits withGroup(HandEdits e, const InstanceSet& group) {
    for (InstanceSet& g : e.locked)
        g = minus(g, group);
    e.excluded = minus(e.excluded, group);
    std::erase(e.dissolved, group);
    e.locked.push_back(group);
    normalize(e);
    return e;
}

InstanceSet checkedSet(const InstanceSet& ids, const char* what) {
    InstanceSet s = normalizedSet(ids);
    if (s.empty()) refuse(std::string(what) + " is empty");
    return s;
}

} // namespace

HandEdits mergeClusters(const HandEdits& edits, const std::vector<InstanceSet>& clusters) {
    InstanceSet all;
    std::vector<InstanceSet> distinct;
    for (const InstanceSet& c : clusters) {
        const InstanceSet s = checkedSet(c, "a selected cluster");
        all = unite(all, s);
        if (std::find(distinct.begin(), distinct.end(), s) == distinct.end()) distinct.push_back(s);
    }
    if (distinct.size() < 2 || all.size() < 2) refuse("select at least two clusters to merge");
    for (const InstanceSet& s : distinct) {
        if (s == all) refuse("the selected clusters already form one cluster");
    }
    if (std::find(edits.locked.begin(), edits.locked.end(), all) != edits.locked.end())
        refuse("the selected clusters already form one locked cluster");
    if (lockedAround(edits, all))
        refuse("the selected clusters lie inside a locked cluster; unlock it first");
    return withGroup(edits, all);
}

HandEdits splitCluster(const HandEdits& edits, const ClusterTree& tree,
                       const InstanceSet& cluster) {
    const InstanceSet set = checkedSet(cluster, "the cluster to split");
    const Id node = findCluster(tree, set);
    if (node == kNoId) refuse("the cluster to split is not in the current tree");
    if (node == tree.root) refuse("the root cannot be split");
    if (tree.nodes[node].isLeaf()) refuse("a single mesh cannot be split");
    HandEdits e = edits;
    const bool wasLocked = std::erase(e.locked, set) > 0;
    if (wasLocked) {
        for (Id c : tree.nodes[node].children) {
            if (!tree.nodes[c].isLeaf()) e.locked.push_back(leafSet(tree, c));
        }
    }
    e.dissolved.push_back(set);
    normalize(e);
    return e;
}

HandEdits moveToCluster(const HandEdits& edits, const std::vector<InstanceSet>& items,
                        const InstanceSet& target) {
    const InstanceSet t = checkedSet(target, "the target cluster");
    InstanceSet moved;
    for (const InstanceSet& item : items) {
        const InstanceSet s = checkedSet(item, "a moved item");
        if (contains(s, t)) refuse("a cluster cannot be moved into itself or into its own part");
        moved = unite(moved, s);
    }
    if (moved.empty()) refuse("nothing to move");
    moved = minus(moved, t);
    if (moved.empty()) refuse("the moved items are already in the target cluster");
    InstanceSet group = unite(t, moved);
    if (const InstanceSet* around = lockedAround(edits, t)) group = unite(*around, moved);
    return withGroup(edits, group);
}

HandEdits lockCluster(const HandEdits& edits, const InstanceSet& cluster) {
    const InstanceSet set = checkedSet(cluster, "the cluster to lock");
    if (std::find(edits.locked.begin(), edits.locked.end(), set) != edits.locked.end())
        refuse("the cluster is already locked");
    if (lockedAround(edits, set)) refuse("the cluster lies inside a locked cluster already");
    for (const InstanceSet& g : edits.locked) {
        if (intersects(g, set) && !contains(set, g))
            refuse("the cluster overlaps a locked cluster only in part");
    }
    return withGroup(edits, set);
}

HandEdits unlockCluster(const HandEdits& edits, const InstanceSet& cluster) {
    const InstanceSet set = normalizedSet(cluster);
    HandEdits e = edits;
    if (std::erase(e.locked, set) == 0) refuse("the cluster is not locked");
    return e;
}

HandEdits excludeInstances(const HandEdits& edits, const InstanceSet& instances) {
    const InstanceSet ids = checkedSet(instances, "the selection to exclude");
    if (contains(edits.excluded, ids)) refuse("the selection is already excluded");
    HandEdits e = edits;
    for (InstanceSet& g : e.locked)
        g = minus(g, ids);
    e.excluded = unite(e.excluded, ids);
    normalize(e);
    return e;
}

HandEdits includeInstances(const HandEdits& edits, const InstanceSet& instances) {
    const InstanceSet ids = checkedSet(instances, "the selection to include");
    if (!contains(edits.excluded, ids)) refuse("only excluded meshes can be included again");
    HandEdits e = edits;
    e.excluded = minus(e.excluded, ids);
    return e;
}

} // namespace hlod
