// Incremental construction of a ClusterTree, shared by every clusterer: leaves first (node id =
// instance id), inner nodes appended bottom-up, then `finish` fills the derived fields.
//
// Each node carries a ClusterUnit (CostModel.h) while the tree is built: the clustering volume,
// F*V and cost the merging works with. `finish` copies sphere, fill and cost into the nodes and
// computes what follows from the structure: exact boxes (hull of the children's exact boxes,
// not the padded clustering boxes) and levels (leaves 0, inner 1 + max child level).
// Failure: throws Error(InvalidArgument) when a child already has a parent or an id is out of
// range (a clusterer bug, never user input).
#pragma once

#include <vector>

#include "pipeline/cluster/ClusterTree.h"
#include "pipeline/cluster/CostModel.h"

namespace hlod {

class TreeBuilder {
public:
    explicit TreeBuilder(CostModel model) : model_(model) {}

    // Room for `nodes` nodes, so that adding them never moves the ones built (a tree over n
    // leaves without single-child nodes has at most 2n - 1).
    void reserve(std::size_t nodes) {
        nodes_.reserve(nodes);
        units_.reserve(nodes);
    }

    const CostModel& model() const { return model_; }
    std::size_t size() const { return nodes_.size(); }
    const ClusterUnit& unit(Id node) const { return units_[node]; }
    const ClusterNode& node(Id id) const { return nodes_[id]; }
    void setLocked(Id node, bool locked) { nodes_[node].locked = locked; }

    // A leaf for `instance` with its exact world box and its clustering unit.
    Id addLeaf(Id instance, const Aabb& exactBox, const ClusterUnit& unit);

    // An inner node over `children` (stored in ascending id order) with the given unit.
    Id addNode(std::vector<Id> children, const ClusterUnit& unit);

    // An inner node whose unit folds CostModel::merge over the children in ascending id order
    // (the fill of a multi-child node of the baselines and of the root with excluded leaves).
    Id addFoldedNode(std::vector<Id> children);

    // Moves the nodes into a tree rooted at `root`; the builder is empty afterwards.
    ClusterTree finish(Id root, VolumeType volume, double k);

private:
    CostModel model_;
    std::vector<ClusterNode> nodes_;
    std::vector<ClusterUnit> units_;
};

} // namespace hlod
