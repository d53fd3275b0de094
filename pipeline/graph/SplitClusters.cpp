// Dissolving split clusters in a rebuilt tree (see SplitClusters.h).
#include "pipeline/graph/SplitClusters.h"

#include <algorithm>

#include "pipeline/cluster/DissolveNodes.h"

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
    return dissolveNodes(tree, remove).tree;
}

} // namespace hlod
