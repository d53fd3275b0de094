// Removing inner nodes from a cluster tree, see DissolveNodes.h.
#include "pipeline/cluster/DissolveNodes.h"

#include <algorithm>

namespace hlod {

void recomputeLevels(ClusterTree& tree) {
    if (tree.root == kNoId) return;
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

DissolvedTree dissolveNodes(const ClusterTree& tree, const std::vector<char>& removeIn) {
    DissolvedTree out;
    const std::size_t n = tree.nodes.size();
    std::vector<char> remove(n, 0);
    for (Id i = 0; i < n && i < removeIn.size(); ++i)
        remove[i] = removeIn[i] && i != tree.root && !tree.nodes[i].isLeaf();
    // The nearest surviving ancestor adopts the children of removed nodes.
    auto keptParent = [&](Id id) {
        Id p = tree.nodes[id].parent;
        while (p != kNoId && remove[p])
            p = tree.nodes[p].parent;
        return p;
    };
    out.newId.assign(n, kNoId);
    Id next = 0;
    for (Id i = 0; i < n; ++i) {
        if (!remove[i]) out.newId[i] = next++;
    }
    ClusterTree& t = out.tree;
    t.volume = tree.volume;
    t.k = tree.k;
    t.root = tree.root == kNoId ? kNoId : out.newId[tree.root];
    t.nodes.resize(next);
    for (Id i = 0; i < n; ++i) {
        if (remove[i]) continue;
        ClusterNode node = tree.nodes[i];
        node.children.clear();
        const Id p = node.parent == kNoId ? kNoId : keptParent(i);
        node.parent = p == kNoId ? kNoId : out.newId[p];
        t.nodes[out.newId[i]] = std::move(node);
    }
    for (Id i = 0; i < n; ++i) {
        if (remove[i] || i == tree.root || tree.nodes[i].parent == kNoId) continue;
        t.nodes[t.nodes[out.newId[i]].parent].children.push_back(out.newId[i]);
    }
    // Children were appended in ascending old id order, which is ascending new id order.
    recomputeLevels(t);
    return out;
}

} // namespace hlod
