// Who a cluster is across rebuilds (issue 20 #4): a cluster is its leaf set, the meshes below
// it (HandEdits.h names clusters the same way). Node ids of a ClusterTree are renumbered by
// every rebuild; the key of a leaf set is not, so the editor keeps, by key, a cluster's label
// ("Cluster 12"), its colour, its row's expansion and the selection.
//
// Key: an order-free 64-bit hash of the leaf set (the sum of a mixed value per instance), so a
// parent's key is the sum of its children's and all keys come in one bottom-up pass. Two
// different leaf sets colliding is a 2^-64 event per pair; at worst a label or an expanded row
// is kept for the wrong cluster.
// Labels: the first tree of a scene is labelled by its node ids (what the editor always
// showed); later trees keep the label of every leaf set seen before and give new leaf sets the
// next unused number. Leaves are labelled by their instance id.
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "pipeline/cluster/ClusterTree.h"

namespace hlod::widgets {

using ClusterKey = std::uint64_t;

// Per node of `tree`: the key of its leaf set.
std::vector<ClusterKey> clusterKeys(const ClusterTree& tree);

class ClusterLabels {
public:
    // Forgets every label (a new scene).
    void reset();
    // The label of every node of `tree` whose keys are `keys`.
    std::vector<int> assign(const ClusterTree& tree, const std::vector<ClusterKey>& keys);

private:
    std::unordered_map<ClusterKey, int> labels_;
    int next_ = 0;
};

} // namespace hlod::widgets
