// The "split" hand edit applied to a freshly clustered tree: a node whose leaf set is one of
// HandEdits::dissolved is removed and its children hang from its parent instead (the parent
// may then exceed maxChildren, as the root with excluded leaves does: a hand edit wins).
//
// Kept: leaf ids (= instance ids), the relative order of the remaining nodes (children before
// parents, so ids still grow toward the root), boxes and spheres (a parent's leaves do not
// change); children lists stay in ascending id order. Recomputed: levels. Never dissolved: the
// root (nothing to hang the children from), leaves, locked nodes (a lock wins over a split).
#pragma once

#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/graph/HandEdits.h"

namespace hlod {

// Returns the tree with every matching node dissolved (the input when none matches).
ClusterTree splitClusters(ClusterTree tree, const std::vector<InstanceSet>& dissolved);

} // namespace hlod
