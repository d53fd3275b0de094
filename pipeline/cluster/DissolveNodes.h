// Removing inner nodes from a cluster tree: a removed node's children hang from its nearest
// kept ancestor. Shared by the "split" hand edit (SplitClusters.h) and the proxy economy
// (ProxyEconomy.h), which dissolve nodes for different reasons but in the same way.
//
// Kept: leaf ids (= instance ids when the clusterer numbered them so), the relative order of
// the remaining nodes (children before parents, so ids still grow toward the root), boxes,
// spheres, fill, cost and locks (a parent's leaves do not change); children lists stay in
// ascending id order. Recomputed: levels. The root and leaves are never removed (a flag on
// them is ignored).
#pragma once

#include <vector>

#include "pipeline/cluster/ClusterTree.h"

namespace hlod {

struct DissolvedTree {
    ClusterTree tree;
    std::vector<Id> newId; // per old node: its id in `tree`, kNoId when removed
};

// `remove[i]` != 0 removes node i. `remove` has one entry per node.
DissolvedTree dissolveNodes(const ClusterTree& tree, const std::vector<char>& remove);

// Levels from the children (leaves 0, inner 1 + max over children).
void recomputeLevels(ClusterTree& tree);

} // namespace hlod
