// Dissolving split clusters in a rebuilt tree (see SplitClusters.h).
#include "pipeline/graph/SplitClusters.h"

#include <algorithm>

namespace hlod {

namespace {

// Leaf sets of every node, bottom-up (children have smaller ids than their parents).
std::vector<InstanceSet> allLeafSets(const ClusterTree& tree) {
    std::vector<InstanceSet> sets(tree.nodes.size());
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        const ClusterNode& n = tree.nodes[i];
        if (n.isLeaf()) {
            sets[i] = {n.instance};
            continue;
        }
        for (Id c : n.children)
            sets[i].insert(sets[i].end(), sets[c].begin(), sets[c].end());
        std::sort(sets[i].begin(), sets[i].end());
    }
    return sets;
}

void recomputeLevels(ClusterTree& tree) {
    // Post-order without recursion: a node's level is known once all its children are done.
    std::vector<std::pair<Id, bool>> stack{{tree.root, false}};
    while (!stack.empty()) {
        auto [id, expanded] = stack.back();
        stack.pop_back();
        ClusterNode& n = tree.nodes[id];
        if (n.isLeaf()) {
            n.level = 0;
        } else if (!expanded) {
            stack.push_back({id, true});
            for (Id c : n.children)
                stack.push_back({c, false});
        } else {
            int level = 0;
            for (Id c : n.children)
                level = std::max(level, tree.nodes[c].level + 1);
            n.level = level;
        }
    }
}

} // namespace

ClusterTree splitClusters(ClusterTree tree, const std::vector<InstanceSet>& dissolved) {
    if (dissolved.empty() || tree.root == kNoId) return tree;
    const std::vector<InstanceSet> sets = allLeafSets(tree);
    std::vector<char> remove(tree.nodes.size(), 0);
    bool any = false;
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        const ClusterNode& n = tree.nodes[i];
        if (i == tree.root || n.isLeaf() || n.locked) continue;
        if (std::binary_search(dissolved.begin(), dissolved.end(), sets[i])) {
            remove[i] = 1;
            any = true;
        }
    }
    if (!any) return tree;

    // The nearest surviving ancestor adopts the children of removed nodes.
    auto keptParent = [&](Id id) {
        Id p = tree.nodes[id].parent;
        while (p != kNoId && remove[p])
            p = tree.nodes[p].parent;
        return p;
    };
    std::vector<Id> newId(tree.nodes.size(), kNoId);
    Id next = 0;
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        if (!remove[i]) newId[i] = next++;
    }
    ClusterTree out;
    out.volume = tree.volume;
    out.k = tree.k;
    out.root = newId[tree.root];
    out.nodes.resize(next);
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        if (remove[i]) continue;
        ClusterNode n = tree.nodes[i];
        n.children.clear();
        const Id p = n.parent == kNoId ? kNoId : keptParent(i);
        n.parent = p == kNoId ? kNoId : newId[p];
        out.nodes[newId[i]] = std::move(n);
    }
    for (Id i = 0; i < tree.nodes.size(); ++i) {
        if (remove[i] || i == tree.root) continue;
        out.nodes[out.nodes[newId[i]].parent].children.push_back(newId[i]);
    }
    // Children were appended in ascending old id order, which is ascending new id order.
    recomputeLevels(out);
    return out;
}

} // namespace hlod
