// Dissolving levels that grow too little, see LevelGrowth.h.
#include "pipeline/cluster/LevelGrowth.h"

#include <utility>

#include "pipeline/cluster/DissolveNodes.h"

namespace hlod {

namespace {

double diameterOf(const ClusterNode& n) {
    return n.sphere.radius > 0.0 ? 2.0 * n.sphere.radius : n.box.diagonal();
}

} // namespace

ClusterTree coarsenLevels(const ClusterTree& tree, double minGrowth) {
    if (!(minGrowth > 1.0) || tree.root == kNoId) return tree;
    std::vector<char> remove(tree.nodes.size(), 0);
    bool any = false;
    // (node, its nearest kept ancestor)
    std::vector<std::pair<Id, Id>> stack{{tree.root, kNoId}};
    while (!stack.empty()) {
        const auto [id, kept] = stack.back();
        stack.pop_back();
        const ClusterNode& n = tree.nodes[id];
        if (n.isLeaf()) continue;
        const bool dissolve = kept != kNoId && !n.locked &&
                              diameterOf(tree.nodes[kept]) < minGrowth * diameterOf(n);
        if (dissolve) remove[id] = 1, any = true;
        for (Id c : n.children)
            stack.emplace_back(c, dissolve ? kept : id);
    }
    return any ? dissolveNodes(tree, remove).tree : tree;
}

} // namespace hlod
