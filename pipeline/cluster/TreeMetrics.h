// Quality measures of a cluster tree, to compare clusterers and parameters (thesis chapter 6
// compares hierarchies by node count and by how they render; these are the structural side).
//
// - depth: edges on the longest root-to-leaf path; meanLeafDepth: average over leaves.
// - children per inner node: min, mean, max.
// - total node volume: sum over inner nodes of their sphere volumes and of their box volumes
//   (what the proxies of a tree must cover; smaller is tighter), in cubic metres.
// - mean fill: average fill factor F of the inner nodes.
// - spread of an inner node: RMS distance of its leaves' box centres from their centroid,
//   divided by the node's bounding-sphere radius. Near 0: the node's meshes sit together
//   (one compact part plus small details); near 1: they lie spread over the whole node,
//   like the four wheels of thesis figure 3.1 grouped in one subtree. Reported as mean and
//   max over inner nodes. Computed bottom-up with pairwise-combined moments (Chan et al.), so
//   the cost is linear in the tree size.
// An empty tree gives all zeros; a single leaf has depth 0 and no inner nodes.
#pragma once

#include <cstddef>

#include "pipeline/cluster/ClusterTree.h"

namespace hlod {

struct TreeMetrics {
    std::size_t nodes = 0;
    std::size_t leaves = 0;
    std::size_t innerNodes = 0;
    int depth = 0;
    double meanLeafDepth = 0.0;
    std::size_t minChildren = 0;
    double meanChildren = 0.0;
    std::size_t maxChildren = 0;
    double totalSphereVolume = 0.0;
    double totalBoxVolume = 0.0;
    double meanFill = 0.0;
    double meanSpread = 0.0;
    double maxSpread = 0.0;
};

TreeMetrics computeTreeMetrics(const ClusterTree& tree);

} // namespace hlod
