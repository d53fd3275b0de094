// Read-only views of a ClusterTree for inspection tools (the editor's cluster colouring, its
// cluster tree panel and its HLOD preview tint): the cut of the tree at a level, the cluster of
// every instance at that level, node depths and the leaves below a node.
//
// "The clusters at level L" (thesis fig. 4.x shows the levels of a hierarchy): levels grow by at
// least one from child to parent, so the nodes with level <= L whose parent has level > L (or
// that are the root) form a cut: every leaf lies below exactly one of them. L = 0 gives the
// leaves, L >= height gives the root alone.
// Contracts: functions take a valid tree (validateClusterTree); ids are ClusterTree node ids.
// An empty tree (root == kNoId) gives empty results. Nothing here throws.
#pragma once

#include <cstdint>
#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/scene/Scene.h"

namespace hlod {

// The cut at `level`, sorted by node id. Negative levels are treated as 0.
std::vector<Id> nodesAtLevel(const ClusterTree& tree, int level);

// For every scene instance (index = instance id, size = instanceCount), the index into `cut`
// of the cut node above its leaf; -1 for instances no leaf references.
std::vector<int> clusterOfInstances(const ClusterTree& tree, const std::vector<Id>& cut,
                                    std::size_t instanceCount);

// Edges from the root for every node (root 0).
std::vector<int> nodeDepths(const ClusterTree& tree);

// The instances of the leaves below `node` (itself when it is a leaf), in depth-first child
// order. Empty for kNoId or an id out of range.
std::vector<Id> instancesBelow(const ClusterTree& tree, Id node);

// The leaf that holds `instance`, kNoId when none does.
Id leafOfInstance(const ClusterTree& tree, Id instance);

// True when `node` is `ancestor` or lies below it.
bool isInSubtree(const ClusterTree& tree, Id node, Id ancestor);

} // namespace hlod
